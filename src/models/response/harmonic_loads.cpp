#include "models/response/harmonic_loads.hpp"

#include "models/response/sparse_sink.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "effects/excitation.hpp"
#include "element/harmonic_element.hpp"
#include "geometry/tube_section.hpp"
#include "models/part_materials.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <map>

namespace coremodal {
namespace {

using cd = std::complex<double>;
constexpr int kPlaneWaveNumber = 1;  // sideways motion lives in n = 1 alone

bool in_part(const HarmonicPlane& plane, int cell, const std::string& part) {
    return plane.section.part_names[plane.section.cell_part[cell]] == part;
}

bool in_roll(const HarmonicPlane& plane, int cell) {
    return in_part(plane, cell, "core") || in_part(plane, cell, "rest_paper");
}

Eigen::SparseMatrix<double> cells_matrix(const HarmonicPlane& plane, const std::function<bool(int)>& take, Term term) {
    SparseSink sink(plane.dofs.n_dofs);
    assemble_harmonic_cells(plane.section, plane.materials, plane.dofs, kPlaneWaveNumber, take, sink.insert());
    return sink.matrix(term);
}

// K_roll u_bow, element by element over the core's and rest paper's cells,
// with the bowed axis given at every node, held ones included: a bowed
// core is stress-free in its bowed shape everywhere, and where a clamp
// holds its bore straight the clamp's force is part of the load (as the
// beam level's core_stiffness_load takes the held nodes' bow too). The bow
// is U = V = w(z) sideways, W = -r w'(z) (plane sections turned with the
// axis: no shear in the bow itself).
Eigen::VectorXd bow_load(const HarmonicPlane& plane, const std::function<double(double)>& w,
                         const std::function<double(double)>& slope) {
    const SectionMesh& s = plane.section;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(plane.dofs.n_dofs);
    for (int c = 0; c < s.n_cells(); ++c) {
        if (!in_roll(plane, c)) continue;
        Quad8Coords x;
        Eigen::Matrix<double, 24, 1> u;
        for (int a = 0; a < 8; ++a) {
            const double r = s.nodes[s.cells[c][a]][0], z = s.nodes[s.cells[c][a]][1];
            x.row(a) << r, z;
            u.segment<3>(3 * a) << w(z), w(z), -r * slope(z);
        }
        const PartMaterial& mat = plane.materials.at(s.cell_part[c]);
        const Eigen::Matrix<double, 24, 1> fe =
            harmonic_quad8_matrices(x, mat.C_cylindrical, mat.density, kPlaneWaveNumber).K * u;
        for (int a = 0; a < 8; ++a)
            for (int k = 0; k < 3; ++k)
                if (const int d = plane.dofs.of_component[3 * s.cells[c][a] + k]; d >= 0) f(d) += fe(3 * a + k);
    }
    return f;
}

Eigen::VectorXd bow_load(const Scene& scene, const ExcitationSpec& x, const HarmonicPlane& plane,
                         const Eigen::VectorXd& first_mode) {
    const double L = scene.core.length;
    if (x.bow_shape == BowShape::half_sine)
        return bow_load(plane, [&](double z) { return half_sine_bow(x.bow_m, z, L); },
                        [&](double z) { return half_sine_bow_slope(x.bow_m, z, L); });
    // The first bending mode, zero where held: K_roll times it on the free DOFs.
    COREMODAL_ASSERT(first_mode.size() == plane.dofs.n_dofs);
    return x.bow_m / section_probe(plane, 0.5 * L).dot(first_mode) * (plane.K_roll * first_mode);
}

Eigen::VectorXd sideways_translation(const HarmonicPlane& plane) {
    const std::vector<double> r = harmonic_rigid_field(plane.section, plane.dofs, kPlaneWaveNumber, RigidMotion::x);
    return Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

}  // namespace

PartStiffness harmonic_part_stiffness(const HarmonicPlane& plane) {
    return {plane.K.rows(), plane.section.part_names,
            [&plane](const std::string& part) {
                return cells_matrix(plane, [&](int c) { return in_part(plane, c, part); }, Term::stiffness);
            },
            "each part's cells of wave number n = 1 (core, rest paper, chucks)"};
}

HarmonicPlane assemble_harmonic_plane(const Scene& scene) {
    HarmonicPlane plane;
    plane.section = make_section_mesh(make_tube_section(scene), scene.supports.clamps);
    plane.materials = part_materials(scene, plane.section.part_names, "generated section");
    plane.dofs = harmonic_dofs(scene, plane.section, kPlaneWaveNumber);
    SparseSink whole(plane.dofs.n_dofs), spin(plane.dofs.n_dofs);
    assemble_harmonic_terms(scene, plane.section, plane.materials, plane.dofs, kPlaneWaveNumber, whole.insert());
    assemble_harmonic_spin_terms(plane.section, plane.materials, plane.dofs, kPlaneWaveNumber, spin.insert());
    plane.K = whole.matrix(Term::stiffness);
    plane.M = whole.matrix(Term::mass);
    plane.G = 2.0 * spin.matrix(Term::gyroscopic);  // G = 2 Gamma (spinning_harmonic.hpp)
    plane.K_roll = cells_matrix(plane, [&](int c) { return in_roll(plane, c); }, Term::stiffness);
    plane.K_core = cells_matrix(plane, [&](int c) { return in_part(plane, c, "core"); }, Term::stiffness);
    plane.M_rest_paper = cells_matrix(plane, [&](int c) { return in_part(plane, c, "rest_paper"); }, Term::mass);
    return plane;
}

Eigen::VectorXd section_probe(const HarmonicPlane& plane, double z) {
    // One core cell per radial position whose z range holds z (a cell
    // boundary at z belongs to the first found), 3 Gauss points across it.
    const double xi[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, weight[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    const SectionMesh& s = plane.section;
    std::map<double, int> by_radius;
    for (int c = 0; c < s.n_cells(); ++c) {
        const double z0 = s.nodes[s.cells[c][0]][1], z1 = s.nodes[s.cells[c][3]][1];
        if (in_part(plane, c, "core") && z >= std::min(z0, z1) && z <= std::max(z0, z1))
            by_radius.emplace(s.nodes[s.cells[c][0]][0], c);
    }
    if (by_radius.empty()) throw InputError("[response] probe at z = " + significant(z, 4) + " m is not on the core");
    Eigen::VectorXd w = Eigen::VectorXd::Zero(plane.dofs.n_dofs);
    double area = 0;  // the integral of r dr over the wall
    for (const auto& [r0, c] : by_radius) {
        const double r1 = s.nodes[s.cells[c][1]][0], z0 = s.nodes[s.cells[c][0]][1], z1 = s.nodes[s.cells[c][3]][1];
        const double eta = 2 * (z - z0) / (z1 - z0) - 1;  // section cells are rectangles: xi along r, eta along z
        for (int g = 0; g < 3; ++g) {
            const double r = r0 + 0.5 * (xi[g] + 1) * (r1 - r0), dA = weight[g] * 0.5 * (r1 - r0) * r;
            const Eigen::Matrix<double, 8, 1> N = quad8_values(xi[g], eta);
            for (int a = 0; a < 8; ++a)
                for (int k = 0; k < 2; ++k)  // U and V: u_x averages (U + V) / 2 over the ring
                    if (const int d = plane.dofs.of_component[3 * s.cells[c][a] + k]; d >= 0) w(d) += 0.5 * dA * N(a);
            area += dA;
        }
    }
    return w / area;
}

LevelLoads build_harmonic_loads(const Scene& scene, const ExcitationSpec& x, const HarmonicPlane& plane,
                                   const ModalResponse& response, const Eigen::VectorXd& first_mode) {
    LevelLoads out;
    const Eigen::VectorXcd zero = Eigen::VectorXcd::Zero(plane.dofs.n_dofs);
    const Eigen::VectorXd r_x = sideways_translation(plane);
    if (x.unbalance_kg_m > 0)  // U Omega^2 at the core's cross-section at mid-core
        add_order_load(out.orders, 1, zero, (x.unbalance_kg_m * section_probe(plane, 0.5 * scene.core.length)).cast<cd>(),
                       Unbalance::kName);
    if (x.eccentricity_m > 0)  // the rest paper's mass, e Omega^2 sideways
        add_order_load(out.orders, 1, zero, (x.eccentricity_m * (plane.M_rest_paper * r_x)).cast<cd>(), Eccentricity::kName);
    if (x.bow_m > 0)
        add_order_load(out.orders, 1, bow_load(scene, x, plane, first_mode).cast<cd>(), zero, Bow::kName);
    if (x.gravity) out.sag = response.static_response(kGravity * (plane.M * r_x));
    if (x.ovality_m > 0 && x.gravity) {
        out.ovality_split = ovality_stiffness_split(x.ovality_m, scene.core.outer_diameter, scene.core.inner_diameter);
        add_ovality_load(out, (plane.K_core * out.sag).cast<cd>(),
                         "in wave number n = 1, to first order in eps (the ovalling it also drives in n = 2 and 3 is "
                         "not computed)");
    }
    sort_orders(out);
    return out;
}

}  // namespace coremodal
