#include "beam/beam_model.hpp"

#include "beam/rotating_modes.hpp"  // label_beam_mode

#include "beam/eigenvalue_scale.hpp"
#include "beam/network_modes.hpp"
#include "common/error.hpp"
#include "common/stopwatch.hpp"
#include "effects/support_effects.hpp"
#include "effects/web.hpp"
#include "eigensolve/tolerances.hpp"
#include "modes/classify.hpp"
#include "scene/rotation_spec.hpp"  // roll_outer_diameter

#include <algorithm>
#include <array>
#include <cmath>

namespace coremodal {
namespace {

// Edges closer than this share of the core length are one station.
constexpr double kStationTolerance = 1e-9;
// A shaft gets at least this many elements (it carries the chuck's tilt to the bearing).
constexpr int kMinShaftElements = 2;
// Every gap between support edges (clamp zone, overhang, expanding element)
// gets at least this many elements: a stiff spring layer bends the core over
// a decay length of the order of its width, which one element cannot follow
// (one element left case 05's chucked f1 3e-4 high, two 3e-5).
constexpr int kMinElementsPerGap = 2;
constexpr int kCoreBeam = 0;

// ---- stations along z ------------------------------------------------------

// Every z where the supports need a core node.
std::vector<double> support_edges(const Scene& scene, const SupportEffects& effects) {
    std::vector<double> edges = {0.0, scene.core.length};
    for (const RigidClamp& c : effects.clamps) edges.insert(edges.end(), {c.zone.lo, c.zone.hi});
    for (const ChuckEffects& chuck : effects.chucks) {
        const ZRange body = chuck.placement.body_range();
        edges.insert(edges.end(), {body.lo, body.hi});
        for (const ExpandingElement& e : chuck.placement.expanding) {
            const ZRange r = chuck.placement.element_range(e);
            edges.insert(edges.end(), {r.lo, r.hi});
        }
    }
    std::sort(edges.begin(), edges.end());
    const double tol = kStationTolerance * scene.core.length;
    edges.erase(std::unique(edges.begin(), edges.end(), [tol](double a, double b) { return b - a <= tol; }), edges.end());
    return edges;
}

// The core's element ends: the support edges, and between them uniform
// elements of about Lc / n_elements (at least kMinElementsPerGap per gap),
// each gap's count then multiplied by `refine`.
std::vector<double> core_stations(const Scene& scene, const SupportEffects& effects, int n_elements, int refine) {
    const std::vector<double> edges = support_edges(scene, effects);
    std::vector<double> z;
    for (size_t i = 0; i + 1 < edges.size(); ++i) {
        const double gap = edges[i + 1] - edges[i];
        const int n = refine * std::max(kMinElementsPerGap,
                                        static_cast<int>(std::lround(gap / scene.core.length * n_elements)));
        for (int k = 0; k < n; ++k) z.push_back(edges[i] + gap * k / n);
    }
    z.push_back(edges.back());
    return z;
}

// ---- the network -----------------------------------------------------------

// Every node of the core's chain (element ends and middles), ascending in z.
struct CoreNodes {
    std::vector<double> z;
    std::vector<int> node;
    // The core node at z, or -1.
    int at(double z_wanted, double tol) const {
        const auto it = std::lower_bound(z.begin(), z.end(), z_wanted - tol);
        return it != z.end() && *it <= z_wanted + tol ? node[it - z.begin()] : -1;
    }
};

CoreNodes add_core(BeamNetwork& net, const Scene& scene, const std::vector<double>& stations) {
    CoreNodes core;
    const std::vector<BeamSection> sections(stations.size() - 1, beam_section(scene));
    net.add_beam("core", stations, sections, [&](double z) {
        core.z.push_back(z);
        core.node.push_back(net.add_node(z));
        return core.node.back();
    });
    return core;
}

// Rigid clamps (effects/support_effects.hpp): every core node in a zone held.
void hold_clamp_zones(BeamNetwork& net, const Scene& scene, const std::vector<RigidClamp>& clamps,
                      const CoreNodes& core) {
    const double tol = kStationTolerance * scene.core.length;
    for (const RigidClamp& c : clamps)
        for (size_t i = 0; i < core.z.size(); ++i)
            if (c.zone.holds(core.z[i], tol)) net.hold_all(core.node[i]);
}

// Element ends of a chuck, ascending: the core's stations over the body,
// then the shaft's own out to the bearing (or the reverse on the right).
std::vector<double> chuck_stations(const Scene& scene, const ChuckPlacement& chuck,
                                   const std::vector<double>& core_stations, int n_elements, int refine) {
    const double tol = kStationTolerance * scene.core.length;
    const ZRange body = chuck.body_range();
    const double h = scene.core.length / n_elements;
    const int n_shaft = refine * std::max(kMinShaftElements, static_cast<int>(std::ceil(chuck.shaft_length / h)));
    std::vector<double> z;
    for (double zc : core_stations)
        if (body.holds(zc, tol)) z.push_back(zc);
    for (int k = 1; k <= n_shaft; ++k) {
        const double out = chuck.shaft_length * k / n_shaft;  // beyond the core end
        z.push_back(chuck.right ? scene.core.length + out : -out);
    }
    std::sort(z.begin(), z.end());
    return z;
}

// Bonded expanding elements tie the body to the core: over their width the
// chuck's chain runs through the core's own nodes.
int chuck_node(BeamNetwork& net, const Scene& scene, const ChuckEffects& chuck, const CoreNodes& core, double z) {
    const double tol = kStationTolerance * scene.core.length;
    if (chuck.bonded)
        for (const ExpandingElement& e : chuck.placement.expanding)
            if (chuck.placement.element_range(e).holds(z, tol)) {
                const int shared = core.at(z, tol);
                COREMODAL_ASSERT(shared >= 0);  // expanding-element edges are core stations
                return shared;
            }
    return net.add_node(z);
}

// The stand (effects/support_effects.hpp): a rigid bearing holds the shaft
// end; bearing springs join it to the ground, the radial one through the
// frame mass when there is one.
void add_bearing(BeamNetwork& net, const ChuckEffects& chuck, int shaft_end, std::vector<std::string>& notes) {
    if (!chuck.bearing_springs) {
        net.hold_all(shaft_end);
        return;
    }
    const BearingSprings& b = *chuck.bearing_springs;
    // The scene gives radial and tilting stiffness only: axially the bearing
    // locates the shaft and in torsion the unwind brake holds it.
    net.hold(shaft_end, beam_dof::uz);
    net.hold(shaft_end, beam_dof::rz);
    notes.push_back("chuck " + chuck.placement.chuck + ": the elastic bearing holds the shaft end axially and in "
                    "torsion (beam model; the scene gives radial and tilting stiffness only)");
    Matrix6 radial = Matrix6::Zero(), tilting = Matrix6::Zero();
    radial(beam_dof::ux, beam_dof::ux) = radial(beam_dof::uy, beam_dof::uy) = b.radial;
    tilting(beam_dof::rx, beam_dof::rx) = tilting(beam_dof::ry, beam_dof::ry) = b.tilting;
    net.springs.push_back({shaft_end, -1, tilting});
    if (!chuck.frame) {
        net.springs.push_back({shaft_end, -1, radial});
        return;
    }
    // The frame: a mass that translates sideways, on its own spring to ground;
    // the bearing's radial spring joins it to the shaft end.
    const int frame = net.add_node(net.node_z[shaft_end]);
    for (int d : {beam_dof::uz, beam_dof::rx, beam_dof::ry, beam_dof::rz}) net.hold(frame, d);
    Matrix6 frame_spring = Matrix6::Zero();
    frame_spring(beam_dof::ux, beam_dof::ux) = frame_spring(beam_dof::uy, beam_dof::uy) = chuck.frame->stiffness;
    net.springs.push_back({shaft_end, frame, radial});
    net.springs.push_back({frame, -1, frame_spring});
    net.masses.push_back({frame, chuck.frame->mass});
}

void add_chuck(BeamNetwork& net, const Scene& scene, const ChuckSpec& spec, const ChuckEffects& chuck,
               const std::vector<double>& core_stations, const CoreNodes& core, int n_elements, int refine,
               std::vector<std::string>& notes) {
    const double tol = kStationTolerance * scene.core.length;
    if (chuck.one_sided)  // a beam has no circumference on which a contact could open
        throw InputError(scene.source_file + ": model = \"beam\": the " + spec.name +
                         " chuck is not expanded, with a one-sided contact under gravity, which the 3D solid and "
                         "the coupled harmonics model; expected model = \"auto\", \"coupled\" or \"solid\", or "
                         "contact = \"uniform\" for a "
                         "uniform soft layer");
    const ChuckPlacement& place = chuck.placement;
    const ZRange body = place.body_range();
    const BeamSection body_section = tube_beam_section(spec.body_diameter, 0, spec.material);
    const BeamSection shaft_section = tube_beam_section(spec.shaft_diameter, 0, spec.material);
    const std::vector<double> z = chuck_stations(scene, place, core_stations, n_elements, refine);
    std::vector<BeamSection> sections;
    for (size_t e = 0; e + 1 < z.size(); ++e)
        sections.push_back(body.holds(0.5 * (z[e] + z[e + 1]), tol) ? body_section : shaft_section);
    const int index = net.add_beam("chuck_" + place.chuck, z, sections,
                                   [&](double zi) { return chuck_node(net, scene, chuck, core, zi); });
    const BeamNetwork::Beam& beam = net.beams[index];
    const int shaft_end = place.right ? beam.nodes.back() : beam.nodes.front();
    if (chuck.spring_layer) {
        const double bore_radius = scene.core.inner_diameter / 2;
        for (const ExpandingElement& e : place.expanding) {
            const ZRange r = place.element_range(e);
            net.couplings.push_back(
                {kCoreBeam, index, r.lo, r.hi, spring_layer_per_length(*chuck.spring_layer, e, bore_radius)});
        }
    }
    add_bearing(net, chuck, shaft_end, notes);
}

// ---- spring layer ------------------------------------------------------------

// Integrals over theta in [a, b] of 1, cos, sin, cos^2, sin^2, sin cos.
struct ArcMoments {
    double one = 0, c = 0, s = 0, cc = 0, ss = 0, sc = 0;
    void add(double a, double b) {
        one += b - a;
        c += std::sin(b) - std::sin(a);
        s += std::cos(a) - std::cos(b);
        cc += (b - a) / 2 + (std::sin(2 * b) - std::sin(2 * a)) / 4;
        ss += (b - a) / 2 - (std::sin(2 * b) - std::sin(2 * a)) / 4;
        sc += (std::sin(b) * std::sin(b) - std::sin(a) * std::sin(a)) / 2;
    }
};

ArcMoments arc_moments(const ExpandingElement& e) {
    ArcMoments m;
    for (const Arc& arc : contact_arcs(e)) m.add(arc.from, arc.to);
    return m;
}

// ---- labels ------------------------------------------------------------------

// Kinetic energy of a mode per motion family (sums to 1 for an M-normalised mode).
std::array<double, kMotionFamilies> family_energy(const Eigen::VectorXd& shape, const Eigen::VectorXd& mass_shape) {
    std::array<double, kMotionFamilies> e{};
    for (Eigen::Index d = 0; d < shape.size(); ++d)
        e[static_cast<int>(motion_family(static_cast<int>(d)))] += shape(d) * mass_shape(d);
    return e;
}

// Sign changes along the core of its motion in the mode's family.
int axial_sign_changes(const BeamNetwork& net, const Eigen::VectorXd& shape, MotionFamily family) {
    const std::vector<int>& nodes = net.beams[kCoreBeam].nodes;
    const auto at = [&](int node, int dof) { return shape(beam_dof::per_node * node + dof); };
    std::vector<double> profile;
    if (family == MotionFamily::axial || family == MotionFamily::torsion) {
        const int d = family == MotionFamily::axial ? beam_dof::uz : beam_dof::rz;
        for (int n : nodes) profile.push_back(at(n, d));
    } else {  // lateral motion projected on its principal direction (a pair may come rotated)
        double sxx = 0, syy = 0, sxy = 0;
        for (int n : nodes) {
            const double x = at(n, beam_dof::ux), y = at(n, beam_dof::uy);
            sxx += x * x, syy += y * y, sxy += x * y;
        }
        const double phi = 0.5 * std::atan2(2 * sxy, sxx - syy);
        for (int n : nodes) profile.push_back(at(n, beam_dof::ux) * std::cos(phi) + at(n, beam_dof::uy) * std::sin(phi));
    }
    return sign_changes(profile);
}

ModeLabel label_mode(const BeamNetwork& net, const Eigen::VectorXd& shape, const Eigen::VectorXd& mass_shape,
                     double lambda, double lambda_scale) {
    if (std::abs(lambda) < kRigidEigenvalueFraction * lambda_scale) return {"rigid", 0, 0, 1.0};
    const auto e = family_energy(shape, mass_shape);
    const double bending = e[0] + e[1], axial = e[2], torsion = e[3], total = bending + axial + torsion;
    ModeLabel label{"bending", 1, 0, bending / total};
    MotionFamily family = MotionFamily::bending_xz;
    if (axial > bending && axial >= torsion) {
        label = {"axial", 0, 0, axial / total};
        family = MotionFamily::axial;
    } else if (torsion > bending && torsion > axial) {
        label = {"torsion", 0, 0, torsion / total};
        family = MotionFamily::torsion;
    }
    if (label.dominant_share < kMinDominantShare) label.type = "mixed";
    label.m = axial_sign_changes(net, shape, family);
    return label;
}

// Effective masses (x^T M r)^2 of an M-normalised mode x, r a unit rigid
// motion: the sum of M x over the DOFs r moves.
EffectiveMass effective_mass(const Eigen::VectorXd& mass_shape) {
    const auto along = [&](int dof) {
        double sum = 0;
        for (Eigen::Index d = dof; d < mass_shape.size(); d += beam_dof::per_node) sum += mass_shape(d);
        return sum * sum;
    };
    return {along(beam_dof::ux), along(beam_dof::uy), along(beam_dof::uz), along(beam_dof::rz)};
}

NetworkSolveRequest solve_request(const Scene& scene, const BeamModelOptions& options) {
    // The beam network has no section modes: only its own families set the scale.
    NetworkSolveRequest r{mode_request(scene, ModeFamilies::beam)};
    r.force_dense = options.force_dense;
    return r;
}

long fully_held_nodes(const BeamNetwork& net) {
    long n = 0;
    for (int node = 0; node < net.n_nodes(); ++node) {
        bool all = true;
        for (int d = 0; d < beam_dof::per_node; ++d) all = all && net.held[beam_dof::per_node * node + d];
        n += all;
    }
    return n;
}

}  // namespace

Matrix6 spring_layer_per_length(const SpringLayer& layer, const ExpandingElement& element, double R) {
    const double k_n = layer.normal, k_t = layer.tangential;
    // A bore point at angle theta, (R cos, R sin), moves relative to the body by
    // d = du + dr x (R cos, R sin, 0): normal  c dux + s duy,
    // circumferential  -s dux + c duy + R drz,  axial  duz + R (s drx - c dry).
    // Energy per length: 1/2 int (k_n d_n^2 + k_t d_t^2 + k_t d_z^2) R dtheta.
    const ArcMoments m = arc_moments(element);
    using namespace beam_dof;
    Matrix6 k = Matrix6::Zero();
    k(ux, ux) = R * (k_n * m.cc + k_t * m.ss);
    k(uy, uy) = R * (k_n * m.ss + k_t * m.cc);
    k(ux, uy) = R * (k_n - k_t) * m.sc;
    k(ux, rz) = -R * R * k_t * m.s;
    k(uy, rz) = R * R * k_t * m.c;
    k(rz, rz) = R * R * R * k_t * m.one;
    k(uz, uz) = R * k_t * m.one;
    k(uz, rx) = R * R * k_t * m.s;
    k(uz, ry) = -R * R * k_t * m.c;
    k(rx, rx) = R * R * R * k_t * m.ss;
    k(rx, ry) = -R * R * R * k_t * m.sc;
    k(ry, ry) = R * R * R * k_t * m.cc;
    return Matrix6(k.selfadjointView<Eigen::Upper>());
}

ModeLabel label_beam_mode(const BeamNetwork& network, const Eigen::VectorXd& shape, const Eigen::VectorXd& mass_shape,
                          double eigenvalue, double lambda_scale) {
    return label_mode(network, shape, mass_shape, eigenvalue, lambda_scale);
}

// The web's span on the roll's surface line over the core's length (the
// rest roll's width), at the roll's outer radius (effects/web.hpp).
void add_web(BeamNetwork& net, const Scene& scene) {
    const double radius = roll_outer_diameter(scene) / 2;
    net.couplings.push_back(
        {kCoreBeam, -1, 0.0, scene.core.length, web_beam_stiffness_per_length(*scene.web, radius)});
}

BeamNetwork build_beam_network(const Scene& scene, const BeamModelOptions& options,
                               std::vector<std::string>* assumptions) {
    COREMODAL_ASSERT(options.core_elements >= 1 && options.refine >= 1);
    std::vector<std::string> notes;
    BeamNetwork net;
    const SupportEffects effects = support_effects(scene);
    const std::vector<double> stations = core_stations(scene, effects, options.core_elements, options.refine);
    const CoreNodes core = add_core(net, scene, stations);
    if (scene.supports.kind == SupportKind::clamped) hold_clamp_zones(net, scene, effects.clamps, core);
    if (scene.supports.kind == SupportKind::chucks)
        for (size_t k = 0; k < effects.chucks.size(); ++k)
            add_chuck(net, scene, scene.supports.chucks[k], effects.chucks[k], stations, core, options.core_elements,
                      options.refine, notes);
    if (scene.web) add_web(net, scene);
    if (assumptions) assumptions->insert(assumptions->end(), notes.begin(), notes.end());
    return net;
}

BeamModelResult solve_beam_model(const Scene& scene, const BeamModelOptions& options) {
    Stopwatch stage;
    BeamModelResult out;
    out.network = build_beam_network(scene, options, &out.assumptions);
    out.n_held_nodes = fully_held_nodes(out.network);
    out.timing_s.build = stage.lap();

    const NetworkSolveRequest request = solve_request(scene, options);
    out.lambda_scale = request.lambda_scale;
    NetworkModes solved = solve_network_modes(out.network, request);
    out.n_dofs = solved.n_free_dofs;
    out.verification = solved.verification;
    out.n_problems = solved.n_problems;
    out.mirrored_planes = solved.mirrored_planes;
    out.dense_retry = solved.dense_retry;
    out.timing_s.solve = stage.lap();

    for (size_t i = 0; i < solved.eigenvalues.size(); ++i) {
        BeamMode mode;
        mode.eigenvalue = solved.eigenvalues[i];
        mode.frequency_hz = eigenvalue_hz(mode.eigenvalue);
        mode.relative_residual = solved.relative_residuals[i];
        mode.effective_mass = effective_mass(solved.mass_shapes[i]);
        mode.label = label_mode(out.network, solved.shapes[i], solved.mass_shapes[i], mode.eigenvalue, request.lambda_scale);
        mode.shape = std::move(solved.shapes[i]);
        out.modes.push_back(std::move(mode));
    }
    out.timing_s.classify = stage.lap();
    return out;
}

}  // namespace coremodal
