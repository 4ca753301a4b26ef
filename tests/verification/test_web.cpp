// The paper web ([web], effects/web.hpp) against independent truths: its
// springs on a section by hand; a simply supported Timoshenko tube held by a
// web along x, whose first sine mode couples bending in x with torsion
// through the web's line (w = W sin bz, phi = P cos bz, theta = T sin bz
// solve a 3 x 3 problem exactly), and bends freely across it (y: a string
// on a Winkler foundation k_n); the beam and solid levels on one scene.
#include "beam/beam_model.hpp"
#include "beam/network_modes.hpp"
#include "assembly/chuck_supports.hpp"
#include "beam/timoshenko_element.hpp"
#include "effects/web.hpp"
#include "scene/case_file.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>

#include <cmath>

using namespace coremodal;

using testing::web_along;

TEST_CASE("The web's springs on a section, by hand", "[web]") {
    const WebSpec w = web_along(30);
    const double R = 0.1, k_d = 5e9 * 80e-6 / 1.2, k_n = 300 / 1.2, k_z = (w.shear_modulus * 80e-6 + 300) / 1.2;
    const Matrix6 K = web_beam_stiffness_per_length(w, R);
    CHECK((K - K.transpose()).norm() <= 1e-12 * K.norm());
    using V6 = Eigen::Matrix<double, 6, 1>;
    const auto energy = [&](const V6& q) { return q.dot(K * q); };
    V6 along, across, axial, twist;
    along << std::cos(w.angle), std::sin(w.angle), 0, 0, 0, 0;
    across << -std::sin(w.angle), std::cos(w.angle), 0, 0, 0, 0;
    axial << 0, 0, 1, 0, 0, 0;
    twist << 0, 0, 0, 0, 0, 1;
    CHECK(energy(along) == Approx(k_d).epsilon(1e-12));
    CHECK(energy(across) == Approx(k_n).epsilon(1e-12));
    CHECK(energy(axial) == Approx(k_z).epsilon(1e-12));
    // A turn rz of the section moves the tangent point R rz along the web
    // (the roll pays the web out): the twist stretches it like a shift R along d.
    CHECK(energy(twist) == Approx(k_d * R * R).epsilon(1e-12));
    CHECK(energy(twist + R * along) == Approx(4 * k_d * R * R).epsilon(1e-12));
    CHECK(energy(twist - R * along) == Approx(0).margin(1e-9 * k_d * R * R));
    // Positive semi-definite, of rank 3 (three springs).
    const Eigen::SelfAdjointEigenSolver<Matrix6> eig(K);
    CHECK(eig.eigenvalues().minCoeff() > -1e-9 * eig.eigenvalues().maxCoeff());
    CHECK((eig.eigenvalues().array() > 1e-9 * eig.eigenvalues().maxCoeff()).count() == 3);
    // Baum's rule for the default shear modulus.
    CHECK(default_web_shear_modulus(5e9) == Approx(0.387 * std::sqrt(5e9 * 2.5e9)));
}

TEST_CASE("A simply supported tube on a web: bending, torsion and stretch coupled exactly as in closed form",
          "[web][beam]") {
    // Steel tube 106 x 76 mm, 2 m, simply supported (u_x = u_y = 0 and the
    // twist held at both ends, free axially), a stiff web leaving along +x
    // from the tangent point p = (0, -R, 0), R = 53 mm. The surface line
    // moves by u + r x p: (u_x + R r_z, u_y, u_z - R r_x). With the first
    // sine mode in every field (each trig square integrating to L/2) the
    // energies per length give K q = omega^2 M q exactly:
    //  in x-z (W sin, P cos, T sin: deflection, section rotation r_y, twist)
    //   K = [[kGA b^2 + k_d, -kGA b, k_d R], [-kGA b, EI b^2 + kGA, 0], [k_d R, 0, GJ b^2 + k_d R^2]],
    //   M = diag(rho_A, rho_I, rho_J);
    //  in y-z (V sin, P cos, U cos: deflection, r_x, axial)
    //   K = [[kGA b^2 + k_n, kGA b, 0], [kGA b, EI b^2 + kGA + k_z R^2, -k_z R], [0, -k_z R, EA b^2 + k_z]],
    //   M = diag(rho_A, rho_I, rho_A).
    const BeamSection s = tube_beam_section(0.106, 0.076, OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850));
    const double L = 2.0, R = 0.053, b = M_PI / L;
    const WebSpec w = web_along(0, 2e5, 200e9);  // k_d = 1.3e7, k_n = 1.7e5, k_z = 3.8e6 N/m^2: large effects
    const double k_d = w.modulus * w.thickness / w.span, k_n = w.tension / w.span;
    const double k_z = (w.shear_modulus * w.thickness + w.tension) / w.span;
    BeamNetwork net;
    std::vector<double> z;
    for (int i = 0; i <= 40; ++i) z.push_back(L * i / 40);
    net.add_beam("tube", z, std::vector<BeamSection>(40, s), [&](double zi) { return net.add_node(zi); });
    for (int node : {net.beams[0].nodes.front(), net.beams[0].nodes.back()})
        for (int d : {beam_dof::ux, beam_dof::uy, beam_dof::rz}) net.hold(node, d);
    net.couplings.push_back({0, -1, 0.0, L, web_beam_stiffness_per_length(w, R)});
    NetworkSolveRequest request;
    request.n_modes = 8;
    request.lambda_scale = s.EI * std::pow(b, 4) / s.rho_A;
    const NetworkModes modes = solve_network_modes(net, request);
    const auto error = [&](double lambda) {
        double best = 1e300;
        for (double l : modes.eigenvalues) best = std::min(best, std::abs(l / lambda - 1));
        return best;
    };
    Eigen::Matrix3d Kx, Mx = Eigen::Vector3d(s.rho_A, s.rho_I, s.rho_J).asDiagonal();
    Kx << s.kappa_GA * b * b + k_d, -s.kappa_GA * b, k_d * R, -s.kappa_GA * b, s.EI * b * b + s.kappa_GA, 0, k_d * R, 0,
        s.GJ * b * b + k_d * R * R;
    Eigen::Matrix3d Ky, My = Eigen::Vector3d(s.rho_A, s.rho_I, s.rho_A).asDiagonal();
    Ky << s.kappa_GA * b * b + k_n, s.kappa_GA * b, 0, s.kappa_GA * b, s.EI * b * b + s.kappa_GA + k_z * R * R, -k_z * R,
        0, -k_z * R, s.EA * b * b + k_z;
    const double x_lowest = Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d>(Kx, Mx).eigenvalues()[0];
    const double y_lowest = Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d>(Ky, My).eigenvalues()[0];
    const double bare = s.EI * std::pow(b, 4) / s.rho_A;  // Euler-Bernoulli, for scale only
    INFO("lowest in x " << std::sqrt(x_lowest) / (2 * M_PI) << " Hz, in y " << std::sqrt(y_lowest) / (2 * M_PI)
                        << " Hz; bare tube ~" << std::sqrt(bare) / (2 * M_PI) << " Hz");
    CHECK(x_lowest > 1.5 * y_lowest);  // the web's stretch holds the x plane
    // 40 quadratic elements: the first sine mode's discretisation error is ~1e-7 (h^4).
    CHECK(error(x_lowest) < 1e-6);
    CHECK(error(y_lowest) < 1e-6);
    for (double r : modes.relative_residuals) CHECK(r < 1e-9);
}

TEST_CASE("The solid level puts the web's springs on one line of the roll's surface", "[web][solid]") {
    // A paper core 76 x 15 mm, 1 m, 16 cells around (corner nodes every
    // 22.5 deg): the web at 30 deg leaves from theta = -60 deg, between node
    // columns, so the line crosses the faces' interiors. Rigid motions of the
    // roll give the springs' integrals over the line of length L exactly:
    // a shift along d, n or z gives k_d L, k_n L, k_z L; a turn about the
    // axis moves the line by R along d: k_d R^2 L (R of the faceted surface:
    // the quadratic faces' radius differs from the circle's by < 1e-4 here).
    Scene s = testing::paper_core(1.0, 16, 8);
    s.web = web_along(30);
    const Mesh mesh = testing::generated_mesh(s);
    const ChuckSupports supports = chuck_supports(s, mesh);
    REQUIRE(!supports.couplings.empty());
    const double L = 1.0, R = 0.053;
    const double k_d = 5e9 * 80e-6 / 1.2, k_n = 300 / 1.2, k_z = (s.web->shear_modulus * 80e-6 + 300) / 1.2;
    const Eigen::Vector3d d = web_direction(*s.web), n = web_tangent_normal(*s.web), e_z(0, 0, 1);
    const auto energy = [&](const std::function<Eigen::Vector3d(const std::array<double, 3>&)>& field) {
        double e = 0;
        for (const CouplingElement& c : supports.couplings) {
            Eigen::VectorXd q(3 * c.nodes.size());
            for (size_t a = 0; a < c.nodes.size(); ++a) q.segment<3>(3 * a) = field(mesh.nodes[c.nodes[a]]);
            e += q.dot(c.matrix(Term::stiffness) * q);
        }
        return e;
    };
    const auto shift = [](const Eigen::Vector3d& v) {
        return [v](const std::array<double, 3>&) { return v; };
    };
    CHECK(energy(shift(d)) == Approx(k_d * L).epsilon(1e-10));
    CHECK(energy(shift(n)) == Approx(k_n * L).epsilon(1e-10));
    CHECK(energy(shift(e_z)) == Approx(k_z * L).epsilon(1e-10));
    CHECK(energy(shift(d + n)) == Approx((k_d + k_n) * L).epsilon(1e-10));
    const auto turn = [](const std::array<double, 3>& x) { return Eigen::Vector3d(-x[1], x[0], 0); };
    CHECK(energy(turn) == Approx(k_d * R * R * L).epsilon(2e-4));
}
