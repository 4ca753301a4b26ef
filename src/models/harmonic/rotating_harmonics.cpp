#include "models/harmonic/rotating_harmonics.hpp"

#include "assembly/chuck_supports.hpp"
#include "common/error.hpp"
#include "common/log_event.hpp"
#include "eigensolve/gyroscopic_solver.hpp"
#include "eigensolve/projected_gyroscopic.hpp"
#include "geometry/tube_section.hpp"
#include "models/harmonic/harmonic_search.hpp"
#include "models/harmonic/harmonic_shapes.hpp"
#include "models/part_materials.hpp"
#include "models/solve_steps.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace coremodal {
namespace {

// Modes solved per wave number beyond those it has among the window at rest:
// a backward wave coming down with speed, or a pair's second member.
constexpr int kExtraModesPerHarmonic = 2;
// The modes at rest in each n's projection basis (projected_gyroscopic.hpp):
// this many times the modes solved per speed, plus a few, so that the modes
// at speed, mixtures of the ones at rest nearby, are carried by the basis.
constexpr int kRestBasisFactor = 2;
constexpr int kExtraRestModes = 4;

const Progress kQuiet = [](const std::string&) {};

// The window-th lowest eigenvalue of the modes at rest found so far, or none.
std::optional<double> window_edge(std::vector<double> lambdas, int window) {
    if (static_cast<int>(lambdas.size()) < window) return std::nullopt;
    std::nth_element(lambdas.begin(), lambdas.begin() + (window - 1), lambdas.end());
    return lambdas[window - 1];
}

// The eigenvalues at rest of wave number n (each pair's twice for n >= 1)
// up to the window, or none when n has no mode below the edge.
std::vector<double> rest_eigenvalues(const Scene& scene, HarmonicSystem& system, SolveRequest request,
                                     std::optional<double> edge, int window) {
    request.n_modes = system.n == 0 ? window : (window + 1) / 2;
    if (edge) {
        request.n_modes = static_cast<int>(count_eigenvalues_below(system.operators, *edge * (1 + 1e-9)));
        if (request.n_modes == 0) return {};
    }
    const SolvedModes m =
        solve_for_case(scene, system.operators, request, kQuiet, "the problem of wave number n = " + std::to_string(system.n) + ": ");
    std::vector<double> out;
    for (double lambda : m.eigenvalues)
        for (int k = 0; k < (system.n == 0 ? 1 : 2); ++k) out.push_back(lambda);
    return out;
}

// Forward (+1) to backward (-1): 2 Im(a . conj b) / (|a|^2 + |b|^2) of the
// two families' complex amplitudes (spinning_harmonic.hpp).
double circularity(const FamilyValues& re, const FamilyValues& im) {
    double cross = 0, norm = 0;
    for (size_t k = 0; k < re.cos_values.size(); ++k) {
        const std::complex<double> a(re.cos_values[k], im.cos_values[k]), b(re.sin_values[k], im.sin_values[k]);
        cross += (a * std::conj(b)).imag();
        norm += std::norm(a) + std::norm(b);
    }
    return norm > 0 ? 2 * cross / norm : 0.0;
}

Eigen::VectorXcd complex_shape(const FamilyValues& re, const FamilyValues& im) {
    const size_t n = re.cos_values.size(), m = re.sin_values.size();
    Eigen::VectorXcd x(n + m);
    for (size_t k = 0; k < n; ++k) x[k] = {re.cos_values[k], im.cos_values[k]};
    for (size_t k = 0; k < m; ++k) x[n + k] = {re.sin_values[k], im.sin_values[k]};
    return x;
}

double squared_norm(const FamilyValues& v) {
    double s = 0;
    for (double x : v.cos_values) s += x * x;
    for (double x : v.sin_values) s += x * x;
    return s;
}

}  // namespace

struct RotatingHarmonics::Harmonic {
    SpinningHarmonic problem;
    int n_modes = 0;  // solved at every speed (both members of a pair counted)
    // The scale the solver's target and rigid line take (SolveRequest): the
    // scene's for n <= 1, which hold its rigid modes; for n >= 2 this
    // harmonic's own lowest eigenvalue at rest, so that the target sits
    // next to its modes (a ring harmonic's lie far above the scene's first).
    double lambda_scale = 1;
    std::unique_ptr<ProjectedGyroscopic> projected;  // SpinSolver::projected
    int n_rest = 0;                                  // the modes at rest in the projection basis
    SolveRequest request;                            // n_modes and lambda_scale as solved
    OperatorSet damping;                             // include_damping: the set with its damping terms
    std::unique_ptr<ProjectedDamped> damped;         // include_damping
};

RotatingHarmonics::~RotatingHarmonics() = default;

RotatingHarmonics::RotatingHarmonics(const Scene& scene, int window, bool centrifugal_stiffening, SpinSolver solver)
    : scene_(scene),
      window_(window),
      section_(make_section_mesh(make_tube_section(scene), scene.supports.clamps)),
      revolved_(revolve_section(section_, std::min(scene.mesh.n_around, kMaxDisplayAround))) {
    add_frame_nodes(scene, revolved_.mesh);
    frame_nodes_ = frame_nodes_of(scene, revolved_.mesh);
    classifier_ = std::make_unique<ModeClassifier>(revolved_.mesh, roll_nodes(revolved_.mesh), body_held(scene));
    const std::vector<PartMaterial> materials = part_materials(scene, section_.part_names, "generated section");
    const SolveRequest request = solve_request(scene);
    lambda_scale_ = request.lambda_scale;

    // The search at rest, as the harmonic level's (models/harmonic/harmonic_search.hpp).
    std::vector<std::vector<double>> rest;  // per n
    std::vector<double> rest_lowest;        // per n: its lowest eigenvalue at rest
    std::vector<double> merged;
    const auto visit = [&](int n) -> HarmonicVisit {
        const LogEvent event("CmRestSearch");
        HarmonicSystem system = assemble_harmonic(scene, section_, materials, n);
        const std::optional<double> edge = n >= 2 ? window_edge(merged, window) : std::nullopt;
        const std::vector<double> lambdas = rest_eigenvalues(scene, system, request, edge, window);
        rest.push_back(lambdas);
        rest_lowest.push_back(lambdas.empty() ? lowest_eigenvalue(system.operators, request) : lambdas.front());
        merged.insert(merged.end(), lambdas.begin(), lambdas.end());
        return {!lambdas.empty(), rest_lowest.back()};
    };
    walk_harmonics(visit, [&] {
        return "every wave number up to n = " + std::to_string(kMaxHarmonic) + " has modes among the lowest " +
               std::to_string(window) + ": ask for fewer modes";
    });
    const double edge = window_edge(merged, window).value_or(1e300);
    if (centrifugal_stiffening) {
        const LogEvent event("CmPrestress");
        prestress_ = std::make_unique<CentrifugalPrestress>(centrifugal_prestress(scene, section_, materials));
    }
    for (size_t n = 0; n < rest.size(); ++n) {
        auto h = std::make_unique<Harmonic>();
        {
            const LogEvent event("CmSpinAssembly");
            h->problem = assemble_spinning_harmonic(scene, section_, materials, static_cast<int>(n), prestress_.get());
        }
        const long in_window = std::count_if(rest[n].begin(), rest[n].end(), [&](double l) { return l <= edge * (1 + 1e-9); });
        h->n_modes = static_cast<int>(in_window) + kExtraModesPerHarmonic;
        h->lambda_scale = n <= 1 ? request.lambda_scale : rest_lowest[n];
        h->request = request;
        h->request.n_modes = h->n_modes;
        h->request.lambda_scale = h->lambda_scale;
        h->n_rest = kRestBasisFactor * h->n_modes + kExtraRestModes;
        if (solver == SpinSolver::projected) {
            const SolveRequest& r = h->request;
            h->projected = std::make_unique<ProjectedGyroscopic>(h->problem.operators, r, h->n_rest,
                                                                 n == 0 ? h->problem.meridional_rows : h->problem.cos_rows,
                                                                 n == 0 ? h->problem.tangential_rows : h->problem.sin_rows);
        }
        harmonics_.push_back(std::move(h));
    }
}

// The label of the larger real snapshot of x = re + i im, on the revolved section.
ModeLabel RotatingHarmonics::label(const SpinningHarmonic& h, const FamilyValues& re, const FamilyValues& im,
                                   double omega) const {
    const LogEvent event("CmLabel");
    const FamilyValues& snapshot = squared_norm(re) >= squared_norm(im) ? re : im;
    const std::vector<double> field =
        revolved_field(revolved_, h.dofs, h.n, snapshot.cos_values, snapshot.sin_values, frame_nodes_);
    return classifier_->classify(field, omega * omega, lambda_scale_);
}

ModeLabel RotatingHarmonics::label_of(const RotatingMode& mode) const {
    for (const auto& h : harmonics_) {
        if (h->problem.n != mode.block) continue;
        const size_t n_cos = h->problem.dofs.n_dofs;
        FamilyValues re, im;
        for (Eigen::Index k = 0; k < mode.shape.size(); ++k) {
            (size_t(k) < n_cos ? re.cos_values : re.sin_values).push_back(mode.shape[k].real());
            (size_t(k) < n_cos ? im.cos_values : im.sin_values).push_back(mode.shape[k].imag());
        }
        return label(h->problem, re, im, 2 * M_PI * mode.frequency_hz);
    }
    COREMODAL_ASSERT(!"a mode of a wave number this level solves");
    return {};
}

std::vector<RotatingMode> RotatingHarmonics::modes_at(double speed_hz, Labels labels, int only_block) const {
    const double spin = 2 * M_PI * speed_hz;
    SolveRequest request = solve_request(scene_);
    std::vector<RotatingMode> out;
    for (const auto& h : harmonics_) {
        if (only_block >= 0 && h->problem.n != only_block) continue;
        request.n_modes = h->n_modes;
        request.lambda_scale = h->lambda_scale;
        std::optional<GyroscopicModes> projected;
        if (h->projected) projected = h->projected->modes_at(spin);
        ++n_solves_;
        if (!projected) ++n_full_solves_;
        const GyroscopicModes solved =
            projected ? std::move(*projected) : solve_gyroscopic(h->problem.operators, spin, request, kQuiet);
        if (!solved.verification.complete)
            throw SolveError("the modes of wave number n = " + std::to_string(h->problem.n) + " at " +
                             std::to_string(speed_hz * 60) + " rpm are not proven complete");
        const double rigid_omega = gyroscopic_rigid_omega(request);
        for (const GyroscopicMode& g : solved.modes) {
            const double omega = g.omega < rigid_omega ? 0.0 : g.omega;  // rigid: at 0 Hz
            const FamilyValues re = family_values(h->problem, g.real), im = family_values(h->problem, g.imag);
            RotatingMode m;
            m.block = h->problem.n;
            m.frequency_hz = omega / (2 * M_PI);
            m.relative_residual = g.relative_residual;
            max_residual_ = std::max(max_residual_, g.relative_residual);
            m.shape = complex_shape(re, im);
            if (h->problem.n > 0) m.circularity = circularity(re, im);
            // At rest the two travelling waves are one frequency and the
            // solver returns any mix of them: standing, no whirl.
            if (speed_hz > 0 && std::abs(m.circularity) >= kPlanarCircularity)
                m.whirl = m.circularity > 0 ? Whirl::forward : Whirl::backward;
            if (labels == Labels::every_mode) m.label = label(h->problem, re, im, omega);
            out.push_back(std::move(m));
        }
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const RotatingMode& a, const RotatingMode& b) { return a.frequency_hz < b.frequency_hz; });
    if (only_block < 0 && static_cast<int>(out.size()) > window_) out.resize(window_);
    return out;
}

void RotatingHarmonics::include_damping(const OperatorDamping& damping) {
    const std::vector<PartMaterial> materials = part_materials(scene_, section_.part_names, "generated section");
    for (auto& h : harmonics_) {
        const LogEvent event("CmDampedBasis");
        h->damping = damped_harmonic_terms(h->problem, section_, materials, damping);
        h->damped = std::make_unique<ProjectedDamped>(h->damping, h->request, h->n_rest);
    }
}

std::vector<RotatingHarmonics::DampedShape> RotatingHarmonics::damped_modes_at(double speed_hz, int n) const {
    std::vector<DampedShape> out;
    for (const auto& h : harmonics_) {
        if (h->problem.n != n) continue;
        COREMODAL_ASSERT(h->damped);
        for (DampedMode& m : h->damped->modes_at(2 * M_PI * speed_hz).modes) {
            Eigen::VectorXcd shape = h->damped->full_shape(m);
            out.push_back({std::move(m), std::move(shape)});
        }
    }
    return out;
}

void RotatingHarmonics::sweep_up_to(double speed_hz) {
    for (auto& h : harmonics_)
        if (h->projected) h->projected->prove_rigid_line_clear(2 * M_PI * speed_hz);
}

ProjectedGyroscopic::CountStatistics RotatingHarmonics::count_statistics() const {
    ProjectedGyroscopic::CountStatistics all;
    for (const auto& h : harmonics_) {
        if (!h->projected) continue;
        const ProjectedGyroscopic::CountStatistics s = h->projected->count_statistics();
        all.speeds += s.speeds;
        all.counted += s.counted;
        all.certificates += s.certificates;
        all.certificate_failed += s.certificate_failed;
        all.certified += s.certified;
        all.gamma = std::max(all.gamma, s.gamma);
    }
    return all;
}

long RotatingHarmonics::n_dofs() const {
    long most = 0;
    for (const auto& h : harmonics_) most = std::max<long>(most, h->problem.n_families() * long(h->problem.dofs.n_dofs));
    return most;
}

std::vector<int> RotatingHarmonics::wave_numbers() const {
    std::vector<int> n;
    for (const auto& h : harmonics_) n.push_back(h->problem.n);
    return n;
}

}  // namespace coremodal
