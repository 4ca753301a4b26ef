// The suggested warp scale and the cylindrical components written beside
// each mode shape, against hand-computed values.
#include "output/mode_display.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

// Nodes of a tube of outer radius 0.1 m and length 2 m on the z axis (x and y
// extents 0.2 m, z extent 2 m), with nodes on the axis at both ends too.
Mesh tube_mesh() {
    Mesh mesh;
    for (double z : {0.0, 1.0, 2.0})
        for (int i = 0; i < 8; ++i) {
            const double theta = 2 * M_PI * i / 8;
            mesh.nodes.push_back({0.1 * std::cos(theta), 0.1 * std::sin(theta), z});
        }
    mesh.nodes.push_back({0, 0, 0});
    return mesh;
}

// One displacement per node from f(x, y, z) -> {ux, uy, uz}.
template <class F>
std::vector<double> field(const Mesh& mesh, F f) {
    std::vector<double> shape;
    for (const auto& x : mesh.nodes) {
        const std::array<double, 3> u = f(x[0], x[1], x[2]);
        shape.insert(shape.end(), u.begin(), u.end());
    }
    return shape;
}

}  // namespace

TEST_CASE("the suggested warp shows bending at 10 % of the length and shells at 25 % of the diameter",
          "[output][display]") {
    const Mesh mesh = tube_mesh();
    // Largest |u| = 0.5 (at mid-length): 0.1 x 2 m / 0.5 = 0.4.
    const auto bending = field(mesh, [](double, double, double z) {
        return std::array<double, 3>{0.5 * std::sin(M_PI * z / 2), 0, 0};
    });
    CHECK(suggested_warp_scale(mesh, bending, "bending") == Approx(0.4));
    CHECK(suggested_warp_scale(mesh, bending, "axial") == Approx(0.4));
    // Any other type is capped: 0.25 x 0.2 m / 0.5 = 0.1 < 0.4.
    for (const char* type : {"ovalling", "breathing", "torsion", "rigid", "mixed"}) {
        INFO(type);
        CHECK(suggested_warp_scale(mesh, bending, type) == Approx(0.1));
    }
    // The largest |u| counts all three components: |(0.3, 0, 0.4)| = 0.5.
    const auto oblique = field(mesh, [](double, double, double) { return std::array<double, 3>{0.3, 0, 0.4}; });
    CHECK(suggested_warp_scale(mesh, oblique, "bending") == Approx(0.4));
}

TEST_CASE("the suggested warp of a zero shape or a flat model", "[output][display]") {
    const Mesh mesh = tube_mesh();
    CHECK(suggested_warp_scale(mesh, std::vector<double>(3 * mesh.nodes.size(), 0.0), "bending") == 0);
    // A flat ring (no extent in z): its smallest extent is the diameter, not 0.
    Mesh ring;
    for (int i = 0; i < 8; ++i) ring.nodes.push_back({0.1 * std::cos(i * M_PI / 4), 0.1 * std::sin(i * M_PI / 4), 0});
    const auto out = field(ring, [](double x, double y, double) { return std::array<double, 3>{x, y, 0}; });
    // |u| = 0.1; 0.25 x 0.2 m / 0.1 = 0.5 (the length term 0.1 x 0.2 / 0.1 = 0.2 is smaller).
    CHECK(suggested_warp_scale(ring, out, "breathing") == Approx(0.2));
    CHECK(suggested_warp_scale(ring, out, "bending") == Approx(0.2));
}

TEST_CASE("cylindrical components of a rotation, an expansion and an axial shift", "[output][display]") {
    const Mesh mesh = tube_mesh();
    const double omega = 0.01, strain = 0.02, shift = 0.003;
    // u = omega e_z x r + strain r_xy + shift e_z: u_r = strain r, u_theta = omega r, u_z = shift.
    const auto shape = field(mesh, [&](double x, double y, double) {
        return std::array<double, 3>{-omega * y + strain * x, omega * x + strain * y, shift};
    });
    const CylindricalShape c = cylindrical_components(mesh, shape);
    REQUIRE(c.u_r.size() == mesh.nodes.size());
    for (size_t a = 0; a + 1 < mesh.nodes.size(); ++a) {
        CHECK(c.u_r[a] == Approx(strain * 0.1));
        CHECK(c.u_theta[a] == Approx(omega * 0.1));
        CHECK(c.u_z[a] == Approx(shift));
    }
    // On the axis theta = 0 by convention: u_r = u_x, u_theta = u_y (both 0 here).
    const size_t axis = mesh.nodes.size() - 1;
    CHECK(c.u_r[axis] == 0);
    CHECK(c.u_theta[axis] == 0);
    const auto sideways = field(mesh, [](double, double, double) { return std::array<double, 3>{0.2, 0.5, 0}; });
    const CylindricalShape s = cylindrical_components(mesh, sideways);
    CHECK(s.u_r[axis] == 0.2);
    CHECK(s.u_theta[axis] == 0.5);
}
