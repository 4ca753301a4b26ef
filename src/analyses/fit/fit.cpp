// Levenberg–Marquardt in ln p with exact eigenvalue sensitivities (fit.hpp).
#include "analyses/fit/fit.hpp"

#include "analyses/sensitivity/sensitivity.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "scene/toml_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace coremodal {
namespace {

// Without bounds a parameter may move a factor 10 either way: material
// constants of paperboard and contact stiffnesses are known to about a factor
// 3 (docs/reference/material-sources.md), so the truth lies inside and a runaway
// parameter is stopped where it stops being physical.
constexpr double kDefaultBoundFactor = 10;
constexpr int kMaxIterations = 40;
// Converged when no ln p moves by more than this in an accepted step (1e-6
// relative in p: far below any measurement's uncertainty).
constexpr double kStepTolerance = 1e-6;
constexpr double kInitialDamping = 1e-3, kMaxDamping = 1e12;

// The measurements of one case file solved at one level, and the fit
// parameters that enter it.
struct CaseGroup {
    std::string case_file, model;
    std::vector<size_t> measurements;
    std::vector<size_t> parameters;  // fit parameter of each of the case's keys
    std::optional<CaseParameters> keys;
};

struct Evaluation {
    std::vector<double> f_hz;              // per measurement
    std::vector<std::vector<double>> dlnf; // [measurement][fit parameter]
    std::vector<ModelChoice> level;        // per measurement
};

std::string location(const FitInput& in, const toml::source_region& where) {
    return in.path + ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column) + ": ";
}

std::vector<CaseGroup> group_cases(const FitInput& in) {
    std::vector<CaseGroup> groups;
    for (size_t i = 0; i < in.measurements.size(); ++i) {
        const Measurement& m = in.measurements[i];
        auto it = std::find_if(groups.begin(), groups.end(),
                               [&](const CaseGroup& g) { return g.case_file == m.case_file && g.model == m.model; });
        if (it == groups.end()) it = groups.insert(groups.end(), CaseGroup{m.case_file, m.model, {}, {}, {}});
        it->measurements.push_back(i);
    }
    return groups;
}

// Which keys each case has (a chuck's contact stiffness is not a key of the
// free ISO test); every key must belong to one case at least. Fills the
// parameters' start values and bounds.
std::vector<FitParameter> resolve_parameters(const FitInput& in, std::vector<CaseGroup>& groups) {
    std::vector<FitParameter> params(in.parameters.size());
    std::vector<std::string> first_error(in.parameters.size());
    std::vector<bool> found(in.parameters.size(), false);
    for (CaseGroup& g : groups) {
        const std::string text = [&] {
            try {
                return read_input_file(g.case_file, "case file");
            } catch (const InputError& e) {
                throw InputError(location(in, in.measurements[g.measurements.front()].where) + "case: " + e.what());
            }
        }();
        std::vector<std::string> keys;
        std::vector<KeySource> sources;
        for (size_t j = 0; j < in.parameters.size(); ++j) {
            const KeySource source{in.parameter_nodes[j], in.path};
            try {
                const CaseParameters one = CaseParameters::from_text(text, g.case_file, {in.parameters[j].key}, {source}, g.model);
                const CaseParameter& p = one.parameters().front();
                if (!found[j]) {
                    params[j].key = p.key;
                    params[j].dimension = p.dimension;
                    params[j].start = p.value;
                    params[j].min = std::max(p.min, p.value / kDefaultBoundFactor);
                    params[j].max = std::min(p.max, p.value * kDefaultBoundFactor);
                    found[j] = true;
                }
                keys.push_back(in.parameters[j].key);
                sources.push_back(source);
                g.parameters.push_back(j);
            } catch (const InputError& e) {
                if (first_error[j].empty()) first_error[j] = e.what();
            }
        }
        g.keys = CaseParameters::from_text(text, g.case_file, keys, sources, g.model);
    }
    for (size_t j = 0; j < params.size(); ++j) {
        if (!found[j]) throw InputError(first_error[j] + " (in none of the measurements' cases)");
        const FitParameterSpec& spec = in.parameters[j];
        if (spec.min) params[j].min = *spec.min;
        if (spec.max) params[j].max = *spec.max;
        if (!(params[j].min <= params[j].start && params[j].start <= params[j].max))
            throw InputError(location(in, spec.where) + "parameter \"" + spec.key + "\": the case's value " +
                             format_quantity(params[j].start, params[j].dimension) + " lies outside min/max; expected "
                             "bounds around it");
    }
    return params;
}

Evaluation evaluate(const FitInput& in, const std::vector<CaseGroup>& groups, const Eigen::VectorXd& x) {
    Evaluation e;
    const size_t n_m = in.measurements.size(), n_p = static_cast<size_t>(x.size());
    e.f_hz.assign(n_m, 0.0);
    e.dlnf.assign(n_m, std::vector<double>(n_p, 0.0));
    e.level.assign(n_m, ModelChoice::automatic);
    SensitivityOptions options;
    options.chuck_factor = false;
    for (const CaseGroup& g : groups) {
        std::vector<double> values;
        for (size_t j : g.parameters) values.push_back(std::exp(x[static_cast<Eigen::Index>(j)]));
        const SensitivityResult r = eigen_sensitivities(*g.keys, values, options);
        for (size_t i : g.measurements) {
            const Measurement& m = in.measurements[i];
            const ModeSensitivity* s = r.find(m.mode);
            if (!s) {
                std::string found;
                for (const ModeSensitivity& t : r.modes) found += (found.empty() ? "" : ", ") + t.key.text();
                throw InputError(location(in, m.where) + "mode = \"" + m.mode.text() + "\": the case " + g.case_file +
                                 " has no such mode among its modes (" + found + "); expected one of them, or more "
                                 "[analysis] modes in the case");
            }
            e.f_hz[i] = s->frequency_hz;
            e.level[i] = r.level;
            for (size_t k = 0; k < g.parameters.size(); ++k) e.dlnf[i][g.parameters[k]] = s->dlnf_dlnp[k];
        }
    }
    return e;
}

struct Linear {
    Eigen::VectorXd r;
    Eigen::MatrixXd J;
    double cost() const { return r.squaredNorm(); }
};

Linear linearise(const FitInput& in, const Evaluation& e) {
    const Eigen::Index n_m = static_cast<Eigen::Index>(in.measurements.size());
    const Eigen::Index n_p = static_cast<Eigen::Index>(e.dlnf.empty() ? 0 : e.dlnf[0].size());
    Linear l{Eigen::VectorXd(n_m), Eigen::MatrixXd(n_m, n_p)};
    for (Eigen::Index i = 0; i < n_m; ++i) {
        const Measurement& m = in.measurements[static_cast<size_t>(i)];
        l.r[i] = (e.f_hz[static_cast<size_t>(i)] - m.frequency_hz) / m.uncertainty_hz;
        for (Eigen::Index j = 0; j < n_p; ++j)
            l.J(i, j) = e.f_hz[static_cast<size_t>(i)] * e.dlnf[static_cast<size_t>(i)][static_cast<size_t>(j)] / m.uncertainty_hz;
    }
    return l;
}

Eigen::VectorXd clamp(Eigen::VectorXd x, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
    return x.cwiseMax(lo).cwiseMin(hi);
}

// Covariance of ln p, uncertainties, correlations and the pairs the data cannot separate.
void covariance(const Linear& l, FitOutcome& out) {
    const Eigen::Index n = l.J.cols();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(l.J, Eigen::ComputeThinV);
    const Eigen::VectorXd s = svd.singularValues();
    const Eigen::MatrixXd V = svd.matrixV();
    const double s_max = s.size() ? s[0] : 0;
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
    std::vector<bool> unknown(static_cast<size_t>(n), false);
    for (Eigen::Index k = 0; k < n; ++k) {
        const bool seen = k < s.size() && s[k] > kUnidentifiable * s_max && s_max > 0;
        if (seen) {
            C += V.col(k) * V.col(k).transpose() / (s[k] * s[k]);
            continue;
        }
        // The direction the data do not see: the parameters with a share in it.
        const Eigen::VectorXd v = k < V.cols() ? Eigen::VectorXd(V.col(k)) : Eigen::VectorXd::Unit(n, k);
        std::vector<std::string> names;
        for (Eigen::Index j = 0; j < n; ++j)
            if (std::abs(v[j]) > 0.1) {
                unknown[static_cast<size_t>(j)] = true;
                names.push_back(out.parameters[static_cast<size_t>(j)].key);
            }
        std::string list;
        for (size_t j = 0; j < names.size(); ++j) list += (j ? (j + 1 == names.size() ? " and " : ", ") : "") + names[j];
        out.warnings.push_back("the measurements cannot separate " + list + ": only a combination of them is "
                               "determined (singular value " + significant(k < s.size() ? s[k] / s_max : 0.0, 2) +
                               " of the largest); fix one of them, or add a measurement that depends on them differently");
    }
    out.correlation = Eigen::MatrixXd::Identity(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
        FitParameter& p = out.parameters[static_cast<size_t>(j)];
        if (!unknown[static_cast<size_t>(j)]) p.uncertainty = p.value * std::sqrt(C(j, j));
        for (Eigen::Index k = 0; k < n; ++k)
            if (j != k && C(j, j) > 0 && C(k, k) > 0) out.correlation(j, k) = C(j, k) / std::sqrt(C(j, j) * C(k, k));
    }
    for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index k = j + 1; k < n; ++k)
            if (!unknown[static_cast<size_t>(j)] && !unknown[static_cast<size_t>(k)] &&
                std::abs(out.correlation(j, k)) > kHighCorrelation)
                out.warnings.push_back("the measurements hardly separate " + out.parameters[static_cast<size_t>(j)].key +
                                       " and " + out.parameters[static_cast<size_t>(k)].key + " (correlation " +
                                       significant(out.correlation(j, k), 3) + "): their uncertainties are large and tied");
}

}  // namespace

namespace {

// Where Levenberg–Marquardt ends: x, its evaluation and linearisation.
struct Minimum {
    Eigen::VectorXd x;
    Evaluation e;
    Linear l;
    int iterations = 0;
    bool converged = false;
};

Minimum levenberg_marquardt(const FitInput& in, const std::vector<CaseGroup>& groups, Eigen::VectorXd x,
                            const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, const FitProgress& say) {
    Minimum m{x, evaluate(in, groups, x), {}, 0, false};
    m.l = linearise(in, m.e);
    double mu = kInitialDamping;
    for (m.iterations = 1; m.iterations <= kMaxIterations; ++m.iterations) {
        const Eigen::MatrixXd A = m.l.J.transpose() * m.l.J;
        const Eigen::VectorXd g = m.l.J.transpose() * m.l.r;
        Eigen::MatrixXd D = A.diagonal().asDiagonal();
        // A parameter no measurement sees has a zero column: keep the system regular.
        D.diagonal() = D.diagonal().cwiseMax(1e-12 * std::max(A.diagonal().maxCoeff(), 1e-300));
        const Eigen::VectorXd x_new = clamp(m.x + (A + mu * D).ldlt().solve(-g), lo, hi);
        const Evaluation e_new = evaluate(in, groups, x_new);
        const Linear l_new = linearise(in, e_new);
        const double moved = (x_new - m.x).cwiseAbs().maxCoeff();
        if (l_new.cost() <= m.l.cost()) {
            m.x = x_new, m.e = e_new, m.l = l_new;
            mu = std::max(mu / 3, 1e-12);
            say("iteration " + std::to_string(m.iterations) + ": chi^2 = " + significant(m.l.cost()));
            if (moved < kStepTolerance) {
                m.converged = true;
                return m;
            }
        } else {
            mu *= 5;
            // No step lowers the cost: a minimum (or a bound).
            if (mu > kMaxDamping || moved < kStepTolerance) {
                m.converged = true;
                return m;
            }
        }
    }
    m.iterations = kMaxIterations;
    return m;
}

}  // namespace

FitOutcome run_fit(const FitInput& in, const FitProgress& progress) {
    const auto say = [&](const std::string& s) {
        if (progress) progress(s);
    };
    std::vector<CaseGroup> groups = group_cases(in);
    FitOutcome out;
    out.parameters = resolve_parameters(in, groups);
    const Eigen::Index n = static_cast<Eigen::Index>(out.parameters.size());
    Eigen::VectorXd x(n), lo(n), hi(n);
    for (Eigen::Index j = 0; j < n; ++j) {
        const FitParameter& p = out.parameters[static_cast<size_t>(j)];
        x[j] = std::log(p.start), lo[j] = std::log(p.min), hi[j] = std::log(p.max);
    }
    const Evaluation start = evaluate(in, groups, x);
    out.chi2_start = linearise(in, start).cost();
    say("start: chi^2 = " + significant(out.chi2_start));
    const Minimum m = levenberg_marquardt(in, groups, x, lo, hi, say);
    out.iterations = m.iterations;
    out.converged = m.converged;
    out.chi2 = m.l.cost();
    for (Eigen::Index j = 0; j < n; ++j) {
        FitParameter& p = out.parameters[static_cast<size_t>(j)];
        p.value = std::exp(m.x[j]);
        p.at_bound = m.x[j] <= lo[j] + 1e-9 || m.x[j] >= hi[j] - 1e-9;
        if (p.at_bound)
            out.warnings.push_back(p.key + " stopped at its bound " + format_quantity(p.value, p.dimension) +
                                   ": the measurements ask for a value outside [" + format_quantity(p.min, p.dimension) +
                                   ", " + format_quantity(p.max, p.dimension) + "]; check the model or widen the bounds");
    }
    if (!out.converged) out.warnings.push_back("not converged in " + std::to_string(kMaxIterations) + " iterations");
    covariance(m.l, out);
    for (size_t i = 0; i < in.measurements.size(); ++i)
        out.measurements.push_back({in.measurements[i], m.e.f_hz[i], start.f_hz[i], m.e.dlnf[i], m.e.level[i]});
    for (const CaseGroup& g : groups) {
        std::vector<double> values;
        for (size_t j : g.parameters) values.push_back(out.parameters[j].value);
        out.cases.push_back({g.case_file, g.model,
                             g.keys->text(values, "Calibrated by coremodal fit " + in.path + " (fit.toml, report.md)")});
    }
    return out;
}

}  // namespace coremodal
