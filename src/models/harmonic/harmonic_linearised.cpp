// The harmonic level's eigenvalue change (models/linearised.hpp): the
// level's verified modes at p, each found again among the eigenpairs of its
// wave number n, and for the scenes at p(1 ± h) the difference of each n's
// assembled operators on the DOFs of the scene at p.
#include "models/harmonic/harmonic_level.hpp"
#include "models/linearised.hpp"

#include "assembly/harmonic_system.hpp"
#include "common/error.hpp"
#include "eigensolve/modal_solver.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "geometry/tube_section.hpp"
#include "models/part_materials.hpp"
#include "models/solve_steps.hpp"
#include "modes/verification_check.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace coremodal {
namespace {

// A distinct mode of the run and its eigenvalue partner in a level's solve
// agree to the solver's tolerance; this is far looser and far tighter than
// the gap between two distinct modes.
constexpr double kSameEigenvalue = 1e-6;

HarmonicSystem harmonic_system(const Scene& scene, int n) {
    const SectionMesh section = make_section_mesh(make_tube_section(scene), scene.supports.clamps);
    const std::vector<PartMaterial> materials = part_materials(scene, section.part_names, "generated section");
    return assemble_harmonic(scene, section, materials, n);
}

// One wave number's solve at p and the distinct modes that belong to it.
struct HarmonicBase {
    int n = 0;
    long n_dofs = 0;
    std::shared_ptr<SolvedModes> solved;
    std::vector<std::pair<size_t, size_t>> picks;  // (distinct mode, eigenpair of this n)
};

}  // namespace

Linearised HarmonicLevel::linearise(const Scene& scene) {
    const std::vector<Mode> modes = verified_modes(scene);
    Linearised lin;
    lin.modes = distinct_modes(modes);
    lin.eigenvalues = eigenvalues_of(lin.modes, modes);
    int n_max = 1;
    for (const DistinctMode& d : lin.modes) n_max = std::max(n_max, d.key.n);
    SolveRequest request = solve_request(scene);
    request.lambda_min.reset();
    request.lambda_max.reset();
    request.n_modes = static_cast<int>(modes.size());
    auto bases = std::make_shared<std::vector<HarmonicBase>>();
    std::vector<bool> matched(lin.modes.size(), false);
    for (int n = 0; n <= n_max + 1; ++n) {
        HarmonicSystem system = harmonic_system(scene, n);
        HarmonicBase h{n,
                       system.dofs.n_dofs,
                       std::make_shared<SolvedModes>(solve_modes(system.operators, request, [](const std::string&) {})),
                       {}};
        for (size_t i = 0; i < lin.modes.size(); ++i)
            for (size_t k = 0; k < h.solved->eigenvalues.size() && !matched[i]; ++k)
                if (std::abs(h.solved->eigenvalues[k] - lin.eigenvalues[i]) <= kSameEigenvalue * lin.eigenvalues[i]) {
                    h.picks.emplace_back(i, k);
                    matched[i] = true;
                }
        if (!h.picks.empty()) bases->push_back(std::move(h));
    }
    for (size_t i = 0; i < lin.modes.size(); ++i)
        if (!matched[i])
            throw SolveError("sensitivities: the mode " + lin.modes[i].key.text() +
                             " of the harmonic run was not "
                             "found again among the wave numbers 0 to " +
                             std::to_string(n_max + 1));
    const std::vector<double> lambdas = lin.eigenvalues;
    const size_t n_modes = lin.modes.size();
    lin.delta_lambda = [bases, lambdas, n_modes](const Scene& plus,
                                                 const Scene& minus) -> std::optional<std::vector<double>> {
        std::vector<double> out(n_modes, 0.0);
        for (const HarmonicBase& h : *bases) {
            const HarmonicSystem p = harmonic_system(plus, h.n), m = harmonic_system(minus, h.n);
            if (p.dofs.n_dofs != h.n_dofs || m.dofs.n_dofs != h.n_dofs) return std::nullopt;
            for (const auto& [i, k] : h.picks) {
                Vec x = h.solved->vectors[k];
                const double dK = quadratic_form(p.operators.K(), x) - quadratic_form(m.operators.K(), x);
                const double dM = quadratic_form(p.operators.M(), x) - quadratic_form(m.operators.M(), x);
                // x is M-normalised; (M₊ + M₋)/2 = M + O(h²) checks it without keeping M.
                const double xMx = 0.5 * (quadratic_form(p.operators.M(), x) + quadratic_form(m.operators.M(), x));
                out[i] = (dK - lambdas[i] * dM) / xMx;
            }
        }
        return out;
    };
    return lin;
}

// The level's modes of the scene, verified as a run's are (a mode whose
// residual, orthogonality or count fails ends the sensitivity run).
std::vector<Mode> HarmonicLevel::verified_modes(const Scene& scene) {
    LevelModes solved = solve(scene, Printer{false});
    require_verified("the modes of " + scene.name + " (harmonic level)",
                     verification_failures(solved.modes, solved.verification, scene.analysis.tolerance), false);
    return std::move(solved.modes);
}

}  // namespace coremodal
