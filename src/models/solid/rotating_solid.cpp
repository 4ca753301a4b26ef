#include "models/solid/rotating_solid.hpp"

#include "assembly/chuck_supports.hpp"
#include "assembly/petsc_system.hpp"
#include "common/error.hpp"
#include "eigensolve/gyroscopic_solver.hpp"
#include "models/choose.hpp"
#include "models/part_materials.hpp"
#include "models/solid/centrifugal_prestress.hpp"
#include "models/solid/solid_level.hpp"
#include "models/solve_steps.hpp"
#include "modes/mode_shapes.hpp"

#include <cmath>
#include <complex>

namespace coremodal {
namespace {

const Progress kQuiet = [](const std::string&) {};

// The scene's mesh, after the check that it is a body of revolution (header).
Mesh spinnable_mesh(const Scene& scene) {
    require_spinnable_by_solid(scene);
    return make_solid_mesh(scene);
}

// Forward (+1) to backward (-1): 2 sum Im(ux conj uy) / sum (|ux|^2 + |uy|^2)
// over `nodes` of the complex node displacements re + i im (n_nodes x 3).
double circularity(const std::vector<double>& re, const std::vector<double>& im, const std::vector<int>& nodes) {
    double cross = 0, norm = 0;
    for (int n : nodes) {
        const std::complex<double> ux(re[3 * n], im[3 * n]), uy(re[3 * n + 1], im[3 * n + 1]);
        cross += (ux * std::conj(uy)).imag();
        norm += std::norm(ux) + std::norm(uy);
    }
    return norm > 0 ? 2 * cross / norm : 0.0;
}

double squared_norm(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return s;
}

}  // namespace

void require_spinnable_by_solid(const Scene& scene) {
    if (const auto why = why_not_axisymmetric(scene))
        throw InputError(scene.source_file + ": [rotation] at the solid level: " + *why +
                         "; the solid level's gyroscopic term is the stationary frame's, right for a body of "
                         "revolution only (docs/rotation.md); expected full bands, no [mesh] file and expanded chucks");
}

RotatingSolid::RotatingSolid(const Scene& scene, int window, SolidSpinOptions options)
    : scene_(scene), window_(window), mesh_(spinnable_mesh(scene)) {
    const ChuckSupports chucks = chuck_supports(scene, mesh_);
    LevelModes summary;  // the model summary and warnings a run at rest reports; not repeated here
    dofs_ = solid_dofs(scene, mesh_, chucks, summary);
    // Every cell spins (roll, chuck bodies and shafts); the couplings
    // (spring layers, bearings, frames) carry no gyroscopic term.
    const std::vector<PartMaterial> materials = part_materials(scene, mesh_.part_names, "generated mesh");
    operators_ = assemble_petsc(mesh_, materials, dofs_, chucks.couplings, PETSC_COMM_WORLD, {Term::gyroscopic});
    if (options.centrifugal_stiffening) {
        const CentrifugalState state = solve_centrifugal_state(operators_, mesh_, materials, dofs_);
        add_centrifugal_term(operators_, mesh_, materials, dofs_, state, CentrifugalPart::stationary_frame);
        pinned_ = state.pinned;
    }
    roll_nodes_ = roll_nodes(mesh_);
    classifier_ = std::make_unique<ModeClassifier>(mesh_, roll_nodes_);
    signature_ = std::make_unique<ModeSignatureSampler>(mesh_);
    lambda_scale_ = solve_request(scene).lambda_scale;
}

RotatingMode RotatingSolid::named_mode(Vec real, Vec imag, double omega, double speed_hz) const {
    const std::vector<double> re = gather_node_displacements(real, mesh_, dofs_);
    const std::vector<double> im = gather_node_displacements(imag, mesh_, dofs_);
    RotatingMode m;
    m.frequency_hz = omega / (2 * M_PI);
    // The label of its largest real snapshot, as the solid run names modes.
    m.label = classifier_->classify(squared_norm(re) >= squared_norm(im) ? re : im, omega * omega, lambda_scale_);
    m.circularity = circularity(re, im, roll_nodes_);
    // At rest a pair's two members are one frequency and the solver returns
    // any mix of them: standing, no whirl; n = 0 and rigid modes have none.
    const bool can_whirl = m.label.type != "rigid" && m.label.n >= 1;
    if (speed_hz > 0 && can_whirl && std::abs(m.circularity) >= kPlanarCircularity)
        m.whirl = m.circularity > 0 ? Whirl::forward : Whirl::backward;
    const Signature sr = (*signature_)(re), si = (*signature_)(im);  // linear in the field
    m.shape.resize(static_cast<Eigen::Index>(sr.size()));
    for (size_t k = 0; k < sr.size(); ++k) m.shape[static_cast<Eigen::Index>(k)] = {sr[k], si[k]};
    return m;
}

std::vector<RotatingMode> RotatingSolid::modes_at(double speed_hz) const {
    SolveRequest request = solve_request(scene_);
    request.n_modes = window_;
    const GyroscopicModes solved = solve_gyroscopic(operators_, 2 * M_PI * speed_hz, request, kQuiet);
    if (!solved.verification.complete)
        throw SolveError("the solid level's modes at " + std::to_string(speed_hz * 60) + " rpm are not proven complete");
    const double rigid_omega = gyroscopic_rigid_omega(request);
    std::vector<RotatingMode> out;
    for (const GyroscopicMode& g : solved.modes) {
        RotatingMode m = named_mode(g.real, g.imag, g.omega < rigid_omega ? 0.0 : g.omega, speed_hz);
        m.relative_residual = g.relative_residual;
        max_residual_ = std::max(max_residual_, g.relative_residual);
        out.push_back(std::move(m));
    }
    if (static_cast<int>(out.size()) > window_) out.resize(window_);
    return out;
}

}  // namespace coremodal
