// The damped projected eigensolver against closed forms: a single mode with
// viscous damping (lambda = -zeta omega + i omega sqrt(1 - zeta^2)) and with
// a loss factor (lambda = i omega sqrt(1 + i eta), at resonance as the
// viscous zeta = eta / 2), two modes with Rayleigh damping at rest (zeta_j =
// alpha / (2 omega_j) + beta omega_j / 2) and a spinning isotropic rotor with
// Rayleigh damping, whose two planes are one complex plane z = x + i y:
// m lambda^2 + (c +- i Omega g) lambda + k = 0.
#include "eigensolve/damped_modes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

using namespace coremodal;

namespace {

using cd = std::complex<double>;

// Dense round-off of a 2m companion form: ~1e-15 relative; 1e-12 leaves room.
constexpr double kTight = 1e-12;

bool near(cd a, cd b, double relative) { return std::abs(a - b) <= relative * std::abs(b); }

// The roots of a lambda^2 + b lambda + c = 0 with positive imaginary part.
std::vector<cd> upper_roots(cd a, cd b, cd c) {
    const cd s = std::sqrt(b * b - 4.0 * a * c);
    std::vector<cd> out;
    for (const cd r : {(-b + s) / (2.0 * a), (-b - s) / (2.0 * a)})
        if (r.imag() > 0) out.push_back(r);
    return out;
}

ProjectedDampedModel single_mode(double m, double k) {
    ProjectedDampedModel model;
    model.M = Eigen::MatrixXd::Constant(1, 1, m);
    model.K = Eigen::MatrixXd::Constant(1, 1, k);
    return model;
}

}  // namespace

TEST_CASE("A single damped mode has the closed-form eigenvalue", "[eigensolve][damping]") {
    const double m = 2.0, k = 800.0, omega = std::sqrt(k / m);  // 20 rad/s
    SECTION("viscous: lambda = -zeta omega + i omega sqrt(1 - zeta^2)") {
        const double zeta = 0.05;
        ProjectedDampedModel model = single_mode(m, k);
        model.D = Eigen::MatrixXd::Constant(1, 1, 2 * zeta * m * omega);
        const DampedModes out = damped_modes(model, 0.0, 1e-6);
        REQUIRE(out.modes.size() == 1);
        const DampedMode& mode = out.modes.front();
        CHECK(near(mode.eigenvalue, cd(-zeta * omega, omega * std::sqrt(1 - zeta * zeta)), kTight));
        CHECK(mode.zeta == Approx(zeta).epsilon(kTight));
        CHECK(mode.natural_frequency_hz == Approx(omega / (2 * M_PI)).epsilon(kTight));
        CHECK(mode.backward_error < 1e-14);
    }
    SECTION("structural: lambda = i omega sqrt(1 + i eta), at resonance the viscous zeta = eta / 2") {
        const double eta = 0.04;
        ProjectedDampedModel model = single_mode(m, k);
        model.H = Eigen::MatrixXd::Constant(1, 1, eta * k);
        const DampedModes out = damped_modes(model, 0.0, 1e-6);
        REQUIRE(out.modes.size() == 1);  // the growing root of K + i H is not a mode
        const DampedMode& mode = out.modes.front();
        CHECK(near(mode.eigenvalue, cd(0, omega) * std::sqrt(cd(1, eta)), kTight));
        CHECK(mode.zeta == Approx(std::sin(std::atan(eta) / 2)).epsilon(kTight));
        // sin(atan(eta) / 2) = eta / 2 (1 - 3 eta^2 / 8 + ...): 6e-4 relative at eta = 0.04.
        CHECK(mode.zeta == Approx(eta / 2).epsilon(3 * eta * eta / 8 * 1.01));
        CHECK(mode.zeta != Approx(eta / 2).epsilon(3 * eta * eta / 8 * 0.99));
    }
    SECTION("overdamped: no oscillating mode, two roots on the real axis") {
        ProjectedDampedModel model = single_mode(m, k);
        model.D = Eigen::MatrixXd::Constant(1, 1, 2 * 1.5 * m * omega);  // zeta = 1.5
        const DampedModes out = damped_modes(model, 0.0, 1e-6);
        CHECK(out.modes.empty());
        CHECK(out.n_non_oscillating == 2);
    }
}

TEST_CASE("Two modes with Rayleigh damping take zeta_j = alpha / (2 omega_j) + beta omega_j / 2",
          "[eigensolve][damping]") {
    // M = I, K = k [[2, -1], [-1, 2]]: omega_1^2 = k, omega_2^2 = 3 k.
    const double k = 100.0, alpha = 0.6, beta = 2e-3;
    ProjectedDampedModel model;
    model.M = Eigen::MatrixXd::Identity(2, 2);
    model.K = k * (Eigen::MatrixXd(2, 2) << 2, -1, -1, 2).finished();
    model.D = alpha * model.M + beta * model.K;
    const DampedModes out = damped_modes(model, 0.0, 1e-6);
    REQUIRE(out.modes.size() == 2);
    for (int j = 0; j < 2; ++j) {
        const double omega = std::sqrt((j == 0 ? 1 : 3) * k);
        const double zeta = alpha / (2 * omega) + beta * omega / 2;
        INFO("mode " << j + 1 << ": omega " << omega << ", zeta " << zeta);
        CHECK(near(out.modes[static_cast<size_t>(j)].eigenvalue, cd(-zeta * omega, omega * std::sqrt(1 - zeta * zeta)),
                   kTight));
        CHECK(out.modes[static_cast<size_t>(j)].zeta == Approx(zeta).epsilon(kTight));
    }
}

TEST_CASE("A spinning isotropic rotor with Rayleigh damping whirls at the roots of its complex plane",
          "[eigensolve][damping]") {
    // x, y of a point mass on an isotropic shaft: M = m I, K = k I,
    // D = alpha M + beta K = c I, G = g [[0, -1], [1, 0]]. With z = x + i y,
    // G q is i g z, so m z'' + (c + i Omega g) z' + k z = 0, and for the
    // conjugate plane m lambda^2 + (c - i Omega g) lambda + k = 0.
    const double m = 1.5, k = 600.0, alpha = 0.4, beta = 1e-4, g = 0.8;
    const double c = alpha * m + beta * k;
    ProjectedDampedModel model;
    model.M = m * Eigen::MatrixXd::Identity(2, 2);
    model.K = k * Eigen::MatrixXd::Identity(2, 2);
    model.D = alpha * model.M + beta * model.K;
    model.G = g * (Eigen::MatrixXd(2, 2) << 0, -1, 1, 0).finished();
    for (const double spin : {0.0, 30.0, 120.0}) {
        INFO("spin " << spin << " rad/s");
        std::vector<cd> expected = upper_roots(m, cd(c, spin * g), k);
        for (const cd r : upper_roots(m, cd(c, -spin * g), k)) expected.push_back(r);
        std::sort(expected.begin(), expected.end(), [](cd a, cd b) { return a.imag() < b.imag(); });
        const DampedModes out = damped_modes(model, spin, 1e-6);
        REQUIRE(out.modes.size() == expected.size());
        REQUIRE(expected.size() == 2);  // the backward and the forward whirl
        for (size_t j = 0; j < expected.size(); ++j) {
            CHECK(near(out.modes[j].eigenvalue, expected[j], kTight));
            CHECK(out.modes[j].backward_error < 1e-14);
        }
        // Rayleigh's zeta of the mode at rest, alpha / (2 omega) + beta omega / 2, at spin 0.
        if (spin == 0.0)
            for (const DampedMode& mode : out.modes) {
                const double omega = std::sqrt(k / m);
                CHECK(mode.zeta == Approx(alpha / (2 * omega) + beta * omega / 2).epsilon(kTight));
            }
    }
}

TEST_CASE("A term projected on a basis is V^T A V", "[eigensolve][damping]") {
    // The modes at rest of M = I, K = [[2, -1], [-1, 2]] diagonalise K and any alpha M + beta K.
    const Eigen::MatrixXd K = (Eigen::MatrixXd(2, 2) << 2, -1, -1, 2).finished();
    Eigen::MatrixXd V(2, 2);
    V << 1, 1, 1, -1;
    V /= std::sqrt(2.0);
    const Eigen::MatrixXd Kh = project_term(K, V);
    CHECK(Kh(0, 0) == Approx(1.0).epsilon(kTight));
    CHECK(Kh(1, 1) == Approx(3.0).epsilon(kTight));
    CHECK(std::abs(Kh(0, 1)) < kTight);
}

TEST_CASE("Mirrored families with a loss factor: each double eigenvalue's two vectors span its plane",
          "[eigensolve][damping]") {
    // Two identical chains of 12 masses (K tridiagonal, H = eta K), not
    // coupled: every eigenvalue twice, lambda = i omega_j sqrt(1 + i eta).
    // The pair's vectors must be orthonormal (any basis of the plane is a
    // pair of modes), not the same vector twice: the damped partners of a
    // bending pair were matched on them (models/harmonic/harmonic_spinning.cpp).
    const int n = 12;
    const double eta = 0.04;
    Eigen::MatrixXd chain = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) {
        chain(i, i) = 2e6 + 1e5 * i;  // distinct masses' stiffness: no other coincidences
        if (i + 1 < n) chain(i, i + 1) = chain(i + 1, i) = -1e6;
    }
    ProjectedDampedModel model;
    model.K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    model.K.topLeftCorner(n, n) = chain;
    model.K.bottomRightCorner(n, n) = chain;
    model.M = Eigen::MatrixXd::Identity(2 * n, 2 * n);
    model.H = eta * model.K;
    const DampedModes modes = damped_modes(model, 0.0, 1e-6);
    REQUIRE(modes.modes.size() == size_t(2 * n));
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> undamped(chain);
    for (int j = 0; j < n; ++j) {
        const DampedMode& a = modes.modes[size_t(2 * j)];
        const DampedMode& b = modes.modes[size_t(2 * j + 1)];
        const cd expected = cd(0, std::sqrt(undamped.eigenvalues()(j))) * std::sqrt(cd(1, eta));
        INFO("pair " << j);
        CHECK(near(a.eigenvalue, expected, 1e-9));
        CHECK(near(b.eigenvalue, expected, 1e-9));
        CHECK(std::abs(a.shape.dot(b.shape)) < 1e-8);
        // A double eigenvalue's basis: the SVD of Q(lambda) at the cluster's
        // eigenvalue, itself ~1e-8 off (kSameEigenvalue's measurement):
        // measured up to 1.2e-11 here; 1e-10 as the harmonic level's 1e-9 sweep
        // residuals leave room.
        CHECK(a.backward_error < 1e-10);
        CHECK(b.backward_error < 1e-10);
    }
}
