// Element kernels: shape functions, quadrature, stiffness and mass of hex20,
// hex27 and tet10 on distorted and curved cells.
#include "element/element.hpp"
#include "element/quadrature.hpp"
#include "element/shape_functions.hpp"

#include "support/test_materials.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace coremodal;

namespace {

const CellType all_types[] = {CellType::hex20, CellType::hex27, CellType::tet10};

using coremodal::testing::paperboard;

// Tube sector: r in [ri, ro], theta in [theta0, theta0 + dtheta], z in [0, length].
struct Sector {
    double ri = 0.05, ro = 0.06, theta0 = 0.4, dtheta = 0.5, length = 0.03;
};

// Nodes placed exactly on the cylinders: a hex reference point (xi, eta, zeta)
// maps to r linear in xi, theta linear in eta, z linear in zeta; a tet reference
// point to r linear in xi, theta in eta, z in zeta.
CellCoords sector_cell(CellType type, const Sector& s) {
    const ReferenceCoords& ref = reference_node_coords(type);
    const bool hex = type != CellType::tet10;
    CellCoords X(ref.rows(), 3);
    for (Eigen::Index a = 0; a < ref.rows(); ++a) {
        const Eigen::Vector3d t = hex ? Eigen::Vector3d((ref.row(a).array() + 1.0) / 2.0)
                                      : Eigen::Vector3d(ref.row(a).transpose());
        const double r = s.ri + t.x() * (s.ro - s.ri);
        const double theta = s.theta0 + t.y() * s.dtheta;
        X.row(a) << r * std::cos(theta), r * std::sin(theta), t.z() * s.length;
    }
    return X;
}

// Affine image x = A xi + b of the reference cell.
CellCoords affine_cell(CellType type, const Eigen::Matrix3d& A, const Eigen::Vector3d& b) {
    const ReferenceCoords& ref = reference_node_coords(type);
    CellCoords X(ref.rows(), 3);
    for (Eigen::Index a = 0; a < ref.rows(); ++a)
        X.row(a) = (A * ref.row(a).transpose() + b).transpose();
    return X;
}

Eigen::Matrix3d distorting_map() {
    Eigen::Matrix3d A;
    A << 0.02, 0.004, -0.003,  //
        0.002, 0.015, 0.005,   //
        -0.001, 0.003, 0.025;
    return A;
}

// Six rigid-body fields (3 translations, 3 infinitesimal rotations) at the nodes.
Eigen::MatrixXd rigid_body_modes(const CellCoords& X) {
    const Eigen::Index n = X.rows();
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * n, 6);
    for (Eigen::Index a = 0; a < n; ++a) {
        const Eigen::Vector3d x = X.row(a).transpose();
        for (int c = 0; c < 3; ++c) R(3 * a + c, c) = 1;
        for (int c = 0; c < 3; ++c) {
            Eigen::Vector3d omega = Eigen::Vector3d::Zero();
            omega(c) = 1;
            R.block<3, 1>(3 * a, 3 + c) = omega.cross(x);
        }
    }
    return R;
}

// Sum of M over all DOF pairs of one displacement component: int rho dV.
double mass_of_component(const Eigen::MatrixXd& M, int component) {
    double total = 0;
    for (Eigen::Index i = component; i < M.rows(); i += 3)
        for (Eigen::Index j = component; j < M.cols(); j += 3) total += M(i, j);
    return total;
}

// Exact area swept from the origin by the quadratic interpolant of a unit arc
// of half-angle alpha through its ends and midpoint: triangle plus the
// parabolic segment, 4/3 of the inscribed triangle (Archimedes).
double swept_area_of_quadratic_arc(double alpha) {
    return 0.5 * std::sin(2 * alpha) + 4.0 / 3.0 * std::sin(alpha) * (1 - std::cos(alpha));
}

}  // namespace

TEST_CASE("Shape functions interpolate at gmsh's nodes", "[element][shape]") {
    for (CellType type : all_types) {
        INFO(cell_type_name(type));
        const ReferenceCoords& ref = reference_node_coords(type);
        REQUIRE(ref.rows() == nodes_per_cell(type));
        for (Eigen::Index b = 0; b < ref.rows(); ++b) {
            const Eigen::VectorXd N = shape_values(type, ref.row(b).transpose());
            // Polynomials with small integer coefficients at nodes of +-1, 0, 1/2: exact.
            for (Eigen::Index a = 0; a < N.size(); ++a) CHECK(N(a) == (a == b ? 1.0 : 0.0));
        }
    }
}

TEST_CASE("Shape functions are a partition of unity with consistent gradients",
          "[element][shape]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.05, 0.3);
    for (CellType type : all_types) {
        INFO(cell_type_name(type));
        for (int trial = 0; trial < 5; ++trial) {
            const Eigen::Vector3d xi(u(rng), u(rng), u(rng));  // inside every reference cell
            const Eigen::VectorXd N = shape_values(type, xi);
            const Eigen::MatrixXd dN = shape_gradients(type, xi);
            CHECK(N.sum() == Approx(1.0).epsilon(1e-14));        // round-off of ~27 terms
            CHECK(dN.colwise().sum().cwiseAbs().maxCoeff() < 1e-13);
            // Central differences with h = 1e-5: truncation h^2 |N'''| ~ 1e-10,
            // cancellation eps / h ~ 1e-11; 1e-8 leaves a wide margin.
            const double h = 1e-5;
            for (int j = 0; j < 3; ++j) {
                const Eigen::Vector3d e = Eigen::Vector3d::Unit(j) * h;
                const Eigen::VectorXd fd = (shape_values(type, xi + e) - shape_values(type, xi - e)) / (2 * h);
                CHECK((fd - dN.col(j)).cwiseAbs().maxCoeff() < 1e-8);
            }
        }
    }
}

TEST_CASE("Quadrature rules integrate the promised monomials exactly", "[element][quadrature]") {
    auto factorial = [](int n) { return std::tgamma(n + 1.0); };
    SECTION("3x3x3 Gauss: degree 5 in each direction on [-1, 1]^3") {
        const QuadratureRule rule = gauss_hex_3x3x3();
        auto exact_1d = [](int p) { return p % 2 ? 0.0 : 2.0 / (p + 1); };
        for (int p = 0; p <= 5; ++p)
            for (int q = 0; q <= 5; ++q)
                for (int r = 0; r <= 5; ++r) {
                    double sum = 0;
                    for (int k = 0; k < rule.size(); ++k)
                        sum += rule.weights[k] * std::pow(rule.points[k].x(), p) *
                               std::pow(rule.points[k].y(), q) * std::pow(rule.points[k].z(), r);
                    // 27 terms of size <= 1: a few ulps.
                    CHECK(std::abs(sum - exact_1d(p) * exact_1d(q) * exact_1d(r)) < 1e-14);
                }
    }
    SECTION("14-point tet rule: total degree 5 on the unit tet, positive weights") {
        const QuadratureRule rule = tet_degree5_14_point();
        for (double w : rule.weights) CHECK(w > 0);
        for (int p = 0; p <= 5; ++p)
            for (int q = 0; p + q <= 5; ++q)
                for (int r = 0; p + q + r <= 5; ++r) {
                    double sum = 0;
                    for (int k = 0; k < rule.size(); ++k)
                        sum += rule.weights[k] * std::pow(rule.points[k].x(), p) *
                               std::pow(rule.points[k].y(), q) * std::pow(rule.points[k].z(), r);
                    const double exact =
                        factorial(p) * factorial(q) * factorial(r) / factorial(p + q + r + 3);
                    // Parameters carry 25 digits; 14 terms of size <= 1/6: a few ulps.
                    CHECK(std::abs(sum - exact) < 1e-16);
                }
    }
}

TEST_CASE("Stiffness of curved cells: symmetric, six rigid modes, rest positive",
          "[element][stiffness]") {
    const Matrix6 C = stiffness_cylindrical(paperboard());
    for (CellType type : all_types) {
        INFO(cell_type_name(type));
        const CellCoords X = sector_cell(type, Sector{});
        Eigen::MatrixXd K, M;
        element_matrices(type, X, C, 700, K, M);
        REQUIRE(K.rows() == 3 * nodes_per_cell(type));
        // The kernel mirrors one triangle: exact symmetry.
        CHECK((K - K.transpose()).cwiseAbs().maxCoeff() == 0.0);
        const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
        const double largest = lambda.maxCoeff();
        // Round-off leaves the rigid-mode eigenvalues at ~1e-15 of the largest;
        // the smallest elastic one (radially soft paperboard, E_r/E_z = 0.005)
        // is still above 1e-6 of it, so 1e-10 separates them cleanly.
        int n_zero = 0;
        for (Eigen::Index i = 0; i < lambda.size(); ++i) {
            if (std::abs(lambda(i)) < 1e-10 * largest) ++n_zero;
            else CHECK(lambda(i) > 0);
        }
        CHECK(n_zero == 6);
        // Every rigid-body field is in the null space: B u = 0 pointwise.
        const Eigen::MatrixXd R = rigid_body_modes(X);
        CHECK((K * R).cwiseAbs().maxCoeff() < 1e-12 * K.cwiseAbs().maxCoeff() * R.cwiseAbs().maxCoeff());
    }
}

TEST_CASE("Consistent mass sums to rho times the volume", "[element][mass]") {
    const Matrix6 C = stiffness_cylindrical(paperboard());
    const double rho = 700;
    for (CellType type : all_types) {
        INFO(cell_type_name(type));
        SECTION(std::string("parallelepiped ") + cell_type_name(type)) {
            const Eigen::Matrix3d A = distorting_map();
            const double volume = (type == CellType::tet10 ? 1.0 / 6.0 : 8.0) * A.determinant();
            Eigen::MatrixXd K, M;
            element_matrices(type, affine_cell(type, A, Eigen::Vector3d(0.1, 0.02, 0.3)), C, rho, K, M);
            // Constant Jacobian, exact quadrature: round-off only.
            for (int c = 0; c < 3; ++c) CHECK(mass_of_component(M, c) == Approx(rho * volume).epsilon(1e-13));
            // Components do not couple, and M is symmetric positive definite.
            CHECK(M(0, 1) == 0.0);
            CHECK(Eigen::LLT<Eigen::MatrixXd>(M).info() == Eigen::Success);
        }
    }
    SECTION("curved tube sector hex20 and hex27") {
        const Sector s;
        const double volume = s.length * (s.ro * s.ro - s.ri * s.ri) * swept_area_of_quadratic_arc(s.dtheta / 2);
        for (CellType type : {CellType::hex20, CellType::hex27}) {
            Eigen::MatrixXd K, M;
            element_matrices(type, sector_cell(type, s), C, rho, K, M);
            // The isoparametric volume is integrated exactly (see the volume test).
            CHECK(mass_of_component(M, 2) == Approx(rho * volume).epsilon(1e-13));
        }
    }
}

TEST_CASE("Volume of a curved tube sector cell", "[element][volume]") {
    // Nodes on the arcs make x = r(xi) P(eta) + z(zeta) e_z, with r linear and
    // P the quadratic interpolant of the unit arc (both hex20 and hex27 span
    // this map). Its volume is L (ro^2 - ri^2) S(alpha) with S the swept area
    // of the interpolated arc, S = alpha - alpha^5/30 + O(alpha^7), and det J
    // is of degree <= 3 per direction, so 3-point Gauss integrates it exactly.
    for (double dtheta : {0.5, 0.2}) {
        Sector s;
        s.dtheta = dtheta;
        const double alpha = dtheta / 2;
        const double isoparametric = s.length * (s.ro * s.ro - s.ri * s.ri) * swept_area_of_quadratic_arc(alpha);
        const double true_sector = s.length * (s.ro * s.ro - s.ri * s.ri) * alpha;
        for (CellType type : {CellType::hex20, CellType::hex27}) {
            INFO(cell_type_name(type) << ", dtheta = " << dtheta);
            const double volume = element_volume(type, sector_cell(type, s));
            CHECK(volume == Approx(isoparametric).epsilon(1e-13));  // exact quadrature: round-off
            // Geometric error of the quadratic arc: relative alpha^4 / 30 at
            // leading order; the next term is O(alpha^6), so allow 1 %.
            const double relative_error = (true_sector - volume) / true_sector;
            CHECK(relative_error == Approx(std::pow(alpha, 4) / 30).epsilon(0.01));
        }
    }
}

TEST_CASE("Volume of a curved tet10 with a known quadratic map", "[element][volume]") {
    // x = A (xi + beta xi eta, eta, zeta): tet10 reproduces quadratic maps, and
    // det = det A (1 + beta eta) integrates to det A (1/6 + beta/24).
    const double beta = 0.4;
    const Eigen::Matrix3d A = distorting_map();
    const ReferenceCoords& ref = reference_node_coords(CellType::tet10);
    CellCoords X(10, 3);
    for (int a = 0; a < 10; ++a) {
        const Eigen::Vector3d xi = ref.row(a).transpose();
        X.row(a) = (A * Eigen::Vector3d(xi.x() + beta * xi.x() * xi.y(), xi.y(), xi.z())).transpose();
    }
    // det J is cubic, the rule exact to degree 5: round-off only.
    CHECK(element_volume(CellType::tet10, X) == Approx(A.determinant() * (1.0 / 6 + beta / 24)).epsilon(1e-13));
}

TEST_CASE("An inverted cell throws naming the cell type and the Jacobian", "[element]") {
    for (CellType type : all_types) {
        CellCoords X = affine_cell(type, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
        X.col(2) *= -1;  // mirror image: det J < 0 everywhere
        Eigen::MatrixXd K, M;
        const Matrix6 C = stiffness_cylindrical(paperboard());
        CHECK_THROWS_WITH(element_matrices(type, X, C, 700, K, M),
                          Catch::Contains(cell_type_name(type)) && Catch::Contains("Jacobian"));
        CHECK_THROWS_AS(element_volume(type, X), std::runtime_error);
    }
}

TEST_CASE("Uniaxial radial strain meets the radial modulus at theta = 90 degrees",
          "[element][stiffness]") {
    // A small hex20 box centred on (0, R): there e_r = y, so eps_yy is radial
    // and u.K.u = C_rr V (C_tt V, 120 times larger, if r and theta were
    // swapped). Over the cell theta varies by +-h/R = 1e-3, changing
    // C_yy by ~ (C_tt / C_rr) (h/R)^2 ~ 1e-4 relative: tolerance 1e-3.
    const double R = 1.0, h = 1e-3;
    const Matrix6 C = stiffness_cylindrical(paperboard());
    const CellCoords X = affine_cell(CellType::hex20, Eigen::Matrix3d::Identity() * h, Eigen::Vector3d(0, R, 0));
    Eigen::MatrixXd K, M;
    element_matrices(CellType::hex20, X, C, 700, K, M);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(60);
    for (int a = 0; a < 20; ++a) u(3 * a + 1) = X(a, 1);  // u_y = y: eps_yy = 1
    const double volume = 8 * h * h * h;
    CHECK(u.dot(K * u) == Approx(C(0, 0) * volume).epsilon(1e-3));
}

namespace {

// A 3x3x3 patch of hex20 cells on the unit cube; every cell touches an
// interior corner, and all interior corners are moved randomly by up to 20 %
// of the cell size, so every cell is a distorted (straight-edged) hex.
struct Patch {
    std::vector<Eigen::Vector3d> nodes;
    std::vector<std::vector<int>> cells;  // gmsh hex20 order
    std::vector<bool> on_boundary;
};

Patch distorted_hex20_patch(int n_cells, const Eigen::Vector3d& origin) {
    const int n = 2 * n_cells + 1;  // quadratic lattice points per direction
    const double h = 1.0 / n_cells;
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> jitter(-0.2 * h, 0.2 * h);
    // Corner positions (even lattice indices), interior ones jittered.
    std::map<std::array<int, 3>, Eigen::Vector3d> corner;
    for (int i = 0; i < n; i += 2)
        for (int j = 0; j < n; j += 2)
            for (int k = 0; k < n; k += 2) {
                Eigen::Vector3d x(i / 2 * h, j / 2 * h, k / 2 * h);
                const bool interior = i > 0 && i < n - 1 && j > 0 && j < n - 1 && k > 0 && k < n - 1;
                if (interior) x += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
                corner[{i, j, k}] = x + origin;
            }
    Patch patch;
    std::map<std::array<int, 3>, int> id;
    // Node at lattice point p: a corner, or the midpoint of the two corners
    // of its edge (straight edges keep the patch test exact under 3x3x3 Gauss).
    auto node = [&](std::array<int, 3> p) {
        if (auto it = id.find(p); it != id.end()) return it->second;
        std::array<int, 3> lo = p, hi = p;
        for (int d = 0; d < 3; ++d)
            if (p[d] % 2) lo[d] = p[d] - 1, hi[d] = p[d] + 1;
        patch.nodes.push_back(0.5 * (corner.at(lo) + corner.at(hi)));
        bool boundary = false;
        for (int d = 0; d < 3; ++d) boundary = boundary || p[d] == 0 || p[d] == n - 1;
        patch.on_boundary.push_back(boundary);
        return id[p] = static_cast<int>(patch.nodes.size()) - 1;
    };
    const ReferenceCoords& ref = reference_node_coords(CellType::hex20);
    for (int ci = 0; ci < n_cells; ++ci)
        for (int cj = 0; cj < n_cells; ++cj)
            for (int ck = 0; ck < n_cells; ++ck) {
                std::vector<int> cell;
                for (int a = 0; a < 20; ++a)
                    cell.push_back(node({2 * ci + 1 + static_cast<int>(ref(a, 0)),
                                         2 * cj + 1 + static_cast<int>(ref(a, 1)),
                                         2 * ck + 1 + static_cast<int>(ref(a, 2))}));
                patch.cells.push_back(cell);
            }
    return patch;
}

Eigen::MatrixXd assemble_dense_stiffness(const Patch& patch, const Matrix6& C) {
    const int n_dof = 3 * static_cast<int>(patch.nodes.size());
    Eigen::MatrixXd K_global = Eigen::MatrixXd::Zero(n_dof, n_dof);
    CellCoords X(20, 3);
    Eigen::MatrixXd K, M;
    for (const auto& cell : patch.cells) {
        for (int a = 0; a < 20; ++a) X.row(a) = patch.nodes[cell[a]].transpose();
        element_matrices(CellType::hex20, X, C, 1000, K, M);
        for (int a = 0; a < 20; ++a)
            for (int b = 0; b < 20; ++b)
                K_global.block<3, 3>(3 * cell[a], 3 * cell[b]) += K.block<3, 3>(3 * a, 3 * b);
    }
    return K_global;
}

}  // namespace

TEST_CASE("Patch test: distorted hex20 cells reproduce a linear displacement field",
          "[element][patch]") {
    // Homogeneous material: a constant strain is then an exact equilibrium state.
    const Matrix6 C = stiffness_cylindrical(OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850));
    const Patch patch = distorted_hex20_patch(3, Eigen::Vector3d::Zero());
    const Eigen::MatrixXd K = assemble_dense_stiffness(patch, C);
    Eigen::Matrix3d grad;
    grad << 1e-3, 2e-4, -3e-4,  //
        -1e-4, 5e-4, 4e-4,      //
        2e-4, -6e-4, 8e-4;
    const Eigen::Vector3d u0(1e-3, -2e-3, 5e-4);
    const int n_nodes = static_cast<int>(patch.nodes.size());
    Eigen::VectorXd u_exact(3 * n_nodes);
    std::vector<int> interior, boundary;
    for (int a = 0; a < n_nodes; ++a) {
        u_exact.segment<3>(3 * a) = u0 + grad * patch.nodes[a];
        for (int c = 0; c < 3; ++c) (patch.on_boundary[a] ? boundary : interior).push_back(3 * a + c);
    }
    REQUIRE(interior.size() > 60);  // 8 interior corners and their edge nodes
    // Interior forces of the exact field: int grad N_a . sigma dV sums to zero
    // over the patch; with straight edges the integrand is a polynomial Gauss
    // integrates exactly, so only round-off remains (1e-12 of |K| |u|).
    const Eigen::VectorXd f = K * u_exact;
    const double scale = K.cwiseAbs().maxCoeff() * u_exact.cwiseAbs().maxCoeff();
    for (int i : interior) CHECK(std::abs(f(i)) < 1e-12 * scale);
    // Solve K_II u_I = -K_IB u_B: cond(K_II) ~ 1e3 on this patch, so the
    // solution carries ~1e-13 relative error; 1e-10 of |u| is the brief's target.
    const Eigen::Index ni = interior.size(), nb = boundary.size();
    Eigen::MatrixXd K_II(ni, ni), K_IB(ni, nb);
    Eigen::VectorXd u_B(nb);
    for (Eigen::Index i = 0; i < ni; ++i) {
        for (Eigen::Index j = 0; j < ni; ++j) K_II(i, j) = K(interior[i], interior[j]);
        for (Eigen::Index j = 0; j < nb; ++j) K_IB(i, j) = K(interior[i], boundary[j]);
    }
    for (Eigen::Index j = 0; j < nb; ++j) u_B(j) = u_exact(boundary[j]);
    const Eigen::VectorXd u_I = K_II.ldlt().solve(-K_IB * u_B);
    double max_error = 0;
    for (Eigen::Index i = 0; i < ni; ++i) max_error = std::max(max_error, std::abs(u_I(i) - u_exact(interior[i])));
    CHECK(max_error < 1e-10 * u_exact.cwiseAbs().maxCoeff());
}

TEST_CASE("A rigid rotation about z gives zero forces with cylindrical orthotropy",
          "[element][patch]") {
    // C varies from point to point (theta changes across the off-axis patch),
    // but a rigid rotation has zero strain everywhere, so K u = 0 to round-off.
    const Matrix6 C = stiffness_cylindrical(paperboard());
    const Patch patch = distorted_hex20_patch(2, Eigen::Vector3d(0.5, 0.2, 0.0));
    const Eigen::MatrixXd K = assemble_dense_stiffness(patch, C);
    Eigen::VectorXd u(3 * patch.nodes.size());
    for (std::size_t a = 0; a < patch.nodes.size(); ++a)
        u.segment<3>(3 * a) = Eigen::Vector3d::UnitZ().cross(patch.nodes[a]) * 1e-3;
    const double scale = K.cwiseAbs().maxCoeff() * u.cwiseAbs().maxCoeff();
    CHECK((K * u).cwiseAbs().maxCoeff() < 1e-12 * scale);
    // And the patch is not trivially stiff-free: a radial expansion costs energy.
    Eigen::VectorXd v(u.size());
    for (std::size_t a = 0; a < patch.nodes.size(); ++a)
        v.segment<3>(3 * a) = Eigen::Vector3d(patch.nodes[a].x(), patch.nodes[a].y(), 0) * 1e-3;
    CHECK(v.dot(K * v) > 0);
}
