// The spring layer and the bearing springs against their closed forms.
#include "assembly/chuck_supports.hpp"

#include "geometry/tube_model.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <set>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

// Force along x on the core side when the core moves by one metre in x
// against a fixed chuck, summed over the spring-layer elements.
double translation_stiffness(const ChuckSupports& supports) {
    double k = 0;
    for (const CouplingElement& e : supports.couplings) {
        const int n = static_cast<int>(e.nodes.size()) / 2;
        Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * n);
        for (int a = 0; a < n; ++a) u[3 * a] = 1;  // core nodes come first
        k += u.dot(e.matrix(Term::stiffness) * u);
    }
    return k;
}

}  // namespace

TEST_CASE("A band's spring layer resists translation with pi R w (k_n + k_t)", "[assembly][chucks]") {
    const Scene s = with_chucks(paper_core(0.6, 16, 16), InterfaceKind::spring, 3e10);
    const ChuckSupports supports = chuck_supports(s, generated_mesh(s));
    const double R = 0.038, w = 0.06, kn = 3e10, kt = 0.82 * 3e10;
    // Quadratic faces on 16 elements around follow the circle to ~1e-5.
    CHECK(supports.coupled_area_m2 == Approx(2 * 2 * M_PI * R * w).epsilon(1e-4));
    CHECK(translation_stiffness(supports) == Approx(2 * M_PI * R * w * (kn + kt)).epsilon(1e-4));
    CHECK(supports.ties.empty());
}

TEST_CASE("Segments whose edges cut through faces cover exactly their area", "[assembly][chucks]") {
    Scene s = with_chucks(paper_core(0.6, 16, 16), InterfaceKind::spring, 3e10);
    // 3 segments of 50 degrees: edges at +-25 deg, never on the 22.5-degree grid.
    for (auto& c : s.supports.chucks) c.expanding[0] = {0.08, 0.06, 3, 50 * M_PI / 180};
    const ChuckSupports supports = chuck_supports(s, generated_mesh(s));
    const double R = 0.038, w = 0.06, kn = 3e10, kt = 0.82 * 3e10, covered = 3 * 50 * M_PI / 180;
    CHECK(supports.coupled_area_m2 == Approx(2 * R * w * covered).epsilon(1e-4));
    // Three segments 120 degrees apart: cos^2 and sin^2 average to 1/2 each.
    CHECK(translation_stiffness(supports) == Approx(2 * R * w * covered * (kn + kt) / 2).epsilon(1e-4));
}

TEST_CASE("A bonded band ties every bore node over it to a chuck node", "[assembly][chucks]") {
    const Scene s = with_chucks(paper_core(0.6, 16, 16), InterfaceKind::bonded);
    const Mesh mesh = generated_mesh(s);
    const ChuckSupports supports = chuck_supports(s, mesh);
    std::set<int> core_nodes(mesh.node_groups.at("interface_left_core").begin(),
                             mesh.node_groups.at("interface_left_core").end());
    int left = 0;
    for (const NodeTie& t : supports.ties) {
        const auto &a = mesh.nodes[t.node], &b = mesh.nodes[t.master];
        CHECK(std::atan2(a[1], a[0]) == Approx(std::atan2(b[1], b[0])).margin(1e-9));
        CHECK(a[2] == Approx(b[2]).margin(1e-12));
        left += core_nodes.count(t.node);
    }
    CHECK(left == static_cast<int>(core_nodes.size()));
    // Rigid bearings: the shaft end faces are eliminated.
    CHECK(supports.eliminated.size() ==
          mesh.node_groups.at("bearing_left").size() + mesh.node_groups.at("bearing_right").size());
}

TEST_CASE("Elastic bearing springs give the face k_radial in translation and k_tilt in tilt", "[assembly][chucks]") {
    const Scene s = on_elastic_bearings(with_chucks(paper_core(0.6, 16, 16), InterfaceKind::bonded), 2e8, 3e6);
    const Mesh mesh = generated_mesh(s);
    const ChuckSupports supports = chuck_supports(s, mesh);
    double k_translation = 0, k_tilt = 0;
    for (const CouplingElement& e : supports.couplings) {
        if (mesh.nodes[e.nodes[0]][2] > 0) continue;  // the left bearing only
        const int n = static_cast<int>(e.nodes.size());
        Eigen::VectorXd shift = Eigen::VectorXd::Zero(3 * n), tilt = Eigen::VectorXd::Zero(3 * n);
        for (int a = 0; a < n; ++a) {
            shift[3 * a] = 1;
            tilt[3 * a + 2] = mesh.nodes[e.nodes[a]][0];  // rotation about y: u_z = x
        }
        k_translation += shift.dot(e.matrix(Term::stiffness) * shift);
        k_tilt += tilt.dot(e.matrix(Term::stiffness) * tilt);
    }
    CHECK(k_translation == Approx(2e8).epsilon(1e-10));
    CHECK(k_tilt == Approx(3e6).epsilon(1e-10));
    CHECK(supports.eliminated.empty());
}
