// The coupled problem truncated at N: each independent set of harmonics
// solved (or, for a congruent partner, mapped from its primary), the modes
// merged in frequency order on all blocks' DOFs, and read off there.
#include "models/coupled/coupled_modes.hpp"

#include "assembly/harmonic_system.hpp"
#include "common/petsc_handle.hpp"
#include "models/solve_steps.hpp"
#include "modes/mode_shapes.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

int CoupledModes::dominant_n(size_t k) const {
    const std::vector<double>& e = block_energy.at(k);
    const size_t b = std::max_element(e.begin(), e.end()) - e.begin();
    return dofs.blocks.at(b).harmonic.n;
}

namespace {


// The rigid motions (x, y, z, about z) on the coupled DOFs: x lives in
// (1, cos), y in (1, sin) (the same field turned by 90 deg), z and about z in n = 0.
std::array<std::vector<double>, 4> rigid_fields(const SectionMesh& section, const CoupledDofs& dofs) {
    std::array<std::vector<double>, 4> r;
    for (auto& v : r) v.assign(dofs.n_dofs, 0.0);
    const auto put = [&](int d, int n, Family f, RigidMotion motion) {
        const int b = dofs.block_of(n, f);
        if (b < 0) return;
        const CoupledBlock& block = dofs.blocks[b];
        const std::vector<double> field = harmonic_rigid_field(section, block.dofs, n, motion);
        std::copy(field.begin(), field.end(), r[d].begin() + block.offset);
    };
    put(0, 1, Family::cos, RigidMotion::x);
    put(1, 1, Family::sin, RigidMotion::x);
    put(2, 0, Family::cos, RigidMotion::z);
    put(3, 0, Family::cos, RigidMotion::rz);
    return r;
}

// One independent component's verified modes on its own DOFs (the vectors
// and their products with M on rank 0).
struct ComponentModes {
    std::vector<double> eigenvalues, residuals;
    std::vector<std::vector<double>> x, Mx;
    Verification verification;
    double mass_kg = 0;
    long n_coupling_entries = 0;
};

ComponentModes solve_component(const Scene& scene, const SectionMesh& section,
                               const std::vector<PartMaterial>& materials, const CoupledComponent& component,
                               const SolveRequest& request, const Attachments& attached) {
    CoupledSystem system = assemble_coupled(scene, section, materials, component.dofs, attached);
    ComponentModes out;
    out.mass_kg = system.operators.model_mass;
    out.n_coupling_entries = system.n_coupling_entries;
    std::string blocks;
    for (const CoupledBlock& b : component.dofs.blocks)
        if (b.harmonic.n < 7) blocks += std::to_string(b.harmonic.n) + (b.harmonic.family == Family::sin ? "s " : "c ");
    const SolvedModes solved = solve_for_case(scene, system.operators, request, [](const std::string&) {},
                                              "the coupled problem of the harmonics " + blocks + "... N = " +
                                                  std::to_string(component.dofs.n_max) + ": ");
    out.verification = solved.verification;
    out.eigenvalues = solved.eigenvalues;
    out.residuals = solved.relative_residuals;
    for (const PetscVector& x : solved.vectors) {
        PetscVector Mx;
        COREMODAL_PETSC(VecDuplicate(x, Mx.out()));
        COREMODAL_PETSC(MatMult(system.operators.M(), x, Mx));
        std::vector<double> v = gather_to_root(x), mv = gather_to_root(Mx);
        if (mpi_rank() != 0) continue;
        out.x.push_back(std::move(v));
        out.Mx.push_back(std::move(mv));
    }
    return out;
}

// A component's modes added to the whole, mapped onto all blocks' DOFs;
// `sign` (per block of `component`) maps a primary's modes onto its partner.
void add_component(const CoupledComponent& component, const ComponentModes& modes, const std::vector<double>& sign,
                   const std::array<std::vector<double>, 4>& rigid, CoupledModes& out) {
    out.mass_kg = std::max(out.mass_kg, modes.mass_kg);  // the block n = 0 carries it
    out.n_coupling_entries += modes.n_coupling_entries;
    // Counts add over independent problems, as over the harmonic level's wave numbers.
    Verification& v = out.verification;
    const Verification& w = modes.verification;
    v.max_relative_residual = std::max(v.max_relative_residual, w.max_relative_residual);
    v.max_orthonormality_error = std::max(v.max_orthonormality_error, w.max_orthonormality_error);
    v.check_shift = std::min(v.check_shift, w.check_shift);
    v.negative_pivots_at_shift += w.negative_pivots_at_shift;
    v.modes_below_shift += w.modes_below_shift;
    v.eigenvalues_below_band += w.eigenvalues_below_band;
    v.complete = v.complete && w.complete;
    out.eigenvalues.insert(out.eigenvalues.end(), modes.eigenvalues.begin(), modes.eigenvalues.end());
    out.residuals.insert(out.residuals.end(), modes.residuals.begin(), modes.residuals.end());
    for (size_t k = 0; k < modes.x.size(); ++k) {
        // M is block diagonal (mass never couples harmonics), so x^T M x splits by block.
        std::vector<double> x(out.dofs.n_dofs, 0.0), mx(out.dofs.n_dofs, 0.0), energy(out.dofs.blocks.size(), 0.0);
        for (size_t b = 0; b < component.dofs.blocks.size(); ++b) {
            const CoupledBlock& block = component.dofs.blocks[b];
            const std::vector<int>& dof_in = component.dof_in[b];  // empty: the whole block from offset_in
            const double s = sign.empty() ? 1.0 : sign[b];
            double e = 0;
            for (int i = 0; i < block.dofs.n_dofs; ++i) {
                const int to = dof_in.empty() ? component.offset_in[b] + i : dof_in[i];
                x[to] = s * modes.x[k][block.offset + i];
                mx[to] = s * modes.Mx[k][block.offset + i];
                e += x[to] * mx[to];
            }
            energy[out.dofs.block_of(block.harmonic.n, block.harmonic.family)] = e;
        }
        std::array<double, 4> g{};
        for (int d = 0; d < 4; ++d)
            for (int i = 0; i < out.dofs.n_dofs; ++i) g[d] += rigid[d][i] * mx[i];
        out.block_energy.push_back(std::move(energy));
        out.gamma.push_back(g);
        out.vectors.push_back(std::move(x));
    }
}

}  // namespace

CoupledModes solve_coupled(const Scene& scene, const SectionMesh& section, const std::vector<PartMaterial>& materials,
                           int n_max, const SolveRequest& request) {
    return solve_coupled(scene, section, materials, n_max, request, attachments(scene));
}

CoupledModes solve_coupled(const Scene& scene, const SectionMesh& section, const std::vector<PartMaterial>& materials,
                           int n_max, const SolveRequest& request, const Attachments& attached,
                           const std::optional<LocalHarmonics>& local) {
    CoupledModes all;
    all.dofs = coupled_dofs(scene, section, n_max, local);
    all.verification.complete = true;
    all.verification.check_shift = 1e300;
    // Each independent problem for the modes asked of the whole: every one of
    // its eigenvalues below the merged band edge is among them (it cannot hold
    // more of the merged lowest than were asked).
    const std::vector<CoupledComponent> components = coupled_components(all.dofs, attached);
    const std::array<std::vector<double>, 4> rigid = mpi_rank() == 0 ? rigid_fields(section, all.dofs)
                                                                       : std::array<std::vector<double>, 4>{};
    std::vector<ComponentModes> solved(components.size());
    for (size_t c = 0; c < components.size(); ++c) {
        const CoupledComponent& component = components[c];
        if (component.partner_of >= 0) {
            // A congruent copy of an earlier set (S K S, S M S): its modes are S x, its counts the primary's.
            add_component(component, solved[component.partner_of], component.block_sign, rigid, all);
            continue;
        }
        solved[c] = solve_component(scene, section, materials, component, request, attached);
        add_component(component, solved[c], {}, rigid, all);
    }
    // Frequency order over the components.
    std::vector<size_t> order(all.eigenvalues.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return all.eigenvalues[a] < all.eigenvalues[b]; });
    CoupledModes out;
    out.dofs = all.dofs;
    out.mass_kg = all.mass_kg;
    out.n_coupling_entries = all.n_coupling_entries;
    out.verification = all.verification;
    out.n_components = static_cast<int>(components.size());
    for (size_t k : order) {
        out.eigenvalues.push_back(all.eigenvalues[k]);
        out.residuals.push_back(all.residuals[k]);
        if (mpi_rank() != 0) continue;
        out.vectors.push_back(std::move(all.vectors[k]));
        out.block_energy.push_back(std::move(all.block_energy[k]));
        out.gamma.push_back(all.gamma[k]);
    }
    return out;
}

double zone_edge_amplitude(const CoupledModes& modes, const SectionMesh& section, const LocalHarmonics& local,
                           size_t n_wanted) {
    // The edge's DOFs once (each block's zone depends on its n only), then every mode read on them.
    std::vector<int> edge_dofs;
    for (const CoupledBlock& block : modes.dofs.blocks) {
        if (block.harmonic.n <= local.n_full) continue;
        for (int node : zone_edge_nodes(section, local, block.harmonic.n))
            for (int c = 0; c < 3; ++c)
                if (const int d = block.dofs.of_component[3 * node + c]; d >= 0) edge_dofs.push_back(block.offset + d);
    }
    double worst = 0;
    for (size_t k = 0; k < n_wanted && k < modes.vectors.size(); ++k) {
        const std::vector<double>& x = modes.vectors[k];
        double largest = 0, edge = 0;
        for (double v : x) largest = std::max(largest, std::abs(v));
        for (int d : edge_dofs) edge = std::max(edge, std::abs(x[d]));
        worst = std::max(worst, edge / largest);
    }
    return worst;
}

std::vector<double> coupled_revolved_shape(const RevolvedMesh& revolved, const CoupledModes& modes, size_t k,
                                           const std::vector<int>& frame_nodes) {
    const std::vector<double>& x = modes.vectors.at(k);
    const CoupledDofs& dofs = modes.dofs;
    const auto value = [&](int b, int component) {
        if (b < 0) return 0.0;
        const CoupledBlock& block = dofs.blocks[b];
        const int d = block.dofs.of_component[component];
        return d < 0 ? 0.0 : x[block.offset + d];
    };
    // Every node's sum over n in one pass, cos(n theta) and sin(n theta) by
    // the angle-addition recurrence (revolved_field, block by block, took
    // four cosines and sines per node and block: most of the classify stage).
    std::vector<int> cos_block(dofs.n_max + 1), sin_block(dofs.n_max + 1);
    for (int n = 0; n <= dofs.n_max; ++n) {
        cos_block[n] = dofs.block_of(n, Family::cos);
        sin_block[n] = dofs.block_of(n, Family::sin);
    }
    std::vector<double> u(3 * static_cast<size_t>(revolved.mesh.n_nodes()), 0.0);
    for (size_t i = 0; i < revolved.section_node.size(); ++i) {
        const int s = revolved.section_node[i];
        const double c1 = std::cos(revolved.theta[i]), s1 = std::sin(revolved.theta[i]);
        // n = 0: the torsion V turns with -1 (revolved_field's sign).
        const int b0 = cos_block[0];
        double ur = value(b0, 3 * s), ut = -value(b0, 3 * s + 1), uz = value(b0, 3 * s + 2);
        double cn = 1, sn = 0;
        for (int n = 1; n <= dofs.n_max; ++n) {
            const double c = cn * c1 - sn * s1;
            sn = sn * c1 + cn * s1;
            cn = c;
            const int bc = cos_block[n], bs = sin_block[n];
            ur += value(bc, 3 * s) * cn + value(bs, 3 * s) * sn;
            ut += -value(bc, 3 * s + 1) * sn + value(bs, 3 * s + 1) * cn;
            uz += value(bc, 3 * s + 2) * cn + value(bs, 3 * s + 2) * sn;
        }
        u[3 * i] = ur * c1 - ut * s1;
        u[3 * i + 1] = ur * s1 + ut * c1;
        u[3 * i + 2] = uz;
    }
    // Frame masses: translations in n = 1 (x in cos, y in sin), axial in n = 0.
    for (size_t f = 0; f < frame_nodes.size(); ++f) {
        if (frame_nodes[f] < 0) continue;
        const size_t i = 3 * static_cast<size_t>(frame_nodes[f]);
        const auto frame_value = [&](int n, Family family) {
            const int b = dofs.block_of(n, family);
            if (b < 0 || dofs.blocks[b].dofs.frame[f] < 0) return 0.0;
            return x[dofs.blocks[b].offset + dofs.blocks[b].dofs.frame[f]];
        };
        u[i] = frame_value(1, Family::cos);
        u[i + 1] = frame_value(1, Family::sin);
        u[i + 2] = frame_value(0, Family::cos);
    }
    return u;
}

}  // namespace coremodal
