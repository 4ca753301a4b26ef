#include "output/batch_report.hpp"

#include "output/csv.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <sstream>

namespace coremodal {
namespace {

std::string fixed(const std::optional<double>& v, int decimals) {
    if (!v) return "-";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, *v);
    return buf;
}

std::string csv_number(const std::optional<double>& v) {
    if (!v) return "";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", *v);
    return buf;
}

std::optional<double> times(const std::optional<double>& v, double factor) {
    return v ? std::optional<double>(*v * factor) : std::nullopt;
}

// The displayed columns of one case: status, f1, ratio, k, D [mm], v_safe m/s, m/min, time.
std::vector<std::string> row_cells(const BatchCase& c) {
    return {c.name,
            c.ok ? "ok" : "FAILED",
            fixed(c.f1_hz, 2),
            fixed(c.fe_over_timoshenko, 4),
            fixed(c.chuck_factor, 4),
            fixed(times(c.diameter_m, 1000), 1),
            fixed(c.v_safe_m_s, 2),
            fixed(times(c.v_safe_m_s, 60), 0),
            fixed(c.time_s, 1)};
}

const std::vector<std::string> kHeader = {"case",         "status", "f1 [Hz]",      "FE/Timoshenko",
                                          "k (chucks)",   "D [mm]", "v_safe [m/s]", "v_safe [m/min]",
                                          "time [s]"};

std::string footnote() {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "f1: first bending mode (summary.json beam.fe_first_bending_hz); FE/Timoshenko: f1 over the "
                  "Timoshenko beam formula; k: the chuck factor f1/f2 (summary.json chuck.chuck_factor; scenes on "
                  "elastic chucks).\n"
                  "v_safe = %.1f * pi * D * f1 (safe web speed, Ilomäki I-5, with the factor %.1f; summary.json "
                  "speeds); D = rest roll outer diameter, or the core's without rest paper; not given for free-free "
                  "cases.\n",
                  kBatchSafeFactor, kBatchSafeFactor);
    return buf;
}

}  // namespace

void print_batch_table(std::ostream& out, const std::vector<BatchCase>& cases) {
    std::vector<std::vector<std::string>> rows = {kHeader};
    for (const auto& c : cases) rows.push_back(row_cells(c));
    std::vector<std::size_t> widths(kHeader.size(), 0);
    for (const auto& r : rows)
        for (std::size_t i = 0; i < r.size(); ++i) widths[i] = std::max(widths[i], r[i].size());
    auto print_row = [&](const std::vector<std::string>& r) {
        std::string line = " ";
        for (std::size_t i = 0; i < r.size(); ++i) {
            const std::string pad(widths[i] - r[i].size(), ' ');
            line += i < 2 ? r[i] + pad : pad + r[i];  // names left, numbers right
            if (i + 1 < r.size()) line += "  ";
        }
        out << line << '\n';
    };
    out << '\n';
    print_row(rows[0]);
    std::vector<std::string> rule;
    for (auto w : widths) rule.push_back(std::string(w, '-'));
    print_row(rule);
    for (std::size_t i = 1; i < rows.size(); ++i) print_row(rows[i]);
    out << '\n' << footnote();
    std::size_t failed = 0;
    for (const auto& c : cases)
        if (!c.ok) {
            if (failed++ == 0) out << '\n';
            out << "FAILED " << c.name << ": " << c.error << "\n  case " << c.file << ", log " << c.log_file << '\n';
        }
    bool noted = false;
    for (const auto& c : cases)
        if (!c.note.empty()) {
            if (!noted) out << '\n';
            noted = true;
            out << "note " << c.name << ": " << c.note << '\n';
        }
    out << '\n' << cases.size() - failed << " of " << cases.size() << " cases ok";
    if (failed) out << ", " << failed << " failed";
    out << std::endl;
}

std::string batch_csv(const std::vector<BatchCase>& cases) {
    std::ostringstream s;
    s << "case,file,status,f1_hz,fe_over_timoshenko,chuck_factor_k,diameter_m,v_safe_m_per_s,v_safe_m_per_min,time_s,"
         "error,note\n";
    for (const auto& c : cases) {
        char time[64];
        std::snprintf(time, sizeof time, "%.3f", c.time_s);
        s << csv_field(c.name) << ',' << csv_field(c.file) << ',' << (c.ok ? "ok" : "failed") << ','
          << csv_number(c.f1_hz) << ',' << csv_number(c.fe_over_timoshenko) << ',' << csv_number(c.chuck_factor) << ','
          << csv_number(c.diameter_m) << ','
          << csv_number(c.v_safe_m_s) << ',' << csv_number(times(c.v_safe_m_s, 60)) << ',' << time << ','
          << csv_field(c.error) << ',' << csv_field(c.note) << '\n';
    }
    return s.str();
}

std::string batch_markdown(const std::vector<BatchCase>& cases) {
    auto cell = [](std::string s) {
        std::string out;
        for (char c : s) {
            if (c == '|') out += '\\';
            out += c == '\n' ? ' ' : c;
        }
        return out;
    };
    std::ostringstream s;
    s << "# coremodal batch\n\n|";
    for (const auto& h : kHeader) s << ' ' << h << " |";
    s << " error | note |\n|";
    for (std::size_t i = 0; i < kHeader.size(); ++i) s << (i < 2 ? "---|" : "---:|");
    s << "---|---|\n";
    for (const auto& c : cases) {
        s << '|';
        for (const auto& v : row_cells(c)) s << ' ' << cell(v) << " |";
        s << ' ' << cell(c.error) << " | " << cell(c.note) << " |\n";
    }
    std::string note = footnote();
    std::replace(note.begin(), note.end(), '\n', ' ');
    note.pop_back();
    s << '\n' << note << '\n';
    return s.str();
}

}  // namespace coremodal
