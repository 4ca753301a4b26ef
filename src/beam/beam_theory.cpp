#include "beam/beam_theory.hpp"

#include "common/error.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

constexpr int kTimoshenkoElements = 80;

double ring_area(double d_out, double d_in) { return M_PI / 4 * (d_out * d_out - d_in * d_in); }
double ring_inertia(double d_out, double d_in) { return M_PI / 64 * (std::pow(d_out, 4) - std::pow(d_in, 4)); }

}  // namespace

double cowper_hollow_circle(double nu, double m) {
    const double q = (1 + m * m) * (1 + m * m);
    return 6 * (1 + nu) * q / ((7 + 6 * nu) * q + (20 + 12 * nu) * m * m);
}

BeamSection beam_section(const Scene& scene) {
    BeamSection s;
    auto add = [&s](double d_out, double d_in, const OrthotropicMaterial& mat) {
        const double A = ring_area(d_out, d_in), I = ring_inertia(d_out, d_in);
        s.EI += mat.E_z * I;
        s.rho_A += mat.density * A;
        s.rho_I += mat.density * I;
        s.kappa_GA += cowper_hollow_circle(mat.nu_thetaz, d_in / d_out) * mat.G_thetaz * A;
    };
    add(scene.core.outer_diameter, scene.core.inner_diameter, scene.core.material);
    if (scene.rest_paper) add(scene.rest_paper->outer_diameter, scene.core.outer_diameter, scene.rest_paper->material);
    return s;
}

double euler_bernoulli_first_bending_hz(const BeamSection& s, double L) {
    return kBeta1L * kBeta1L / (2 * M_PI * L * L) * std::sqrt(s.EI / s.rho_A);
}

std::vector<double> timoshenko_bending_hz(const BeamSection& s, double length, BeamEnds ends, int n_modes) {
    // Unknowns per node: deflection w and section rotation phi.
    // Weak form: int EI phi'^2 + kGA (w' - phi)^2 dx  and  int rhoA w^2 + rhoI phi^2 dx.
    const int n_el = kTimoshenkoElements, n_nodes = 2 * n_el + 1, n = 2 * n_nodes;
    const double h = length / n_el;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), M = Eigen::MatrixXd::Zero(n, n);
    auto shape = [](double xi, double N[3], double dN[3]) {  // on [-1, 1], nodes -1, 0, 1
        N[0] = 0.5 * xi * (xi - 1), N[1] = 1 - xi * xi, N[2] = 0.5 * xi * (xi + 1);
        dN[0] = xi - 0.5, dN[1] = -2 * xi, dN[2] = xi + 0.5;
    };
    const double g3[3] = {-std::sqrt(0.6), 0, std::sqrt(0.6)}, w3[3] = {5. / 9, 8. / 9, 5. / 9};
    const double g2[2] = {-1 / std::sqrt(3.), 1 / std::sqrt(3.)}, w2[2] = {1, 1};
    const double J = h / 2;
    for (int e = 0; e < n_el; ++e) {
        int dof[6];
        for (int a = 0; a < 3; ++a) dof[2 * a] = 2 * (2 * e + a), dof[2 * a + 1] = 2 * (2 * e + a) + 1;
        Eigen::Matrix<double, 6, 6> Ke = Eigen::Matrix<double, 6, 6>::Zero(), Me = Ke;
        double N[3], dN[3];
        for (int q = 0; q < 3; ++q) {  // bending and mass: full integration
            shape(g3[q], N, dN);
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) {
                    Ke(2 * a + 1, 2 * b + 1) += s.EI * dN[a] * dN[b] / (J * J) * J * w3[q];
                    Me(2 * a, 2 * b) += s.rho_A * N[a] * N[b] * J * w3[q];
                    Me(2 * a + 1, 2 * b + 1) += s.rho_I * N[a] * N[b] * J * w3[q];
                }
        }
        for (int q = 0; q < 2; ++q) {  // shear: reduced integration against locking
            shape(g2[q], N, dN);
            double B[6];  // gamma = w' - phi
            for (int a = 0; a < 3; ++a) B[2 * a] = dN[a] / J, B[2 * a + 1] = -N[a];
            for (int i = 0; i < 6; ++i)
                for (int j = 0; j < 6; ++j) Ke(i, j) += s.kappa_GA * B[i] * B[j] * J * w2[q];
        }
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) K(dof[i], dof[j]) += Ke(i, j), M(dof[i], dof[j]) += Me(i, j);
    }
    std::vector<int> keep;
    for (int i = 0; i < n; ++i) {
        const bool end_node = i / 2 == 0 || i / 2 == n_nodes - 1;
        if (!(ends == BeamEnds::clamped_clamped && end_node)) keep.push_back(i);
    }
    Eigen::MatrixXd Kr(keep.size(), keep.size()), Mr(keep.size(), keep.size());
    for (size_t i = 0; i < keep.size(); ++i)
        for (size_t j = 0; j < keep.size(); ++j) Kr(i, j) = K(keep[i], keep[j]), Mr(i, j) = M(keep[i], keep[j]);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(Kr, Mr, Eigen::EigenvaluesOnly);
    std::vector<double> f;
    // Rigid-body modes of a free–free beam come out at |lambda| ~ 1e-10 of the
    // first elastic one; shear and rotary inertia never lower it by 1e4.
    const double f_eb = euler_bernoulli_first_bending_hz(s, length);
    const double rigid_limit = 1e-4 * std::pow(2 * M_PI * f_eb, 2);
    for (int i = 0; i < solver.eigenvalues().size() && int(f.size()) < n_modes; ++i)
        if (solver.eigenvalues()(i) > rigid_limit) f.push_back(std::sqrt(solver.eigenvalues()(i)) / (2 * M_PI));
    return f;
}

double beam_span(const Scene& scene) {
    // Elastic chucks: Ilomäki's free span, core ends to the middles of the
    // furthest expanding elements.
    if (scene.supports.kind == SupportKind::chucks && scene.supports.chucks.size() == 2)
        return scene.core.length - scene.supports.chucks[0].li() - scene.supports.chucks[1].li();
    if (scene.supports.kind == SupportKind::free || scene.supports.clamps.size() < 2) return scene.core.length;
    double left_inner = 0, right_inner = scene.core.length;
    for (const auto& c : scene.supports.clamps) {
        if (c.z_end <= 0.5 * scene.core.length) left_inner = std::max(left_inner, c.z_end);
        else right_inner = std::min(right_inner, c.z_start);
    }
    return right_inner - left_inner;
}

}  // namespace coremodal
