// MAC, subspace MAC and the mesh-independent signatures (modes/mac.hpp).
#include "modes/mac.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

using namespace coremodal;

namespace {

// The outer surface of a tube as rings of nodes: n_rings equally spaced from
// z = 0 to length, n_around nodes per ring starting at angle `phase`. Only
// the node group "core_outer" is filled; the sampler needs nothing else.
Mesh ring_mesh(int n_rings, int n_around, double length, double radius, double phase = 0) {
    Mesh mesh;
    std::vector<int> outer;
    for (int i = 0; i < n_rings; ++i)
        for (int j = 0; j < n_around; ++j) {
            const double t = phase + 2 * M_PI * j / n_around, z = length * i / (n_rings - 1);
            outer.push_back(mesh.n_nodes());
            mesh.nodes.push_back({radius * std::cos(t), radius * std::sin(t), z});
        }
    mesh.node_groups["core_outer"] = outer;
    return mesh;
}

using Field = std::function<std::array<double, 3>(double theta, double zeta)>;  // u_r, u_theta, u_z

// A displacement field given in cylindrical components, sampled at the nodes.
std::vector<double> shape_of(const Mesh& mesh, double length, const Field& field) {
    std::vector<double> u;
    for (const auto& x : mesh.nodes) {
        const double t = std::atan2(x[1], x[0]);
        const auto [ur, ut, uz] = field(t, x[2] / length);
        u.push_back(ur * std::cos(t) - ut * std::sin(t));
        u.push_back(ur * std::sin(t) + ut * std::cos(t));
        u.push_back(uz);
    }
    return u;
}

// Bending in x: the section translates by w(z) = sin(pi z/L).
const Field bending_x = [](double t, double z) {
    const double w = std::sin(M_PI * z);
    return std::array<double, 3>{w * std::cos(t), -w * std::sin(t), 0.0};
};
const Field bending_y = [](double t, double z) {
    const double w = std::sin(M_PI * z);
    return std::array<double, 3>{w * std::sin(t), w * std::cos(t), 0.0};
};
const Field ovalling = [](double t, double z) {
    return std::array<double, 3>{std::cos(2 * t), -0.5 * std::sin(2 * t), 0.0};
};
const Field torsion = [](double, double z) { return std::array<double, 3>{0.0, std::cos(M_PI * z), 0.0}; };

}  // namespace

TEST_CASE("MAC is 1 for a mode against itself scaled or negated, 0 against an orthogonal one", "[mac]") {
    const Signature a = {1, 2, 3, 0}, b = {-2, -4, -6, 0}, c = {0, 0, 0, 5};
    CHECK(mac(a, a) == Approx(1));
    CHECK(mac(a, b) == Approx(1));
    CHECK(mac(a, c) == Approx(0).margin(1e-15));
    CHECK(mac(a, {0, 0, 0, 0}) == 0);  // a zero signature matches nothing
    const Signature d = {1, 0, 0, 0}, e = {1, 1, 0, 0};
    CHECK(mac(d, e) == Approx(0.5));
}

TEST_CASE("A degenerate pair is one subspace: any rotation of it matches the pair fully", "[mac]") {
    const Signature x = {1, 0, 0}, y = {0, 1, 0}, z = {0, 0, 1};
    const double a = 0.3;
    const Signature rx = {std::cos(a), std::sin(a), 0}, ry = {-std::sin(a), std::cos(a), 0};
    CHECK(subspace_mac({x, y}, {rx, ry}) == Approx(1));
    CHECK(subspace_mac({x, y}, {z}) == Approx(0).margin(1e-15));
    // A single member against its pair: a change of multiplicity is a poor match.
    CHECK(subspace_mac({rx}, {x, y}) == Approx(0.5));
    // One vector each: the plain MAC.
    CHECK(subspace_mac({rx}, {x}) == Approx(mac(rx, x)));
}

TEST_CASE("Signatures of one field on two different meshes match; different families do not", "[mac]") {
    const double length = 2.0, radius = 0.05;
    const Mesh coarse = ring_mesh(9, 16, length, radius);
    const Mesh fine = ring_mesh(41, 48, length, radius, 0.1);  // other rings, other angles
    const ModeSignatureSampler on_coarse(coarse), on_fine(fine);
    const auto sig = [&](const ModeSignatureSampler& s, const Mesh& m, const Field& f) {
        const Signature out = s(shape_of(m, length, f));
        REQUIRE(out.size() == static_cast<size_t>(kSignatureSize));
        return out;
    };
    SECTION("The same field: MAC near 1 across meshes") {
        CHECK(mac(sig(on_coarse, coarse, bending_x), sig(on_fine, fine, bending_x)) > 0.99);
        CHECK(mac(sig(on_coarse, coarse, ovalling), sig(on_fine, fine, ovalling)) > 0.99);
        CHECK(mac(sig(on_coarse, coarse, torsion), sig(on_fine, fine, torsion)) > 0.99);
    }
    SECTION("Bending, ovalling and torsion are told apart") {
        CHECK(mac(sig(on_coarse, coarse, bending_x), sig(on_fine, fine, ovalling)) < 0.01);
        CHECK(mac(sig(on_coarse, coarse, bending_x), sig(on_fine, fine, torsion)) < 0.01);
        CHECK(mac(sig(on_coarse, coarse, ovalling), sig(on_fine, fine, torsion)) < 0.01);
    }
    SECTION("The two bending directions are orthogonal, and a pair in any orientation spans both") {
        CHECK(mac(sig(on_coarse, coarse, bending_x), sig(on_fine, fine, bending_y)) < 0.01);
        const Field rotated = [](double t, double z) { return bending_x(t - 0.7, z); };
        CHECK(subspace_mac({sig(on_coarse, coarse, bending_x), sig(on_coarse, coarse, bending_y)},
                           {sig(on_fine, fine, rotated), sig(on_fine, fine, bending_y)}) > 0.99);
    }
}

TEST_CASE("A mesh without rings (scattered nodes) still gives comparable signatures", "[mac]") {
    // Nodes at pseudo-random (theta, z): the sampler bins them in z.
    const double length = 1.0, radius = 0.05;
    Mesh scattered;
    std::vector<int> outer;
    unsigned seed = 12345;
    const auto next = [&seed] {
        seed = seed * 1103515245u + 12345u;
        return (seed >> 8) / double(1u << 24);
    };
    for (int i = 0; i < 4000; ++i) {
        const double t = 2 * M_PI * next(), z = length * next();
        outer.push_back(scattered.n_nodes());
        scattered.nodes.push_back({radius * std::cos(t), radius * std::sin(t), z});
    }
    scattered.node_groups["core_outer"] = outer;
    const Mesh rings = ring_mesh(17, 32, length, radius);
    const ModeSignatureSampler a(scattered), b(rings);
    CHECK(mac(a(shape_of(scattered, length, bending_x)), b(shape_of(rings, length, bending_x))) > 0.95);
    CHECK(mac(a(shape_of(scattered, length, bending_x)), b(shape_of(rings, length, ovalling))) < 0.05);
}
