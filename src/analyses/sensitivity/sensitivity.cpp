// Eigenvalue sensitivities (sensitivity.hpp): the modes at p, then per
// parameter the operators at p(1 ± h) on the same DOFs, at the beam or the
// harmonic level.
#include "analyses/sensitivity/sensitivity.hpp"

#include "analyses/run/run.hpp"
#include "models/choose.hpp"
#include "models/part_materials.hpp"
#include "models/solve_steps.hpp"
#include "assembly/harmonic_system.hpp"
#include "beam/beam_model.hpp"
#include "common/error.hpp"
#include "common/petsc_handle.hpp"
#include "eigensolve/modal_solver.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "geometry/section_mesh.hpp"
#include "geometry/tube_section.hpp"
#include "scene/free_span.hpp"
#include "scene/materials_library.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

namespace coremodal {
namespace {

// A distinct mode of the run and its eigenvalue partner in a level's solve
// agree to the solver's tolerance; this is far looser and far tighter than
// the gap between two distinct modes.
constexpr double kSameEigenvalue = 1e-6;
// The free–free roll over the free span: its 6 rigid modes and the first bending pair.
constexpr int kFreeSpanModes = 8;

struct Linearised {
    std::vector<DistinctMode> modes;  // of the scene at p
    // Per distinct mode: dλ over the operators' difference (p₊ − p₋), or none when
    // the scenes at p(1 ± h) do not share the DOFs of the scene at p.
    std::function<std::optional<std::vector<double>>(const Scene& plus, const Scene& minus)> delta_lambda;
    std::vector<double> eigenvalues;  // per distinct mode
};

std::vector<double> eigenvalues_of(const std::vector<DistinctMode>& modes, const std::vector<Mode>& all) {
    std::vector<double> out;
    for (const DistinctMode& d : modes) out.push_back(all.at(d.index - 1).eigenvalue);
    return out;
}

// ---- beam level ------------------------------------------------------------

Linearised beam_linearised(const Scene& scene) {
    auto result = std::make_shared<BeamModelResult>(solve_beam_model(scene));
    auto base = std::make_shared<NetworkMatrices>(assemble_network(result->network));
    std::vector<Mode> all;
    for (size_t i = 0; i < result->modes.size(); ++i) {
        const BeamMode& b = result->modes[i];
        Mode mode;
        mode.index = static_cast<int>(i) + 1;
        mode.eigenvalue = b.eigenvalue;
        mode.frequency_hz = b.frequency_hz;
        mode.label = b.label;
        all.push_back(std::move(mode));
    }
    Linearised lin;
    lin.modes = distinct_modes(all);
    lin.eigenvalues = eigenvalues_of(lin.modes, all);
    const std::vector<DistinctMode> modes = lin.modes;
    const std::vector<double> lambdas = lin.eigenvalues;
    lin.delta_lambda = [result, base, modes, lambdas](const Scene& plus, const Scene& minus)
        -> std::optional<std::vector<double>> {
        const NetworkMatrices p = assemble_network(build_beam_network(plus, {}));
        const NetworkMatrices m = assemble_network(build_beam_network(minus, {}));
        if (p.free_dofs != base->free_dofs || m.free_dofs != base->free_dofs) return std::nullopt;
        const Eigen::SparseMatrix<double> dK = p.K - m.K, dM = p.M - m.M;
        std::vector<double> out;
        for (size_t i = 0; i < modes.size(); ++i) {
            const Eigen::VectorXd& shape = result->modes.at(modes[i].index - 1).shape;
            Eigen::VectorXd x(base->free_dofs.size());
            for (size_t r = 0; r < base->free_dofs.size(); ++r) x[r] = shape[base->free_dofs[r]];
            const double xMx = x.dot(base->M * x);
            out.push_back((x.dot(dK * x) - lambdas[i] * x.dot(dM * x)) / xMx);
        }
        return out;
    };
    return lin;
}

// ---- harmonic level ----------------------------------------------------------

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

Linearised harmonic_linearised(const Scene& scene) {
    require_axisymmetric(scene);
    RunOptions quiet;
    quiet.quiet = true;
    quiet.write_results = false;
    quiet.chuck_factor_by_fe = false;
    quiet.plots = false;
    const RunReport report = run_scene(scene, quiet);
    Linearised lin;
    lin.modes = distinct_modes(report.modes.modes);
    lin.eigenvalues = eigenvalues_of(lin.modes, report.modes.modes);
    int n_max = 1;
    for (const DistinctMode& d : lin.modes) n_max = std::max(n_max, d.key.n);
    SolveRequest request = solve_request(scene);
    request.lambda_min.reset();
    request.lambda_max.reset();
    request.n_modes = static_cast<int>(report.modes.modes.size());
    auto bases = std::make_shared<std::vector<HarmonicBase>>();
    std::vector<bool> matched(lin.modes.size(), false);
    for (int n = 0; n <= n_max + 1; ++n) {
        HarmonicSystem system = harmonic_system(scene, n);
        HarmonicBase h{n, system.dofs.n_dofs,
                       std::make_shared<SolvedModes>(solve_modes(system.operators, request, [](const std::string&) {})), {}};
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
            throw SolveError("sensitivities: the mode " + lin.modes[i].key.text() + " of the harmonic run was not "
                             "found again among the wave numbers 0 to " + std::to_string(n_max + 1));
    const std::vector<double> lambdas = lin.eigenvalues;
    const size_t n_modes = lin.modes.size();
    lin.delta_lambda = [bases, lambdas, n_modes](const Scene& plus, const Scene& minus)
        -> std::optional<std::vector<double>> {
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

}  // namespace

ModelChoice sensitivity_level(const Scene& scene) {
    const ModelChoice level = chosen_level(scene);
    if (!level_traits(level).sensitivities)
        throw InputError(scene.source_file + ": model = \"" + to_string(level) + "\": sensitivities are computed at the beam and "
                         "the harmonic level; expected model = \"harmonic\" (axisymmetric scenes) or \"beam\" "
                         "(--model)");
    return level;
}

namespace {

Linearised linearised(const Scene& scene) {
    // The levels' linearisations of this file; sensitivity_level refused the others.
    switch (sensitivity_level(scene)) {
        case ModelChoice::beam: return beam_linearised(scene);
        case ModelChoice::harmonic: return harmonic_linearised(scene);
        case ModelChoice::coupled:
        case ModelChoice::solid:
        case ModelChoice::automatic: break;
    }
    COREMODAL_ASSERT(false);
    return {};
}

// d ln f / d ln p of every distinct mode, for every parameter.
struct Derivatives {
    Linearised base;
    std::vector<std::vector<double>> dlnf;  // [mode][parameter]
    std::vector<std::string> methods;
};

double frequency_of(const std::vector<DistinctMode>& modes, const ModeKey& key) {
    for (const DistinctMode& d : modes)
        if (d.key == key) return d.frequency_hz;
    throw SolveError("sensitivities: the mode " + key.text() + " is missing at a perturbed parameter value (its "
                     "label changed); expected a smaller step");
}

template <typename SceneOf>
Derivatives derivatives(const CaseParameters& c, const std::vector<double>& values, double h, SceneOf scene_of) {
    Derivatives d;
    d.base = linearised(scene_of(c.scene(values)));
    d.dlnf.assign(d.base.modes.size(), std::vector<double>(values.size(), 0.0));
    for (size_t j = 0; j < values.size(); ++j) {
        std::vector<double> plus = values, minus = values;
        plus[j] *= 1 + h;
        minus[j] *= 1 - h;
        const Scene sp = scene_of(c.scene(plus)), sm = scene_of(c.scene(minus));
        const double dlnp = std::log(plus[j] / minus[j]);
        if (const auto dl = d.base.delta_lambda(sp, sm)) {
            d.methods.push_back("operators");
            for (size_t i = 0; i < d.base.modes.size(); ++i)
                d.dlnf[i][j] = (*dl)[i] / (2 * d.base.eigenvalues[i] * dlnp);
            continue;
        }
        d.methods.push_back("re-solved");
        const Linearised lp = linearised(sp), lm = linearised(sm);
        for (size_t i = 0; i < d.base.modes.size(); ++i)
            d.dlnf[i][j] = std::log(frequency_of(lp.modes, d.base.modes[i].key) /
                                    frequency_of(lm.modes, d.base.modes[i].key)) / dlnp;
    }
    return d;
}

std::vector<ModeSensitivity> mode_sensitivities(const Derivatives& d) {
    std::vector<ModeSensitivity> out;
    for (size_t i = 0; i < d.base.modes.size(); ++i)
        out.push_back({d.base.modes[i].key, d.base.modes[i].frequency_hz, d.dlnf[i]});
    return out;
}

const ModeSensitivity* first_bending(const std::vector<ModeSensitivity>& modes) {
    for (const ModeSensitivity& m : modes)
        if (m.key.type == "bending") return &m;
    return nullptr;
}

}  // namespace

std::vector<std::string> material_and_contact_keys(const Scene& scene) {
    std::vector<std::string> keys;
    const auto material = [&](const std::string& owner, const OrthotropicMaterial& m) {
        const auto& names = m.is_isotropic() ? isotropic_material_keys() : orthotropic_material_keys();
        for (std::string_view k : names) keys.push_back(owner + ".material." + std::string(k));
    };
    material("core", scene.core.material);
    if (scene.rest_paper) material("rest_paper", scene.rest_paper->material);
    if (scene.supports.kind == SupportKind::chucks) {
        const ChuckSpec& left = scene.supports.chucks.at(0);
        if (left.interface.kind == InterfaceKind::spring)
            for (const char* k : {"normal_stiffness", "tangential_stiffness"}) keys.push_back("supports.left." + std::string(k));
        for (const char* k : {"E", "density"}) keys.push_back("supports.left.material." + std::string(k));
    }
    return keys;
}

const ModeSensitivity* SensitivityResult::find(const ModeKey& key) const {
    for (const ModeSensitivity& m : modes)
        if (m.key == key) return &m;
    return nullptr;
}

SensitivityResult eigen_sensitivities(const CaseParameters& c, const std::vector<double>& values,
                                      const SensitivityOptions& options) {
    SensitivityResult r;
    r.parameters = c.parameters();
    r.values = values;
    const Scene scene = c.scene(values);
    r.level = to_string(sensitivity_level(scene));
    const auto same = [](Scene s) { return s; };
    const Derivatives d = derivatives(c, values, options.step, same);
    r.methods = d.methods;
    r.modes = mode_sensitivities(d);
    const ModeSensitivity* f1 = first_bending(r.modes);
    if (!options.chuck_factor || scene.supports.kind != SupportKind::chucks || !f1) return r;
    const Derivatives free = derivatives(c, values, options.step, [](const Scene& scene) {
        // Unlike the run's, the free roll keeps the scene's mesh counts: the
        // derivative differences operators on one fixed set of DOFs.
        return free_span_scene(scene, kFreeSpanModes);
    });
    const std::vector<ModeSensitivity> free_modes = mode_sensitivities(free);
    const ModeSensitivity* f2 = first_bending(free_modes);
    if (!f2) return r;
    r.f2 = *f2;
    r.k = f1->frequency_hz / f2->frequency_hz;
    for (size_t j = 0; j < values.size(); ++j) r.dlnk_dlnp.push_back(f1->dlnf_dlnp[j] - f2->dlnf_dlnp[j]);
    return r;
}

}  // namespace coremodal
