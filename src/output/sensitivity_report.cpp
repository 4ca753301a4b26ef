#include "output/sensitivity_report.hpp"

#include "common/format.hpp"
#include "output/csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace coremodal {
namespace {

std::vector<const ModeSensitivity*> shown_modes(const SensitivityResult& r) {
    std::vector<const ModeSensitivity*> out;
    for (const ModeSensitivity& m : r.modes)
        if (static_cast<int>(out.size()) < kSensitivityTableModes) out.push_back(&m);
    return out;
}

std::string fixed3(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%+.3f", v);
    return std::abs(v) < 5e-4 ? "0" : text;
}

std::string column_name(const ModeSensitivity& m) { return m.key.text() + " (" + significant(m.frequency_hz) + " Hz)"; }

}  // namespace

std::string sensitivity_csv(const SensitivityResult& r) {
    std::ostringstream out;
    out << "parameter,value_si,method";
    for (const ModeSensitivity& m : r.modes) out << "," << csv_field("dlnf/dlnp " + m.key.text());
    if (r.k) out << ",dlnf/dlnp f2,dlnk/dlnp";
    out << "\n";
    for (size_t j = 0; j < r.parameters.size(); ++j) {
        out << csv_field(r.parameters[j].key) << "," << r.values[j] << "," << r.methods[j];
        for (const ModeSensitivity& m : r.modes) out << "," << m.dlnf_dlnp[j];
        if (r.k) out << "," << r.f2->dlnf_dlnp[j] << "," << r.dlnk_dlnp[j];
        out << "\n";
    }
    return out.str();
}

std::string sensitivity_table_markdown(const SensitivityResult& r) {
    std::ostringstream out;
    const auto modes = shown_modes(r);
    out << "| parameter | value |";
    for (const ModeSensitivity* m : modes) out << " " << column_name(*m) << " |";
    if (r.k) out << " f2 (" << significant(r.f2->frequency_hz) << " Hz) | k (" << significant(*r.k, 3) << ") |";
    out << "\n|---|---|";
    for (size_t i = 0; i < modes.size() + (r.k ? 2 : 0); ++i) out << "---|";
    out << "\n";
    for (size_t j = 0; j < r.parameters.size(); ++j) {
        out << "| `" << r.parameters[j].key << "` | " << format_quantity(r.values[j], r.parameters[j].dimension) << " |";
        for (const ModeSensitivity* m : modes) out << " " << fixed3(m->dlnf_dlnp[j]) << " |";
        if (r.k) out << " " << fixed3(r.f2->dlnf_dlnp[j]) << " | " << fixed3(r.dlnk_dlnp[j]) << " |";
        out << "\n";
    }
    return out.str();
}

std::string sensitivity_report_markdown(const std::string& case_name, const SensitivityResult& r) {
    std::ostringstream out;
    out << "# Sensitivities of " << case_name << "\n\n"
        << "d ln f / d ln p of the " << to_string(r.level) << " level's modes, from the eigenvalue derivative "
        << "φᵀ(∂K/∂p − λ ∂M/∂p)φ / (2λ) with ∂K/∂p, ∂M/∂p the central difference of the assembled operators "
        << "(docs/how-to/calibration.md, \"Sensitivities\"). A value of 0.5 means f ∝ √p; 0.1: a 10 % error in p moves "
        << "f by 1 %.";
    if (r.k) out << " k = f1 / f2, f2 the free–free roll over the free span at the same level: d ln k = d ln f1 − d ln f2.";
    out << "\n\n" << sensitivity_table_markdown(r) << "\n";
    const bool resolved = std::count(r.methods.begin(), r.methods.end(), "re-solved") > 0;
    if (resolved)
        out << "Parameters marked re-solved change the model's DOFs (an element count follows them): their "
               "column is the central difference of re-solved frequencies (sensitivity.csv, method).\n";
    return out.str();
}

std::string sensitivity_console(const SensitivityResult& r) {
    std::ostringstream out;
    const auto modes = shown_modes(r);
    char line[256];
    std::snprintf(line, sizeof line, "  %-38s", "d ln f / d ln p");
    out << line;
    for (const ModeSensitivity* m : modes) {
        std::snprintf(line, sizeof line, " %10s", (m->key.type.substr(0, 4) + std::to_string(m->key.n) + "," + std::to_string(m->key.m)).c_str());
        out << line;
    }
    if (r.k) out << "         f2          k";
    out << "\n";
    for (size_t j = 0; j < r.parameters.size(); ++j) {
        std::snprintf(line, sizeof line, "  %-38s", r.parameters[j].key.c_str());
        out << line;
        for (const ModeSensitivity* m : modes) {
            std::snprintf(line, sizeof line, " %10s", fixed3(m->dlnf_dlnp[j]).c_str());
            out << line;
        }
        if (r.k) {
            std::snprintf(line, sizeof line, " %10s %10s", fixed3(r.f2->dlnf_dlnp[j]).c_str(), fixed3(r.dlnk_dlnp[j]).c_str());
            out << line;
        }
        out << "\n";
    }
    return out.str();
}

}  // namespace coremodal
