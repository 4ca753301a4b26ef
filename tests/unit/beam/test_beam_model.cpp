// The beam model of a scene (src/beam/beam_model.hpp): clamped and free rest
// rolls against beam theory, convergence with the element count, and what
// chucks, interfaces and bearings do to the first bending mode.
#include "beam/beam_model.hpp"

#include "scene/case_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace coremodal;

namespace {

// Case 03's rest roll (4.32 m, 150.5 x 15.8 core, 10 mm rest paper).
const std::string kRestRoll = R"(
model = "beam"
[core]
inner_diameter = "150.5 mm"
wall = "15.8 mm"
length = "4.32 m"
material = "paperboard_core"
[rest_paper]
thickness = "10 mm"
material = "rest_paper"
)";

// Clamp zones 100 mm long centred at Li = 250 mm, as in case 03.
const std::string kClamps = R"(
[supports]
type = "clamped"
[supports.left]
length = "100 mm"
center = "250 mm"
)";

// Rotogravure chucks: 300 mm inside the core, one 100 mm expanding element at
// Li = 250 mm, a 100 mm shaft 200 mm to the bearing.
std::string chucks(const std::string& interface = "", const std::string& bearing = "") {
    return R"(
[supports]
type = "chucks"
[supports.left]
inserted_length = "300 mm"
shaft_diameter = "100 mm"
shaft_length = "200 mm"
)" + interface + R"(
[[supports.left.expanding]]
center = "250 mm"
width = "100 mm"
)" + bearing;
}

Scene scene_of(const std::string& text, int n_modes = 20) {
    Scene s = parse_case_text(text + "[analysis]\nmodes = " + std::to_string(n_modes) + "\n", "test.toml");
    return s;
}

const BeamMode& nth_of_type(const BeamModelResult& r, const std::string& type, int k = 1) {
    int seen = 0;
    for (const BeamMode& m : r.modes)
        if (m.label.type == type && ++seen == k) return m;
    FAIL("no mode " << k << " of type " << type);
    return r.modes.front();
}

double first_bending_hz(const Scene& s, const BeamModelOptions& options = {}) {
    return nth_of_type(solve_beam_model(s, options), "bending").frequency_hz;
}

}  // namespace

TEST_CASE("A clamped rest roll as a beam: Timoshenko over the span, bars in torsion and stretching",
          "[beam][model]") {
    const Scene scene = scene_of(kRestRoll + kClamps);
    const BeamModelResult r = solve_beam_model(scene);
    REQUIRE(r.verification.complete);
    CHECK_FALSE(r.dense_retry);
    CHECK(r.mirrored_planes);
    // The clamp zones hold every DOF of their nodes: the span between their
    // inner edges is a clamped-clamped Timoshenko beam (the overhangs beyond
    // them vibrate on their own, far higher).
    const BeamSection s = beam_section(scene);
    const double L = beam_span(scene);  // 3.72 m
    CHECK(L == Approx(3.72));
    const auto timoshenko = timoshenko_bending_hz(s, L, BeamEnds::clamped_clamped, 3);
    CHECK(r.modes[0].label.type == "bending");
    CHECK(r.modes[0].label.m == 0);
    CHECK(r.modes[0].frequency_hz == Approx(timoshenko[0]).epsilon(1e-5));  // 35.43 Hz
    CHECK(r.modes[1].frequency_hz == Approx(r.modes[0].frequency_hz).epsilon(1e-12));
    CHECK(nth_of_type(r, "bending", 3).frequency_hz == Approx(timoshenko[1]).epsilon(1e-4));  // 30 elements vs 80
    CHECK(nth_of_type(r, "bending", 3).label.m == 1);
    CHECK(nth_of_type(r, "torsion").frequency_hz == Approx(std::sqrt(s.GJ / s.rho_J) / (2 * L)).epsilon(1e-5));
    CHECK(nth_of_type(r, "axial").frequency_hz == Approx(std::sqrt(s.EA / s.rho_A) / (2 * L)).epsilon(1e-5));
    // 12 asked, 13 given: the last pair is never cut.
    CHECK(solve_beam_model(scene_of(kRestRoll + kClamps, 12)).modes.size() == 13);
}

TEST_CASE("A free rest roll as a beam: six rigid modes that carry its mass, then Timoshenko free-free",
          "[beam][model]") {
    const Scene scene = scene_of(kRestRoll);
    const BeamModelResult r = solve_beam_model(scene);
    REQUIRE(r.verification.complete);
    const BeamSection s = beam_section(scene);
    const double Lc = scene.core.length, mass = s.rho_A * Lc;
    CHECK(r.network.mass() == Approx(mass).epsilon(1e-12));
    EffectiveMass sum;
    for (int i = 0; i < 6; ++i) {
        CHECK(r.modes[i].label.type == "rigid");
        sum.x += r.modes[i].effective_mass.x, sum.y += r.modes[i].effective_mass.y;
        sum.z += r.modes[i].effective_mass.z, sum.rz += r.modes[i].effective_mass.rz;
    }
    CHECK(sum.x == Approx(mass).epsilon(1e-9));
    CHECK(sum.y == Approx(mass).epsilon(1e-9));
    CHECK(sum.z == Approx(mass).epsilon(1e-9));
    CHECK(sum.rz == Approx(s.rho_J * Lc).epsilon(1e-9));  // the polar inertia
    const BeamMode& bending = r.modes[6];
    CHECK(bending.label.type == "bending");
    CHECK(bending.label.m == 2);  // free-free first bending: two nodes
    CHECK(bending.frequency_hz ==
          Approx(timoshenko_bending_hz(s, Lc, BeamEnds::free_free, 1)[0]).epsilon(1e-5));  // 27.12 Hz
    CHECK(bending.effective_mass.x + bending.effective_mass.y < 1e-9 * mass);  // symmetric: no net sideways push
}

TEST_CASE("The default element count is converged to 0.1 % for the first 20 modes, at the rate h^4",
          "[beam][model][convergence]") {
    for (const std::string& supports : {kClamps, chucks()}) {
        const Scene scene = scene_of(kRestRoll + supports, 20);
        BeamModelOptions fine, coarse;
        fine.core_elements = 300;
        coarse.core_elements = 15;
        const BeamModelResult reference = solve_beam_model(scene, fine), r = solve_beam_model(scene),
                              half = solve_beam_model(scene, coarse);
        REQUIRE(r.modes.size() == reference.modes.size());
        double worst = 0, worst_half = 0;
        for (size_t i = 0; i < r.modes.size(); ++i) {
            worst = std::max(worst, std::abs(r.modes[i].frequency_hz / reference.modes[i].frequency_hz - 1));
            worst_half = std::max(worst_half, std::abs(half.modes[i].frequency_hz / reference.modes[i].frequency_hz - 1));
            CHECK(r.modes[i].label.type == reference.modes[i].label.type);
        }
        INFO((scene.supports.kind == SupportKind::chucks ? "chucks" : "clamped")
             << ": worst error of the first 20 modes " << worst << " at 30 elements, " << worst_half << " at 15");
        CHECK(worst < 1e-3);
        // Halving the element length divides the error by about 2^4.
        CHECK(worst_half / worst > 8);
    }
}

TEST_CASE("Chucks: a stiffer hold raises the first bending frequency towards the rigid clamp", "[beam][model][chucks]") {
    const double soft = first_bending_hz(scene_of(kRestRoll + chucks("expanded = false\ncontact = \"uniform\"\n")));
    const double pressured = first_bending_hz(scene_of(kRestRoll + chucks("expansion_pressure = \"0.6 MPa\"\n")));
    const double bonded = first_bending_hz(scene_of(kRestRoll + chucks("interface = \"bonded\"\n")));
    INFO("not expanded " << soft << " Hz, expanded at 6 bar " << pressured << " Hz, bonded " << bonded << " Hz");
    CHECK(soft < pressured);
    CHECK(pressured < bonded);
    SECTION("Elastic bearings lower it, and a frame mass adds modes of its own") {
        const std::string elastic = "[supports.left.bearing]\ntype = \"elastic\"\nradial_stiffness = \"200 kN/mm\"\n"
                                    "tilting_stiffness = \"1 MN*m/rad\"\n";
        const BeamModelResult r = solve_beam_model(scene_of(kRestRoll + chucks("", elastic)));
        CHECK(nth_of_type(r, "bending").frequency_hz < pressured);
        CHECK(std::any_of(r.assumptions.begin(), r.assumptions.end(), [](const std::string& a) {
            return a.find("holds the shaft end axially and in torsion") != std::string::npos;
        }));
        const BeamModelResult framed =
            solve_beam_model(scene_of(kRestRoll + chucks("", elastic + "frame_mass = \"80 kg\"\nframe_stiffness = \"50 kN/mm\"\n")));
        CHECK(framed.n_dofs == r.n_dofs + 4);  // two frames, each moving sideways in x and y
        CHECK(nth_of_type(framed, "bending").frequency_hz != Approx(nth_of_type(r, "bending").frequency_hz));
    }
    SECTION("A stiffer and stiffer bonded chuck on rigid bearings tends to the rigid clamp of its element") {
        // docs/validation/models.md: a stiff elastic chuck tends to the rigid clamp.
        // What is left is the turn of the chuck's shaft and body under the
        // roll's end moment, inversely proportional to their modulus.
        const std::string clamp_at_element = "[supports]\ntype = \"clamped\"\n[supports.left]\nlength = \"100 mm\"\n"
                                             "center = \"250 mm\"\n";
        const double clamped = first_bending_hz(scene_of(kRestRoll + clamp_at_element));
        const auto gap = [&](const std::string& modulus) {
            const std::string stiff = "material = { base = \"steel\", E = \"" + modulus + "\" }\ninterface = \"bonded\"\n";
            return 1 - first_bending_hz(scene_of(kRestRoll + chucks(stiff))) / clamped;
        };
        const double steel = 1 - bonded / clamped, tera = gap("1000 GPa"), ten_tera = gap("10000 GPa");
        INFO("below the clamp: steel " << steel << ", 1 TPa " << tera << ", 10 TPa " << ten_tera);
        CHECK(steel > tera);
        CHECK(tera > ten_tera);
        CHECK(ten_tera > 0);
        CHECK(ten_tera < 0.005);
        CHECK(ten_tera / tera == Approx(0.1).margin(0.03));
    }
}

TEST_CASE("Chucks with pads: two pads split the bending pairs, one couples bending with twist", "[beam][model][chucks]") {
    const std::string two = "[[supports.left.expanding]]\ncenter = \"250 mm\"\nwidth = \"100 mm\"\nsegments = 2\n"
                            "segment_angle = \"60 deg\"\n";
    std::string text = kRestRoll + chucks();
    text.replace(text.find("[[supports.left.expanding]]"), std::string::npos, two);
    const BeamModelResult r = solve_beam_model(scene_of(text));
    CHECK_FALSE(r.mirrored_planes);
    CHECK(r.verification.complete);
    // Pads at 0 and 180 deg hold x harder than y: the pair splits.
    CHECK(r.modes[0].label.type == "bending");
    CHECK(r.modes[1].label.type == "bending");
    CHECK(r.modes[1].frequency_hz > r.modes[0].frequency_hz * (1 + 1e-6));
    CHECK(r.modes[0].effective_mass.x < 1e-9 * r.network.mass());  // the soft one moves in y
    std::string one = text;
    one.replace(one.find("segments = 2"), 12, "segments = 1");
    const BeamModelResult coupled = solve_beam_model(scene_of(one));
    CHECK(coupled.n_problems == 2);
    CHECK(coupled.verification.complete);
    CHECK(coupled.modes[0].label.type == "bending");
}

TEST_CASE("The core's element ends include every support edge, with at least two elements per gap",
          "[beam][model]") {
    const Scene scene = scene_of(kRestRoll + kClamps);
    BeamModelOptions options;
    options.core_elements = 4;
    const BeamNetwork net = build_beam_network(scene, options);
    std::vector<double> ends;
    for (size_t i = 0; i < net.beams[0].nodes.size(); i += 2) ends.push_back(net.node_z[net.beams[0].nodes[i]]);
    for (double edge : {0.0, 0.2, 0.3, 4.02, 4.12, 4.32})
        CHECK(std::any_of(ends.begin(), ends.end(), [&](double z) { return std::abs(z - edge) < 1e-9; }));
    // Gaps 0.2, 0.1, 3.72, 0.1, 0.2 m: 4 elements over 4.32 m would give the
    // long one round(3.44) = 3 and the others none; each gets at least two.
    CHECK(net.beams[0].sections.size() == 11);
}
