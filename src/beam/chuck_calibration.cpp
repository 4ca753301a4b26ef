#include "beam/chuck_calibration.hpp"
#include "common/format.hpp"

#include "beam/formulas.hpp"
#include "common/error.hpp"
#include "scene/toml_text.hpp"

#include <toml++/toml.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace coremodal {
namespace {

// Columns of the least-squares matrix are scaled to unit norm; a singular
// value below this share of the largest means the groups did not vary
// independently over the samples.
constexpr double kCollinearShare = 1e-8;


}  // namespace

std::optional<double> scene_li(const Scene& scene) {
    const SupportSpec& s = scene.supports;
    if (s.kind == SupportKind::clamped && s.clamps.size() == 2) {
        const ClampSpec& left = s.clamps[0];
        const ClampSpec& right = s.clamps[1];
        const double left_li = 0.5 * (left.z_start + left.z_end);
        const double right_li = scene.core.length - 0.5 * (right.z_start + right.z_end);
        return 0.5 * (left_li + right_li);
    }
    if (s.kind == SupportKind::chucks && !s.chucks.empty()) {
        double sum = 0;
        for (const ChuckSpec& c : s.chucks) sum += c.li();
        return sum / static_cast<double>(s.chucks.size());
    }
    return std::nullopt;
}

double core_bending_stiffness(const Scene& scene) {
    return scene.core.material.E_z * tube_inertia(scene.core.outer_diameter, scene.core.inner_diameter);
}

std::optional<ChuckFactorI7> chuck_factor_of(const Scene& scene, double f1_hz) {
    const std::optional<double> li = scene_li(scene);
    if (!li || !(scene.core.length - 2 * *li > 0) || !(f1_hz > 0)) return std::nullopt;
    ChuckFactorI7 c;
    c.li_m = *li;
    c.span_m = scene.core.length - 2 * *li;
    c.f_i7_hz = euler_bernoulli_first_bending_hz(beam_section(scene), c.span_m);
    c.k = f1_hz / c.f_i7_hz;
    return c;
}

CalibrationGroups calibration_groups(const BeamSection& section, double core_EI, double li_m, double span_m) {
    COREMODAL_ASSERT(core_EI > 0 && span_m > 0 && section.kappa_GA > 0 && section.EI >= core_EI * (1 - 1e-12));
    return {section.EI / core_EI * li_m / span_m, section.EI / (section.kappa_GA * span_m * span_m),
            std::max(0.0, (section.EI - core_EI) / section.EI)};
}

CalibrationGroups calibration_groups(const Scene& scene, double li_m, double span_m) {
    return calibration_groups(beam_section(scene), core_bending_stiffness(scene), li_m, span_m);
}

double ChuckFactorLaw::k(const CalibrationGroups& g) const {
    double inverse_square = c[0];
    for (int i = 0; i < kCalibrationGroups; ++i) inverse_square += c[static_cast<size_t>(i + 1)] * g[i];
    if (!(inverse_square > 0))
        throw InputError("the calibrated law 1/k^2 = c0 + c1 g1 + c2 g2 + c3 g3 gives " + significant(inverse_square) +
                         " at g1 = " + significant(g.g1) + ", g2 = " + significant(g.g2) + ", g3 = " +
                         significant(g.g3) + ", far outside the calibrated range; expected a core and span like "
                         "those calibrated");
    return 1 / std::sqrt(inverse_square);
}

namespace {

// A group column that varies by less than this share of its size is constant.
constexpr double kConstantShare = 1e-9;

bool varies(const std::vector<CalibrationSample>& samples, int group) {
    double lo = samples.front().groups[group], hi = lo;
    for (const CalibrationSample& s : samples) lo = std::min(lo, s.groups[group]), hi = std::max(hi, s.groups[group]);
    return hi - lo > kConstantShare * std::max({std::abs(lo), std::abs(hi), 1e-300});
}

}  // namespace

ChuckFactorLaw fit_chuck_factor(const std::vector<CalibrationSample>& samples) {
    ChuckFactorLaw law;
    std::vector<int> columns;  // the groups fitted
    for (int i = 0; i < kCalibrationGroups; ++i) {
        law.fitted[static_cast<size_t>(i)] = !samples.empty() && varies(samples, i);
        if (law.fitted[static_cast<size_t>(i)]) columns.push_back(i);
    }
    const Eigen::Index n = static_cast<Eigen::Index>(samples.size());
    const Eigen::Index m = static_cast<Eigen::Index>(columns.size()) + 1;
    if (n < m + 1)
        throw InputError("the chuck factor fit of " + std::to_string(m) + " coefficients needs at least " +
                         std::to_string(m + 1) + " points, got " + std::to_string(n) +
                         "; expected more values of rest paper thickness and core length");
    Eigen::MatrixXd A(n, m);
    Eigen::VectorXd y(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const CalibrationSample& s = samples[static_cast<size_t>(i)];
        A(i, 0) = 1.0;
        for (size_t j = 0; j < columns.size(); ++j) A(i, static_cast<Eigen::Index>(j) + 1) = s.groups[columns[j]];
        y(i) = 1 / (s.k * s.k);
    }
    const Eigen::VectorXd scale = A.colwise().norm().transpose().cwiseMax(1e-300);
    const Eigen::MatrixXd As = A * scale.cwiseInverse().asDiagonal();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(As, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd sigma = svd.singularValues();
    if (!(sigma(m - 1) > kCollinearShare * sigma(0)))
        throw InputError("the calibration points do not vary the groups g1 = (EI/EcIc)(Li/L), g2 = EI/(kGA L^2) "
                         "and g3 = EpIp/EI independently, so the law cannot be fitted; expected a grid over both "
                         "rest paper thickness and core length (docs/how-to/calibration.md)");
    const Eigen::VectorXd cs = svd.solve(y);
    law.c = {cs(0) / scale(0), 0, 0, 0};
    for (size_t j = 0; j < columns.size(); ++j)
        law.c[static_cast<size_t>(columns[j]) + 1] = cs(static_cast<Eigen::Index>(j) + 1) / scale(static_cast<Eigen::Index>(j) + 1);
    return law;
}

bool Range::contains(double v, double relative_slack) const {
    const double slack = relative_slack * std::max(std::abs(min), std::abs(max));
    return v >= min - slack && v <= max + slack;
}

namespace {

toml::array range_array(const Range& r) { return toml::array{r.min, r.max}; }

}  // namespace

void write_calibration(const std::string& path, const Calibration& c) {
    toml::table t{
        {"format", "coremodal-calibration"},
        {"version", kCalibrationFormatVersion},
        {"case", c.case_name},
        {"case_file", c.case_file},
        {"supports", c.supports},
        {"law", "1/k^2 = c0 + c1*g1 + c2*g2 + c3*g3"},
        {"groups", toml::table{{"g1", "(EI/(Ec*Ic)) * (Li/L)"}, {"g2", "EI/(kappa*G*A*L^2)"}, {"g3", "Ep*Ip/EI"}}},
        {"coefficients", toml::table{{"c0", c.law.c[0]}, {"c1", c.law.c[1]}, {"c2", c.law.c[2]}, {"c3", c.law.c[3]}}},
        {"fit", toml::table{{"points", c.n_fit},
                            {"held_out", c.n_held_out},
                            {"rms_residual_k", c.rms_residual_k},
                            {"max_residual_k", c.max_residual_k},
                            {"max_error_fit", c.max_error_fit},
                            {"max_error_held_out", c.max_error_held_out},
                            {"stated_error", c.stated_error},
                            {"passed", c.passed}}},
        {"range", toml::table{{"g1", range_array(c.g1)},
                              {"g2", range_array(c.g2)},
                              {"g3", range_array(c.g3)},
                              {"span_m", range_array(c.span_m)},
                              {"li_m", range_array(c.li_m)},
                              {"diameter_m", range_array(c.diameter_m)}}},
    };
    std::ofstream out(path);
    out << "# Chuck factor calibration written by coremodal " COREMODAL_VERSION " (docs/how-to/calibration.md).\n"
        << "# Apply it with: coremodal beam CASE.toml --calibration " << "calibration.toml\n"
        << "# k = 1/sqrt(c0 + c1 g1 + c2 g2 + c3 g3), g1 = (EI/(Ec Ic)) (Li/L), g2 = EI/(kappa G A L^2),\n"
        << "# g3 = Ep Ip/EI, EI = Ec Ic + Ep Ip, L = Lc - 2 Li. A coefficient 0 with its group constant over\n"
        << "# the calibration was not fitted ([range] shows the one value it had).\n\n"
        << t << "\n";
    out.close();  // checked: a full disk fails at close
    if (!out) throw std::runtime_error("cannot write " + path + " (" + std::strerror(errno) + ")");
}

namespace {

class CalibrationReader {
public:
    CalibrationReader(const std::string& path, const toml::table& t) : path_(path), t_(t) {}

    [[noreturn]] void fail(const toml::node* at, const std::string& what) const {
        std::string where = path_ + ": ";
        if (at && at->source().begin.line > 0)
            where = path_ + ":" + std::to_string(at->source().begin.line) + ":" +
                    std::to_string(at->source().begin.column) + ": ";
        throw InputError(where + what + "; expected a calibration.toml written by coremodal calibrate "
                                        "(docs/how-to/calibration.md)");
    }
    double number(std::string_view table, std::string_view key) const {
        const toml::node* n = t_[table][key].node();
        if (!n || !n->is_number()) fail(n ? n : t_.get(table), "[" + std::string(table) + "] " + std::string(key) + " missing or not a number");
        return *n->value<double>();
    }
    Range range(std::string_view key) const {
        const toml::node* n = t_["range"][key].node();
        const toml::array* a = n ? n->as_array() : nullptr;
        if (!a || a->size() != 2 || !(*a)[0].is_number() || !(*a)[1].is_number())
            fail(n ? n : t_.get("range"), "[range] " + std::string(key) + " must be [min, max]");
        return {*(*a)[0].value<double>(), *(*a)[1].value<double>()};
    }
    std::string text(std::string_view key) const { return std::string(t_[key].value_or<std::string_view>("")); }

private:
    const std::string& path_;
    const toml::table& t_;
};

}  // namespace

Calibration read_calibration(const std::string& path) {
    const toml::table t = parse_toml_input(read_input_file(path, "calibration file"), path,
                                           "a calibration.toml written by coremodal calibrate");
    const CalibrationReader r(path, t);
    if (t["format"].value_or<std::string_view>("") != "coremodal-calibration")
        r.fail(t.get("format"), "format is not \"coremodal-calibration\"");
    const int version = t["version"].value_or(0);
    if (version != kCalibrationFormatVersion)
        r.fail(t.get("version"), "version " + std::to_string(version) + " is not supported (this coremodal reads " +
                                     std::to_string(kCalibrationFormatVersion) + ")");
    Calibration c;
    c.law.c = {r.number("coefficients", "c0"), r.number("coefficients", "c1"), r.number("coefficients", "c2"),
               r.number("coefficients", "c3")};
    c.case_name = r.text("case");
    c.case_file = r.text("case_file");
    c.supports = r.text("supports");
    c.g1 = r.range("g1"), c.g2 = r.range("g2"), c.g3 = r.range("g3"), c.span_m = r.range("span_m"), c.li_m = r.range("li_m");
    c.diameter_m = r.range("diameter_m");
    c.n_fit = t["fit"]["points"].value_or(0);
    c.n_held_out = t["fit"]["held_out"].value_or(0);
    c.rms_residual_k = r.number("fit", "rms_residual_k");
    c.max_residual_k = r.number("fit", "max_residual_k");
    c.max_error_fit = r.number("fit", "max_error_fit");
    c.max_error_held_out = r.number("fit", "max_error_held_out");
    c.stated_error = r.number("fit", "stated_error");
    const toml::node* passed = t["fit"]["passed"].node();
    if (!passed || !passed->is_boolean()) r.fail(passed ? passed : t.get("fit"), "[fit] passed missing");
    c.passed = *passed->value<bool>();
    return c;
}

double calibrated_k(const Calibration& c, const CalibrationGroups& g, double span_m, double li_m, double diameter_m,
                    std::vector<std::string>& notes) {
    const auto check = [&](const Range& r, double v, const std::string& name, double unit, const char* unit_name) {
        if (!r.contains(v))
            notes.push_back("calibration: " + name + " = " + significant(v * unit) + unit_name +
                            " lies outside the calibrated range " + significant(r.min * unit) + " to " +
                            significant(r.max * unit) + unit_name + ": k is extrapolated");
    };
    check(c.span_m, span_m, "free span L", 1, " m");
    check(c.li_m, li_m, "Li", 1e3, " mm");
    check(c.diameter_m, diameter_m, "rest roll diameter", 1e3, " mm");
    check(c.g1, g.g1, "g1 = (EI/EcIc)(Li/L)", 1, "");
    check(c.g2, g.g2, "g2 = EI/(kGA L^2)", 1, "");
    check(c.g3, g.g3, "g3 = EpIp/EI", 1, "");
    return c.law.k(g);
}

}  // namespace coremodal
