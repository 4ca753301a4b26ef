#include "beam/beam_theory.hpp"

#include "beam/timoshenko_element.hpp"
#include "common/error.hpp"
#include "eigensolve/verification.hpp"  // eigenvalue_hz

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

constexpr int kTimoshenkoElements = 80;
constexpr int kFreeFreeRigidModes = 2;

double ring_area(double d_out, double d_in) { return M_PI / 4 * (d_out * d_out - d_in * d_in); }
double ring_inertia(double d_out, double d_in) { return M_PI / 64 * (std::pow(d_out, 4) - std::pow(d_in, 4)); }

}  // namespace

double cowper_hollow_circle(double nu, double m) {
    const double q = (1 + m * m) * (1 + m * m);
    return 6 * (1 + nu) * q / ((7 + 6 * nu) * q + (20 + 12 * nu) * m * m);
}

BeamSection& BeamSection::operator+=(const BeamSection& layer) {
    EI += layer.EI, rho_A += layer.rho_A, rho_I += layer.rho_I, kappa_GA += layer.kappa_GA;
    EA += layer.EA, GJ += layer.GJ, rho_J += layer.rho_J;
    return *this;
}

BeamSection tube_beam_section(double d_out, double d_in, const OrthotropicMaterial& mat) {
    const double A = ring_area(d_out, d_in), I = ring_inertia(d_out, d_in);
    BeamSection s;
    s.EI = mat.E_z * I;
    s.rho_A = mat.density * A;
    s.rho_I = mat.density * I;
    s.kappa_GA = cowper_hollow_circle(mat.nu_thetaz, d_in / d_out) * mat.G_thetaz * A;
    s.EA = mat.E_z * A;
    s.GJ = mat.G_thetaz * 2 * I;
    s.rho_J = mat.density * 2 * I;
    return s;
}

RestRollSection rest_roll_section(const Scene& s) {
    RestRollSection sec;
    sec.Di = s.core.inner_diameter, sec.Do = s.core.outer_diameter;
    sec.Ec = s.core.material.E_z, sec.rho_c = s.core.material.density;
    sec.Dp = s.rest_paper ? s.rest_paper->outer_diameter : sec.Do;
    if (s.rest_paper) sec.Ep = s.rest_paper->material.E_z, sec.rho_p = s.rest_paper->material.density;
    return sec;
}

BeamSection beam_section(const Scene& scene) {
    BeamSection s = tube_beam_section(scene.core.outer_diameter, scene.core.inner_diameter, scene.core.material);
    if (scene.rest_paper)
        s += tube_beam_section(scene.rest_paper->outer_diameter, scene.core.outer_diameter, scene.rest_paper->material);
    return s;
}

double euler_bernoulli_first_bending_hz(const BeamSection& s, double L) {
    return kBeta1L * kBeta1L / (2 * M_PI * L * L) * std::sqrt(s.EI / s.rho_A);
}

std::vector<double> timoshenko_bending_hz(const BeamSection& s, double length, BeamEnds ends, int n_modes) {
    // Unknowns per node: deflection w and section rotation phi; the plane
    // element of timoshenko_element.hpp.
    const int n_el = kTimoshenkoElements, n_nodes = 2 * n_el + 1, n = 2 * n_nodes;
    const TimoshenkoElement element{length / n_el, s};
    const PlaneMatrix Ke = plane_bending_stiffness(element), Me = plane_bending_mass(element);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), M = Eigen::MatrixXd::Zero(n, n);
    for (int e = 0; e < n_el; ++e) {
        K.block<6, 6>(4 * e, 4 * e) += Ke;
        M.block<6, 6>(4 * e, 4 * e) += Me;
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
    // A free–free beam in its plane has exactly two rigid-body modes (a
    // translation and a rotation), the two lowest eigenvalues (zero up to
    // round-off). Counting them, not comparing with a threshold, holds for any
    // length: a threshold scaled by Euler–Bernoulli once dropped the shear-bending
    // mode of a beam shorter than its diameter, and every mode of a 10 um one.
    const int n_rigid = ends == BeamEnds::free_free ? kFreeFreeRigidModes : 0;
    std::vector<double> f;
    for (int i = n_rigid; i < solver.eigenvalues().size() && int(f.size()) < n_modes; ++i)
        f.push_back(eigenvalue_hz(solver.eigenvalues()(i)));
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
