// The study's report.md (output/study_report.hpp).
#include "output/study_report.hpp"

#include "common/format.hpp"

#include <algorithm>
#include <map>
#include <sstream>

namespace coremodal {

namespace {

std::string cell(const std::optional<double>& v, int digits = 4) { return v ? significant(*v, digits) : "-"; }

void report_points(std::ostream& out, const CaseSweep& sweep, const StudyResult& r) {
    out << "## Points\n\n| # |";
    for (const SweepParameter& p : sweep.parameters()) out << " " << p.name << " |";
    out << " status | f1 [Hz] | k | D [mm] | v_safe [m/s] | time [s] |\n|---|";
    for (size_t j = 0; j < sweep.parameters().size(); ++j) out << "---|";
    out << "---|---|---|---|---|---|\n";
    for (const StudyPoint& p : r.points) {
        out << "| " << p.index + 1 << " |";
        for (size_t j = 0; j < sweep.parameters().size(); ++j)
            out << " " << sweep.parameters()[j].labels[static_cast<size_t>(p.value_index[j])] << " |";
        out << " " << (p.ok ? "ok" : "FAILED") << " | " << cell(p.f1_hz) << " | " << cell(p.k, 3) << " | "
            << significant(p.diameter_m * 1e3, 4) << " | " << cell(p.v_safe_m_s, 3) << " | " << significant(p.time_s, 3) << " |\n";
    }
    out << "\nf1: first bending mode. k = f1 / f_I-7(k = 1) over the free span L = Lc - 2 Li (Li: clamp zone "
           "centres or the chucks' furthest expanding elements). D: rest roll outer diameter (the core's without "
           "rest paper). v_safe = "
        << significant(sweep.options().safe_factor) << " pi D f1 (I-5).\n\n";
}

struct TrackSummary {
    int track = 0;
    std::string label;
    int n_points = 0;
    double f_min = 1e300, f_max = 0;
    int n_ambiguous = 0;
};

void report_tracks(std::ostream& out, const StudyResult& r) {
    std::map<int, TrackSummary> tracks;
    std::vector<std::string> ambiguous;
    for (const StudyPoint& p : r.points) {
        if (!p.ok) continue;
        for (size_t k = 0; k < p.groups.size(); ++k) {
            const TrackStep& t = p.tracks[k];
            TrackSummary& s = tracks[t.track];
            s.track = t.track;
            if (s.label.empty()) s.label = label_text(p.groups[k].label);
            ++s.n_points;
            s.f_min = std::min(s.f_min, p.groups[k].frequency_hz);
            s.f_max = std::max(s.f_max, p.groups[k].frequency_hz);
            if (t.ambiguous) {
                ++s.n_ambiguous;
                ambiguous.push_back("point " + std::to_string(p.index + 1) + " (from point " +
                                    std::to_string(*p.predecessor + 1) + "): track " + std::to_string(t.track) + " " +
                                    label_text(p.groups[k].label) + " at " + significant(p.groups[k].frequency_hz) +
                                    " Hz, MAC " + cell(t.mac_previous, 3));
            }
        }
    }
    out << "## Tracked modes\n\nModes are followed from point to point by the modal assurance criterion (MAC) "
           "of mesh-independent signatures on the core's outer surface; degenerate pairs are tracked as one "
           "subspace (docs/how-to/studies.md).\n\n| track | label (first point) | points | f min [Hz] | f max [Hz] | "
           "ambiguous steps |\n|---|---|---|---|---|---|\n";
    for (const auto& [id, s] : tracks)
        out << "| " << id << " | " << s.label << " | " << s.n_points << " | " << significant(s.f_min) << " | " << significant(s.f_max)
            << " | " << s.n_ambiguous << " |\n";
    out << "\n";
    if (ambiguous.empty()) {
        out << "No ambiguous step (every match has MAC >= " << kAmbiguousMac << " and no rival within "
            << kCloseCandidateMac << ").\n\n";
    } else {
        out << "Ambiguous steps (MAC < " << kAmbiguousMac << ", or a rival candidate within " << kCloseCandidateMac
            << "): check these curves.\n\n";
        for (const auto& a : ambiguous) out << "- " << a << "\n";
        out << "\n";
    }
}

void report_safe_speed(std::ostream& out, const CaseSweep& sweep, const StudyResult& r) {
    const std::optional<double> web = sweep.options().web_speed_m_s;
    if (!web) return;
    const std::vector<SpeedCrossing> crossings = safe_speed_crossings(sweep, r, *web);
    if (crossings.empty()) return;
    out << "## When to change the roll (König's chart)\n\nWeb speed " << significant(*web, 3) << " m/s (" << significant(*web * 60, 4)
        << " m/min), v_safe = " << significant(sweep.options().safe_factor) << " pi D f1:\n\n";
    for (const SpeedCrossing& c : crossings) {
        out << "- " << (c.curve.empty() ? std::string("the roll") : c.curve) << ": ";
        if (!c.change_diameters_m.empty()) {
            out << "change the roll when its diameter falls below **" << significant(c.change_diameters_m.back() * 1e3, 4)
                << " mm**";
        } else if (c.v_min_m_s >= *web) {
            out << "safe over the whole range studied (v_safe >= " << significant(c.v_min_m_s, 3) << " m/s down to D = "
                << significant(c.d_min_m * 1e3, 4) << " mm)";
        } else {
            out << "too fast over the whole range studied (v_safe <= " << significant(c.v_max_m_s, 3) << " m/s even at D = "
                << significant(c.d_max_m * 1e3, 4) << " mm)";
        }
        out << "\n";
    }
    out << "\n";
}

std::string speed_cell(const std::optional<double>& v) { return v ? significant(*v, 4) : "-"; }

// At the press's web speed: the points whose amplitude reaches the limit
// there or below (the first speed at the limit is at most the web speed).
void report_response_at(std::ostream& out, const StudyResult& r, double web) {
    std::vector<std::string> over;
    for (const StudyPoint& p : r.points)
        if (p.response && p.response->v_limit_m_s && *p.response->v_limit_m_s <= web)
            over.push_back("point " + std::to_string(p.index + 1) + " (" + p.description + ", D = " +
                           significant(p.diameter_m * 1e3, 4) + " mm): at " + significant(*p.response->v_limit_m_s, 4) +
                           " m/s");
    out << "At the web speed " << significant(web, 3) << " m/s: ";
    if (over.empty()) {
        out << "every point stays within the amplitude limit (the forced response reaches it only above the web "
               "speed, or not at all).\n\n";
        return;
    }
    out << "the amplitude reaches the limit at or below the web speed at\n\n";
    for (const std::string& o : over) out << "- " << o << "\n";
    out << "\n";
}

// The forced response of every point (a case with [response]): the speed at
// the amplitude limit beside I-5 at 0.7 and 0.8 and König's v_krit.
void report_response(std::ostream& out, const CaseSweep& sweep, const StudyResult& r) {
    const auto has = [](const StudyPoint& p) { return p.response.has_value(); };
    const auto first = std::find_if(r.points.begin(), r.points.end(), has);
    if (first == r.points.end()) return;
    out << "## Safe web speed from the forced response\n\nAt every point the forced response of the case's [damping], "
           "[excitation] and [response] (docs/how-to/response.md): the web speed where the amplitude first reaches +-"
        << significant(first->response->limit_m * 1e3, 3)
        << " mm, the factor that speed implies in I-5 (f_rot / f1), beside I-5 at 0.7 and 0.8 and König's "
           "v_krit (K-1/K-2, experience factor 0.66), all from the same f1 at rest (m/s).\n\n| # |";
    for (const SweepParameter& p : sweep.parameters()) out << " " << p.name << " |";
    out << " D [mm] | largest amplitude | limit reached at | implied factor | I-5 x 0.7 | I-5 x 0.8 | König |\n|---|";
    for (size_t j = 0; j < sweep.parameters().size(); ++j) out << "---|";
    out << "---|---|---|---|---|---|---|\n";
    for (const StudyPoint& p : r.points) {
        if (!p.response) continue;
        const StudyResponse& s = *p.response;
        out << "| " << p.index + 1 << " |";
        for (size_t j = 0; j < sweep.parameters().size(); ++j)
            out << " " << sweep.parameters()[j].labels[static_cast<size_t>(p.value_index[j])] << " |";
        out << " " << significant(p.diameter_m * 1e3, 4) << " | " << significant(s.max_amplitude_m * 1e3, 3) << " mm at "
            << significant(s.max_amplitude_web_speed_m_s, 4) << " m/s | "
            << (s.below_range ? "below the range"
                : s.v_limit_m_s ? "**" + significant(*s.v_limit_m_s, 4) + "**"
                                : "not up to " + significant(s.max_web_speed_m_s, 3))
            << " | " << (s.implied_factor ? formatted("%.3f", *s.implied_factor) : "-") << " | "
            << speed_cell(s.v_i5_07_m_s) << " | " << speed_cell(s.v_i5_08_m_s) << " | " << speed_cell(s.v_koenig_m_s)
            << " |\n";
    }
    out << "\n";
    if (const std::optional<double> web = sweep.options().web_speed_m_s) report_response_at(out, r, *web);
}

void report_failures(std::ostream& out, const StudyResult& r) {
    if (r.n_failed() == 0) return;
    out << "## Failed points\n\n";
    for (const StudyPoint& p : r.points)
        if (!p.ok) out << "- point " << p.index + 1 << " (" << p.description << "): " << p.error << "\n";
    out << "\n";
}

}  // namespace

std::string study_report_markdown(const CaseSweep& sweep, const StudyResult& r, const std::vector<std::string>& pngs,
                                  const std::string& plot_problem) {
    std::ostringstream out;
    const SweepOptions& o = sweep.options();
    out << "# Study: " << sweep.case_name() << "\n\n";
    out << "Case file `" << sweep.case_file() << "`; " << sweep.n_points() << " points ("
        << sweep.n_points() - r.n_failed() << " ok, " << r.n_failed() << " failed) in "
        << minutes_or_seconds(r.time_s) << "; mesh "
        << (o.mesh_level.empty() ? std::string("as the case's [mesh]") : "level " + o.mesh_level) << ", "
        << (o.modes ? std::to_string(o.modes) + " lowest modes per point" : std::string("modes as the case's [analysis]"))
        << ". Written by coremodal " COREMODAL_VERSION ".\n\n";
    out << "| parameter | keys | values |\n|---|---|---|\n";
    for (const SweepParameter& p : sweep.parameters()) {
        std::string keys, values;
        for (const auto& k : p.keys) keys += (keys.empty() ? "" : ", ") + k;
        for (const auto& l : p.labels) values += (values.empty() ? "" : ", ") + l;
        out << "| " << p.name << " | " << keys << " | " << values << " |\n";
    }
    out << "\n";
    report_points(out, sweep, r);
    report_safe_speed(out, sweep, r);
    report_response(out, sweep, r);
    report_tracks(out, r);
    report_failures(out, r);
    out << "## Plots\n\n";
    if (!plot_problem.empty()) out << "Plots were not drawn: " << plot_problem << ".\n\n";
    for (const std::string& png : pngs) out << "![" << png << "](" << png << ")\n\n";
    out << "Files: `study.csv` (one row per point and tracked mode), `study.json` (the study's parameters), this "
           "report.\n";
    return out.str();
}

std::string study_crossings_console(const CaseSweep& sweep, const StudyResult& result) {
    const std::optional<double> web = sweep.options().web_speed_m_s;
    if (!web) return "";
    std::ostringstream out;
    for (const SpeedCrossing& c : safe_speed_crossings(sweep, result, *web)) {
        if (c.change_diameters_m.empty()) continue;
        out << "  at " << significant(*web) << " m/s: " << (c.curve.empty() ? std::string("the roll") : c.curve)
            << ": change the roll below D = " << significant(c.change_diameters_m.back() * 1e3) << " mm\n";
    }
    return out.str();
}

}  // namespace coremodal
