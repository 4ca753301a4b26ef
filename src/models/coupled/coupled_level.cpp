// The coupled-harmonic level's steps 2–6, numbered as in a run: the
// section, then the coupled problem for growing N until it has converged,
// then the modes named on the revolved section.
#include "models/coupled/coupled_level.hpp"

#include "assembly/chuck_supports.hpp"
#include "common/error.hpp"
#include "common/blas_threads.hpp"
#include "common/format.hpp"
#include "common/stopwatch.hpp"
#include "eigensolve/tolerances.hpp"
#include "geometry/tube_model.hpp"
#include "models/choose.hpp"
#include "models/coupled/contact_static.hpp"
#include "models/harmonic/harmonic_level.hpp"
#include "models/harmonic/harmonic_shapes.hpp"
#include "models/part_materials.hpp"
#include "models/solve_steps.hpp"
#include "modes/classify.hpp"
#include "modes/mac.hpp"
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

}  // namespace

namespace {

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

namespace {

// The wanted eigenvalues: the lowest `modes` (with a pair's partner), or the band's.
std::vector<double> wanted(const CoupledModes& m, const Scene& scene, const SolveRequest& request) {
    std::vector<double> out;
    for (double lambda : m.eigenvalues) {
        if (request.lambda_max) {
            if (in_band(lambda, request)) out.push_back(lambda);
        } else if (static_cast<int>(out.size()) < scene.analysis.n_modes ||
                   std::abs(lambda - out.back()) <= kClusterTolerance * std::abs(out.back())) {
            out.push_back(lambda);  // a pair is never cut in half
        }
    }
    return out;
}

// Room above the last step's band edge: eigenvalues that the extra
// harmonics leave where they were (e.g. the axial mode) must stay inside.
constexpr double kEdgeMargin = 1e-6;

double frequency_hz(double lambda) { return std::sqrt(std::max(lambda, 0.0)) / (2 * M_PI); }

// The largest relative change of a wanted frequency between two truncations
// (infinite when their counts differ). Rigid modes (f ~ 0) are compared on
// the scale of the first elastic one.
double max_change(const std::vector<double>& a, const std::vector<double>& b, double lambda_scale) {
    if (a.size() != b.size()) return INFINITY;
    double change = 0;
    const double floor_hz = frequency_hz(lambda_scale);
    for (size_t i = 0; i < a.size(); ++i) {
        const double fa = frequency_hz(a[i]), fb = frequency_hz(b[i]);
        change = std::max(change, std::abs(fa - fb) / std::max(fb, floor_hz));
    }
    return change;
}

std::string convergence_text(const std::vector<CoupledStep>& steps) {
    std::string text;
    for (const CoupledStep& s : steps) {
        text += (text.empty() ? "" : "; ") + std::string("N=") + std::to_string(s.n_max) + ": " +
                std::to_string(s.n_dofs) + " DOFs, f1 " + significant(s.frequencies_hz.empty() ? 0.0 : s.frequencies_hz.front(), 7) +
                " Hz";
        if (&s != &steps.front()) text += ", max change " + significant(s.max_change, 2);
    }
    return text;
}

// What couples the harmonics, for the run's level line.
std::string coupling_text(const Attachments& attached) {
    std::string text;
    if (!attached.pads.empty())
        text = std::to_string(attached.pads.size()) + " segmented element(s) couple n to n +- j*" +
               std::to_string(attached.step());
    if (attached.web)
        text += std::string(text.empty() ? "" : "; ") + "the web's line at theta = " +
                significant(attached.web->theta * 180 / M_PI, 4) + " deg couples every n to every m";
    if (attached.one_sided)
        text += std::string(text.empty() ? "" : "; ") + "the one-sided contact's arc couples every n to every m";
    return text;
}

// A chuck not expanded: the static state under gravity with the harmonics
// n = 0 ... kContactStaticHarmonics (models/coupled/contact_static), and its
// closed points' linearised layer for the modes at every N.
ContactLayer linearised_contact_layer(const Scene& scene, const SectionMesh& section,
                                      const std::vector<PartMaterial>& materials, const Printer& say, LevelModes& out) {
    say("      static state under gravity (-y): one-sided contact by an active-set iteration, harmonics n = 0 ... " +
        std::to_string(kContactStaticHarmonics) + " (those even about the vertical)");
    CoupledContactState state = solve_coupled_contact(scene, section, materials, kContactStaticHarmonics, say);
    for (const std::string& line : contact_state_lines(state.contact, scene.roll_mass() * kStandardGravity)) {
        say("      " + line);
        out.assumptions.push_back(line);
    }
    return std::move(state.layer);
}

}  // namespace

LevelModes CoupledLevel::solve(const Scene& scene, const Printer& say) {
    Stopwatch stage;
    if (scene.mesh.file)
        throw InputError(scene.source_file + ": model = \"coupled\": a [mesh] file; the coupled level meshes the "
                                             "scene's own r-z section; expected model = \"solid\"");
    Attachments attached = attachments(scene);
    const int reach = attached.step();
    if (reach == 0) {
        // Nothing couples: the harmonics are independent, which the harmonic level solves one at a time.
        say("[2/7] no segmented expanding element and no web: nothing couples the harmonics; the harmonic level "
            "solves them");
        axisymmetric_ = std::make_unique<HarmonicLevel>();
        return axisymmetric_->solve(scene, say);
    }
    LevelModes out;

    // 2. Mesh: the r–z section (the harmonic level's) and its revolution, for showing the modes.
    // Why this level (the run's level line; `check` prints the same).
    const std::string why = why_coupled(scene).value_or("segmented expanding elements or the web");
    say("[2/7] coupled harmonics: " + why + "; " + coupling_text(attached));
    say("      meshing the r-z section");
    const SectionMesh section = make_section_mesh(make_tube_section(scene), scene.supports.clamps);
    revolved_ = revolve_section(section, std::min(scene.mesh.n_around, kMaxDisplayAround));
    add_frame_nodes(scene, revolved_->mesh);
    const std::vector<PartMaterial> materials = part_materials(scene, section.part_names, "generated section");
    if (attached.one_sided) attached.contact = linearised_contact_layer(scene, section, materials, say, out);
    out.timing.mesh = stage.lap();

    // 3-5. The coupled problem for N = N_s + 1, 2 N_s + 1, ...: solved, verified,
    // counted, until one more step moves no wanted frequency by kCoupledTolerance
    // and N reaches every wanted mode's dominant harmonic plus N_s.
    say("[3/7] " + std::to_string(section.n_cells()) + " quad8 cells, " + std::to_string(section.n_nodes()) +
        " nodes: n = 0 ... N coupled, stiffness and mass assembled per independent set");
    say(std::string("[4/7] solving one eigenproblem per independent set (SLEPc Krylov-Schur, shift-and-invert with ") +
        shift_invert_factor_package(PETSC_COMM_WORLD) + "; MUMPS LDL^T for the count)");
    const SolveRequest request = solve_request(scene);
    say(shift_scale_text(scene));
    steps_.clear();
    // The coupled sets' factors have small fronts (the section is 2D): OpenBLAS's
    // second thread costs more than it saves (case 10, 2026-11-26, load ~1:
    // 16.8 s wall and 16.4 s CPU on one thread, 19.9 s and 32.1 s on two).
    const SingleThreadBlas one_thread;
    std::optional<CoupledModes> previous, current;
    std::optional<LocalHarmonics> local = local_harmonics(attached, section);
    for (int n_max = reach + 1;; n_max += reach) {
        if (n_max > kMaxHarmonic)
            throw SolveError("the coupled harmonics have not converged to " + significant(kCoupledTolerance, 2) +
                             " by N = " + std::to_string(kMaxHarmonic) + " (" + convergence_text(steps_) +
                             "); ask for fewer modes or use model = \"solid\"");
        Stopwatch lap;
        // Adding harmonics only lowers eigenvalues (nested spaces), so every
        // wanted mode at this N lies below the last step's band edge: each
        // independent set is asked for its modes below that edge only (a band,
        // counted first), not for all the modes asked of the whole.
        SolveRequest step_request = request;
        if (previous && !request.lambda_max && !wanted(*previous, scene, request).empty()) {
            step_request.lambda_min = -request.lambda_scale;  // below any rigid mode
            step_request.lambda_max = wanted(*previous, scene, request).back() * (1 + kEdgeMargin);
        }
        current = solve_coupled(scene, section, materials, n_max, step_request, attached, local);
        out.timing.factor_and_solve += lap.seconds();
        CoupledStep step{n_max, current->dofs.n_dofs, {}, 0, lap.seconds()};
        const std::vector<double> w = wanted(*current, scene, request);
        for (double lambda : w) step.frequencies_hz.push_back(frequency_hz(lambda));
        int n_top = 0;
        if (mpi_rank() == 0)  // the vectors live on rank 0
            for (size_t k = 0; k < w.size(); ++k) n_top = std::max(n_top, current->dominant_n(k));
        MPI_Bcast(&n_top, 1, MPI_INT, 0, PETSC_COMM_WORLD);
        step.max_change = previous ? max_change(wanted(*previous, scene, request), w, request.lambda_scale) : 0;
        if (local && mpi_rank() == 0) step.zone_edge = zone_edge_amplitude(*current, section, *local, w.size());
        MPI_Bcast(&step.zone_edge, 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
        say("      N = " + std::to_string(n_max) + ": " + std::to_string(step.n_dofs) + " DOFs, " +
            std::to_string(w.size()) + " modes from " +
            significant(step.frequencies_hz.empty() ? 0.0 : step.frequencies_hz.front(), 7) + " Hz" +
            (previous ? ", largest change " + significant(step.max_change, 2) : std::string()) +
            (local ? ", zone edge " + significant(step.zone_edge, 2) : std::string()) + ", " +
            significant(step.seconds, 2) + " s" + (current->verification.complete ? "" : " (INCOMPLETE)"));
        steps_.push_back(step);
        const bool zone_enough = step.zone_edge <= kZoneEdgeTolerance;
        if (previous && step.max_change <= kCoupledTolerance && n_max >= n_top + reach && zone_enough) break;
        if (local) {
            // The spaces stay nested: the whole harmonics and the reach only grow.
            local->n_full = std::max(local->n_full, n_top);
            if (!zone_enough) local->reach_2 *= 2;
        }
        previous = std::move(current);
    }
    out.verification = current->verification;
    out.info.level = "coupled";
    out.info.element = "quad8";
    out.info.n_dofs = current->dofs.n_dofs;
    out.info.n_nodes = section.n_nodes();
    out.info.n_elements = section.n_cells();
    for (const auto& [name, nodes] : section.node_groups)
        if (name.rfind("clamp_", 0) == 0) out.info.n_eliminated_nodes += static_cast<long>(nodes.size());
    out.info.mass_kg = current->mass_kg;
    out.info.expected_mass_kg = scene.mass_from_dimensions();
    out.info.mesh_source = "generated section";
    out.info.harmonics = "coupled n = 0 ... " + std::to_string(current->dofs.n_max) + " (both families for n >= 1), " +
                         std::to_string(current->n_coupling_entries) + " coupling entries; " +
                         convergence_text(steps_);
    out.assumptions.push_back("model level coupled: " + why);
    out.assumptions.push_back(
        std::string("coupled harmonics: ") +
        (attached.pads.empty() ? "" : "each segmented element's spring layer acts on its pads only (k(theta) = k on "
                                      "the pads, 0 between), integrated exactly in theta; ") +
        (attached.web ? "the web's springs act on one line of the roll's surface, exactly at its angle; " : "") +
        (attached.one_sided ? "the one-sided contact's linearised layer acts at its closed points (" +
                                  std::to_string(kContactPointsAround) + " angles around x " +
                                  std::to_string(kContactGaussAlong) + " Gauss points along each edge); "
                            : "") +
        "harmonics n = 0 ... " + std::to_string(current->dofs.n_max) + ", N grown in steps of " +
        std::to_string(reach) + " until one step moved no wanted frequency by more than " +
        significant(kCoupledTolerance, 2) + " (last step: " + significant(steps_.back().max_change, 2) + ")");
    if (local)
        out.assumptions.push_back(
            "coupled harmonics: n = 0 ... " + std::to_string(local->n_full) + " on the whole section, n >= " +
            std::to_string(local->n_full + 1) + " only within " + significant(local->reach(2) * 1e3, 3) +
            " mm x 2/n of the pads along z (what the pads stir there dies out with distance; held beyond): the "
            "largest amplitude at that edge is " + significant(steps_.back().zone_edge, 2) + " of the mode's largest (at most " +
            significant(kZoneEdgeTolerance, 2) + ", else the reach doubles)");
    stage.lap();

    // 6. Name every mode on the revolved mesh with the solid's classifier; effective masses from the rigid fields.
    say("[5/7] classifying the modes");
    const bool root = mpi_rank() == 0;
    const std::vector<int> frame_nodes = frame_nodes_of(scene, revolved_->mesh);
    const ModeClassifier classifier(revolved_->mesh, roll_nodes(revolved_->mesh), body_held(scene));
    const std::optional<ModeSignatureSampler> signature =
        root ? std::optional<ModeSignatureSampler>(std::in_place, revolved_->mesh) : std::nullopt;
    const std::vector<double> w = wanted(*current, scene, request);
    for (size_t k = 0, kept = 0; k < current->eigenvalues.size() && kept < w.size(); ++k) {
        const double lambda = current->eigenvalues[k];
        if (!in_band(lambda, request)) continue;
        Mode mode = numbered_mode(static_cast<int>(++kept), lambda, current->residuals[k]);
        if (root) {
            const auto& g = current->gamma[k];
            mode.effective_mass.x = g[0] * g[0];
            mode.effective_mass.y = g[1] * g[1];
            mode.effective_mass.z = g[2] * g[2];
            mode.effective_mass.rz = g[3] * g[3];
            mode.shape = coupled_revolved_shape(*revolved_, *current, k, frame_nodes);
            mode.label = classifier.classify(mode.shape, lambda, request.lambda_scale);
            mode.signature = (*signature)(mode.shape);
        }
        out.modes.push_back(std::move(mode));
    }
    out.timing.classify = stage.lap();
    return out;
}

LevelShapes CoupledLevel::shapes() const {
    if (axisymmetric_) return axisymmetric_->shapes();
    return {&revolved_->mesh};
}

}  // namespace coremodal
