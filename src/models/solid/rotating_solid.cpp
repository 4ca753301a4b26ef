#include "models/solid/rotating_solid.hpp"
#include "models/spinning_model.hpp"

#include "assembly/chuck_supports.hpp"
#include "assembly/petsc_system.hpp"
#include "common/error.hpp"
#include "eigensolve/gyroscopic_solver.hpp"
#include "eigensolve/zero_frequency_speeds.hpp"
#include "models/choose.hpp"
#include "models/part_materials.hpp"
#include "models/solid/centrifugal_prestress.hpp"
#include "models/solid/rotating_frame.hpp"
#include "models/solid/solid_level.hpp"
#include "models/solve_steps.hpp"
#include "modes/mode_shapes.hpp"

#include <cmath>
#include <complex>
#include <set>

namespace coremodal {
namespace {

const Progress kQuiet = [](const std::string&) {};

// The scene's mesh, after the check that it can spin (header).
Mesh spinnable_mesh(const Scene& scene) {
    require_spinnable_by_solid(scene);
    return make_solid_mesh(scene);
}

SpinFrame chosen_frame(const Scene& scene, SpinFrame asked) {
    if (asked != SpinFrame::automatic) return asked;
    // The web does not spin: the stationary frame holds it as it is, when
    // everything that spins is a body of revolution.
    Scene spinning = scene;
    spinning.web.reset();
    return why_not_axisymmetric(spinning) ? SpinFrame::rotating : SpinFrame::stationary;
}

// Rotating frame: the rotating-frame modes solved per mode wanted, since
// the lowest in the stationary frame are not the lowest in the rotating
// one (an n-wave moves by n f_rot between the two).
constexpr int kRotatingFrameSolveFactor = 2;
// The largest circumferential harmonic read on the roll's surface.
constexpr int kMaxSurfaceHarmonic = 12;

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

// Two speeds of zero rotating-frame frequency closer than this share of the
// speed are one (the two members of a pair of a scene symmetric about z,
// equal to the pencil solver's tolerance; split pairs of an unsymmetric
// scene lie far further apart, and each is its own crossing).
constexpr double kSameZeroFrequencySpeed = 1e-6;

double squared_norm(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return s;
}

}  // namespace

void require_spinnable_by_solid(const Scene& scene) {
    if (const auto why = why_not_corotating(scene))
        throw InputError(scene.source_file + ": [rotation] at the solid level: " + *why +
                         " (docs/theory/rotation-solid.md); expected expanded chucks (contact = \"uniform\" or bonded)");
}

RotatingSolid::RotatingSolid(const Scene& scene, int window, SolidSpinOptions options)
    : scene_(scene), window_(window), mesh_(spinnable_mesh(scene)), frame_(chosen_frame(scene, options.frame)) {
    const ChuckSupports chucks = chuck_supports(scene, mesh_);
    if (frame_ == SpinFrame::rotating)
        if (const auto why = anisotropic_support(chucks))
            throw InputError(scene.source_file + ": [rotation] at the solid level: " + *why +
                             ", and the scene is not a body of revolution (" +
                             why_not_axisymmetric(scene).value_or("asked for the rotating frame") +
                             "): neither frame sees constant coefficients (docs/theory/rotation-solid.md)");
    LevelModes summary;  // the model summary and warnings a run at rest reports; not repeated here
    dofs_ = solid_dofs(scene, mesh_, chucks, summary);
    assemble(scene, chucks, options.centrifugal_stiffening);
    roll_nodes_ = roll_nodes(mesh_);
    classifier_ = std::make_unique<ModeClassifier>(mesh_, roll_nodes_, body_held(scene));
    signature_ = std::make_unique<ModeSignatureSampler>(mesh_);
    lambda_scale_ = solve_request(scene).lambda_scale;
    if (frame_ == SpinFrame::rotating) {
        surface_nodes_ = roll_surface_nodes(mesh_, roll_nodes_);
        std::set<long> angles;  // distinct angles around: the harmonics they resolve
        for (int n : surface_nodes_) angles.insert(std::lround(std::atan2(mesh_.nodes[n][1], mesh_.nodes[n][0]) * 1e6));
        max_wave_number_ = std::min<int>(kMaxSurfaceHarmonic, static_cast<int>(angles.size()) / 2 - 1);
    }
}

// Every cell spins (roll, chuck bodies and shafts); the couplings (spring
// layers, bearings, frames) carry no gyroscopic or centrifugal term in the
// stationary frame. In the rotating frame the Coriolis and spin-softening
// terms act on every mass (a change of coordinates), the prestress's
// stiffness on the cells only.
void RotatingSolid::assemble(const Scene& scene, const ChuckSupports& chucks, bool centrifugal_stiffening) {
    const std::vector<PartMaterial> materials =
        part_materials(scene, mesh_.part_names, scene.mesh.file ? *scene.mesh.file : "generated mesh");
    const bool stationary = frame_ == SpinFrame::stationary;
    operators_ = assemble_petsc(mesh_, materials, dofs_, chucks.couplings, PETSC_COMM_WORLD,
                                stationary ? std::vector<Term>{Term::gyroscopic} : std::vector<Term>{});
    if (centrifugal_stiffening) {
        const CentrifugalState state = solve_centrifugal_state(operators_, mesh_, materials, dofs_);
        add_centrifugal_term(operators_, mesh_, materials, dofs_, state,
                             stationary ? CentrifugalPart::stationary_frame : CentrifugalPart::stress_stiffness_only);
        pinned_ = state.pinned;
    }
    if (!stationary) add_rotating_frame_terms(operators_, dofs_);
}

RotatingMode RotatingSolid::named_mode(const std::vector<double>& re, const std::vector<double>& im, double omega,
                                       double speed_hz) const {
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
    request.n_modes = frame_ == SpinFrame::rotating ? kRotatingFrameSolveFactor * window_ : window_;
    const GyroscopicModes solved = solve_gyroscopic(operators_, 2 * M_PI * speed_hz, request, kQuiet);
    if (!solved.verification.complete)
        throw SolveError("the solid level's modes at " + std::to_string(speed_hz * 60) + " rpm are not proven complete");
    for (const GyroscopicMode& g : solved.modes) max_residual_ = std::max(max_residual_, g.relative_residual);
    std::vector<RotatingMode> out =
        frame_ == SpinFrame::rotating ? rotating_frame_modes(solved, speed_hz) : stationary_frame_modes(solved, speed_hz);
    if (static_cast<int>(out.size()) > window_) out.resize(window_);
    return out;
}

std::vector<RotatingMode> RotatingSolid::stationary_frame_modes(const GyroscopicModes& solved, double speed_hz) const {
    const double rigid_omega = gyroscopic_rigid_omega(solve_request(scene_));
    std::vector<RotatingMode> out;
    for (const GyroscopicMode& g : solved.modes) {
        RotatingMode m = named_mode(gather_node_displacements(g.real, mesh_, dofs_),
                                    gather_node_displacements(g.imag, mesh_, dofs_),
                                    g.omega < rigid_omega ? 0.0 : g.omega, speed_hz);
        m.relative_residual = g.relative_residual;
        out.push_back(std::move(m));
    }
    return out;
}

// Each rotating-frame mode x e^{i omega t} with dominant harmonic k on the
// roll's surface is, seen from the stationary frame, x at omega - k Omega
// (a negative one is the conjugate mode at its absolute value): f_stat =
// |f - k f_rot|, forward when -k (f - k f_rot) > 0 (header). Only the modes
// below the highest solved frequency less the largest |k| f_rot are kept:
// those the rotating-frame solve is complete for.
std::vector<RotatingMode> RotatingSolid::rotating_frame_modes(const GyroscopicModes& solved, double speed_hz) const {
    const double rigid_hz = gyroscopic_rigid_omega(solve_request(scene_)) / (2 * M_PI);
    struct Converted {
        RotatingMode mode;
        double share;
    };
    std::vector<Converted> out;
    double highest_hz = 0;
    int largest_n = 0;
    for (const GyroscopicMode& g : solved.modes) {
        std::vector<double> re = gather_node_displacements(g.real, mesh_, dofs_);
        std::vector<double> im = gather_node_displacements(g.imag, mesh_, dofs_);
        const double f = g.omega / (2 * M_PI);
        highest_hz = std::max(highest_hz, f);
        const WaveContent wave = dominant_harmonic(re, im, mesh_, surface_nodes_, max_wave_number_);
        largest_n = std::max(largest_n, std::abs(wave.k));
        const double f_signed = f - wave.k * speed_hz;
        if (f_signed < 0)
            for (double& v : im) v = -v;  // the conjugate mode
        const double f_stat = std::abs(f_signed) < rigid_hz ? 0.0 : std::abs(f_signed);
        RotatingMode m = named_mode(re, im, 2 * M_PI * f_stat, speed_hz);
        m.relative_residual = g.relative_residual;
        if (speed_hz > 0 && wave.k != 0 && m.label.type != "rigid" && f_stat > 0)
            m.whirl = -wave.k * f_signed > 0 ? Whirl::forward : Whirl::backward;
        else
            m.whirl = Whirl::none;
        out.push_back({std::move(m), wave.share});
    }
    const double complete_below = highest_hz - largest_n * speed_hz;
    std::erase_if(out, [&](const Converted& c) { return c.mode.frequency_hz > complete_below; });
    std::sort(out.begin(), out.end(),
              [](const Converted& a, const Converted& b) { return a.mode.frequency_hz < b.mode.frequency_hz; });
    if (static_cast<int>(out.size()) > window_) out.resize(window_);
    std::vector<RotatingMode> modes;
    for (Converted& c : out) {
        // At rest a pair's modes stand (both directions, half each): no conversion to judge.
        if (speed_hz > 0) min_share_ = std::min(min_share_, c.share);
        modes.push_back(std::move(c.mode));
    }
    return modes;
}

// One eigenvector of the pencil (K, B_r) (eigensolve/zero_frequency_speeds.hpp),
// named on the mesh. r = 0: the null vector is real (K(Omega) is), so its
// harmonics k and -k carry equal energy and only |k| is read: the mode
// stands still in the rotating frame, and seen from the stationary one it
// moves at 0 - k f_rot, forward for either sign (rotating_frame_modes:
// -k (0 - k f_rot) = k^2 f_rot > 0), at |k| f_rot. r > 0: x = a + i b is a
// mode at +r f_rot, its signed k read from the complex field, seen at
// (r - k) f_rot (a negative one is the conjugate mode, as in
// rotating_frame_modes).
ZeroFrequencyMode RotatingSolid::pencil_mode(const ZeroFrequencySpeed& z, int ratio) const {
    const std::vector<double> re = gather_node_displacements(z.x, mesh_, dofs_);
    const std::vector<double> im = ratio == 0 ? std::vector<double>(re.size(), 0.0)
                                              : gather_node_displacements(z.y, mesh_, dofs_);
    const WaveContent wave = dominant_harmonic(re, im, mesh_, surface_nodes_, max_wave_number_);
    ZeroFrequencyMode m;
    m.speed_hz = z.spin / (2 * M_PI);
    m.wave_number = std::abs(wave.k);
    m.harmonic = ratio == 0 ? m.wave_number : wave.k;
    m.order = std::abs(ratio - m.harmonic);
    m.share = ratio == 0 && wave.k != 0 ? std::min(1.0, 2 * wave.share) : wave.share;
    if (m.harmonic != 0 && m.order != 0)
        m.whirl = -m.harmonic * (ratio - m.harmonic) > 0 ? Whirl::forward : Whirl::backward;
    const double omega_stat = 2 * M_PI * m.order * m.speed_hz;
    m.label = classifier_->classify(squared_norm(re) >= squared_norm(im) ? re : im, omega_stat * omega_stat,
                                    lambda_scale_);
    m.relative_residual = z.relative_residual;
    return m;
}

ZeroFrequencyModes RotatingSolid::zero_frequency_modes(double max_speed_hz) const {
    return frequency_ratio_modes(max_speed_hz, 0);
}

// Eigenvalues closer than kSameZeroFrequencySpeed are one mode counted
// `multiplicity` times; the real form's two copies of each (x and i x, r > 0)
// are one complex vector, so a group's size is divided by the copies.
ZeroFrequencyModes RotatingSolid::frequency_ratio_modes(double max_speed_hz, int ratio) const {
    COREMODAL_ASSERT(frame_ == SpinFrame::rotating && ratio >= 0);
    const SolveRequest request = solve_request(scene_);
    const ZeroFrequencySpeeds pencil = frequency_ratio_speeds(operators_, ratio, 2 * M_PI * max_speed_hz,
                                                              gyroscopic_rigid_omega(request), request);
    ZeroFrequencyModes out;
    out.counted = pencil.counted / pencil.copies;
    out.max_speed_hz = max_speed_hz;
    out.ratio = ratio;
    std::vector<int> group_size;
    for (const ZeroFrequencySpeed& z : pencil.speeds) {
        const double speed_hz = z.spin / (2 * M_PI);
        if (!out.modes.empty() && speed_hz - out.modes.back().speed_hz <= kSameZeroFrequencySpeed * speed_hz) {
            ++group_size.back();
            out.modes.back().relative_residual = std::max(out.modes.back().relative_residual, z.relative_residual);
            continue;
        }
        out.modes.push_back(pencil_mode(z, ratio));
        group_size.push_back(1);
    }
    for (size_t i = 0; i < out.modes.size(); ++i) {
        if (group_size[i] % pencil.copies != 0)
            throw SolveError("the real form of the pencil (K, B_r), r = " + std::to_string(ratio) + ", has " +
                             std::to_string(group_size[i]) + " vectors at " +
                             std::to_string(out.modes[i].speed_hz * 60) + " rpm, not a multiple of 2 (x and i x): "
                             "raise [analysis] max_iterations");
        out.modes[i].multiplicity = group_size[i] / pencil.copies;
    }
    return out;
}

}  // namespace coremodal
