// The support effects stated once (effects/support_effects.hpp) and what each
// model level makes of them: the same chuck gives the same spring layer to the
// solid, the harmonic section and the beam, and a rigid translation loads the
// bearings by exactly their stiffness at every level.
#include "effects/support_effects.hpp"

#include "models/part_materials.hpp"  // part_materials
#include "assembly/chuck_supports.hpp"
#include "assembly/harmonic_system.hpp"
#include "beam/beam_model.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <set>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

constexpr double kNormal = 3e10;  // Pa/m

Scene chuck_scene() { return with_chucks(paper_core(0.6, 16, 16), InterfaceKind::spring, kNormal); }

// Solid: u^T K u over the left chuck's spring-layer couplings, the core's
// nodes moved by `u` (one metre along x or z), the chuck's held.
double solid_layer(const Scene& s, int component) {
    const Mesh mesh = generated_mesh(s);
    double k = 0;
    for (const CouplingElement& e : chuck_supports(s, mesh).couplings) {
        const int n = static_cast<int>(e.nodes.size()) / 2;
        if (mesh.nodes[e.nodes[0]][2] > s.core.length / 2) continue;  // the left chuck only
        Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * n);
        for (int a = 0; a < n; ++a) u[3 * a + component] = 1;  // core nodes come first
        k += u.dot(e.matrix(Term::stiffness) * u);
    }
    return k;
}

// Harmonic: the whole K_n (dense), a field on the nodes of `parts` (others
// still): x^T K x. Rigid motions leave the cells unstrained, so only the
// supports between moving and still nodes answer.
double harmonic_energy(const Scene& s, int n, const Eigen::Vector3d& u, const std::set<std::string>& parts) {
    const SectionMesh mesh = make_section_mesh(make_tube_section(s), s.supports.clamps);
    const HarmonicDofs dofs = harmonic_dofs(s, mesh, n);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs.n_dofs, dofs.n_dofs);
    assemble_harmonic_terms(s, mesh, part_materials(s, mesh.part_names, "test"), dofs, n,
                            [&](Term t, const std::vector<int>& d, const Eigen::MatrixXd& A) {
                                if (t != Term::stiffness) return;
                                for (size_t a = 0; a < d.size(); ++a)
                                    for (size_t b = 0; b < d.size(); ++b)
                                        if (d[a] >= 0 && d[b] >= 0) K(d[a], d[b]) += A(a, b);
                            });
    Eigen::VectorXd x = Eigen::VectorXd::Zero(dofs.n_dofs);
    for (int c = 0; c < mesh.n_cells(); ++c) {
        if (!parts.count(mesh.part_names[mesh.cell_part[c]])) continue;
        for (int node : mesh.cells[c])
            for (int k = 0; k < 3; ++k)
                if (const int d = dofs.of_component[3 * node + k]; d >= 0) x[d] = u[k];
    }
    return x.dot(K * x);
}

// Beam: the left chuck's spring layer, per length times its length.
Matrix6 beam_layer(const Scene& s) {
    const BeamNetwork net = build_beam_network(s, {});
    const BeamNetwork::Coupling& c = net.couplings.at(0);
    return c.stiffness_per_length * (c.z_end - c.z_start);
}

}  // namespace

TEST_CASE("The effects list names what the levels apply", "[effects]") {
    CHECK(effect_names(paper_core(0.6), support_effects(paper_core(0.6))) == std::vector<std::string>{"core"});
    const Scene s = on_elastic_bearings(chuck_scene(), 2e8, 3e6);
    CHECK(s.effects() == std::vector<std::string>{"core", "elastic_chucks", "contact_compliance", "bearing_springs"});
    const SupportEffects e = support_effects(s);
    REQUIRE(e.chucks.size() == 2);
    CHECK(e.chucks[0].spring_layer->normal == kNormal);
    CHECK(e.chucks[1].placement.bearing_z() == Approx(s.core.length + 0.15));
    CHECK(!e.chucks[0].frame);
}

TEST_CASE("Where a chuck acts: one rule for ranges, arcs and covered points", "[effects][chuck]") {
    Scene s = chuck_scene();
    s.supports.chucks[1].expanding[0] = {0.08, 0.06, 3, M_PI / 3};
    const ChuckPlacement left = chuck_placement(s, s.supports.chucks[0]);
    const ChuckPlacement right = chuck_placement(s, s.supports.chucks[1]);
    CHECK(left.element_range(left.expanding[0]).lo == Approx(0.05));
    CHECK(right.element_range(right.expanding[0]).hi == Approx(s.core.length - 0.05));
    CHECK(right.body_range().lo == Approx(s.core.length - 0.11));
    CHECK(left.covers(0.08, 2.0));       // a band covers every angle
    CHECK_FALSE(left.covers(0.12, 0.0));  // beyond the band
    CHECK(right.covers(s.core.length - 0.08, 2 * M_PI / 3 + 0.5));
    CHECK_FALSE(right.covers(s.core.length - 0.08, M_PI / 3));  // between segments
    const std::vector<Arc> arcs = contact_arcs(right.expanding[0]);
    REQUIRE(arcs.size() == 3);
    CHECK(arcs[1].from == Approx(2 * M_PI / 3 - M_PI / 6));
    // The pressed area matches the arcs the beam integrates over.
    double angle = 0;
    for (const Arc& a : arcs) angle += a.to - a.from;
    CHECK(contact_area(right.expanding[0], 0.038) == Approx(angle * 0.038 * 0.06));
}

TEST_CASE("The same chuck gives the same spring layer to all three levels", "[long][effects][chuck][harmonic][beam]") {
    const Scene s = chuck_scene();
    const SupportEffects effects = support_effects(s);
    const SpringLayer& layer = *effects.chucks[0].spring_layer;
    const ExpandingElement& band = s.supports.chucks[0].expanding[0];
    const double R = s.core.inner_diameter / 2;
    // The effect itself: k_n along the radius, k_t in the tangent plane.
    const double theta = 0.7;
    const Eigen::Vector3d er(std::cos(theta), std::sin(theta), 0), et(-std::sin(theta), std::cos(theta), 0);
    CHECK(er.dot(layer.per_area(theta) * er) == Approx(kNormal));
    CHECK(et.dot(layer.per_area(theta) * et) == Approx(0.82 * kNormal));
    CHECK(layer.sideways_stiffness(band, R) == Approx(M_PI * R * band.width * (layer.normal + layer.tangential)));
    const double sideways = layer.sideways_stiffness(band, R), axial = layer.axial_stiffness(band, R);

    SECTION("solid: the bore faces follow the circle to 1e-4") {
        CHECK(solid_layer(s, 0) == Approx(sideways).epsilon(1e-4));
        CHECK(solid_layer(s, 2) == Approx(axial).epsilon(1e-4));
    }
    SECTION("harmonic: the roll moved against both chucks (n = 1 sideways, n = 0 along z)") {
        const std::set<std::string> roll = {"core"};
        CHECK(harmonic_energy(s, 1, {1, 1, 0}, roll) == Approx(2 * sideways).epsilon(1e-9));
        CHECK(harmonic_energy(s, 0, {0, 0, 1}, roll) == Approx(2 * axial).epsilon(1e-9));
    }
    SECTION("beam: the layer per length over the band") {
        const Matrix6 k = beam_layer(s);
        CHECK(k(beam_dof::ux, beam_dof::ux) == Approx(sideways).epsilon(1e-12));
        CHECK(k(beam_dof::uy, beam_dof::uy) == Approx(sideways).epsilon(1e-12));
        CHECK(k(beam_dof::uz, beam_dof::uz) == Approx(axial).epsilon(1e-12));
    }
}

TEST_CASE("A rigid translation loads the bearings by exactly their stiffness at every level",
          "[long][effects][chuck][harmonic][beam]") {
    const Scene s = on_elastic_bearings(chuck_scene(), 2e8, 3e6);
    const SupportEffects effects = support_effects(s);  // held: the springs below refer into it
    const BearingSprings& springs = *effects.chucks[0].bearing_springs;
    REQUIRE(springs.radial == 2e8);

    SECTION("solid: the left shaft end face moved by one metre along x") {
        const Mesh mesh = generated_mesh(s);
        double k = 0;
        for (const CouplingElement& e : chuck_supports(s, mesh).couplings) {
            if (mesh.nodes[e.nodes[0]][2] > 0) continue;  // the left bearing only
            Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * static_cast<int>(e.nodes.size()));
            for (size_t a = 0; a < e.nodes.size(); ++a) u[3 * a] = 1;
            k += u.dot(e.matrix(Term::stiffness) * u);
        }
        CHECK(k == Approx(springs.radial).epsilon(1e-10));
    }
    SECTION("harmonic: the whole model moved sideways (n = 1) loads both bearings") {
        const std::set<std::string> all = {"core", "chuck_left", "chuck_right"};
        CHECK(harmonic_energy(s, 1, {1, 1, 0}, all) == Approx(2 * springs.radial).epsilon(1e-9));
    }
    SECTION("beam: the shaft end's radial spring to the ground") {
        const BeamNetwork net = build_beam_network(s, {});
        double k = 0;
        for (const BeamNetwork::Spring& sp : net.springs)
            if (sp.node_b < 0 && net.node_z[sp.node_a] < 0) k += sp.stiffness(beam_dof::ux, beam_dof::ux);
        CHECK(k == springs.radial);
    }
}
