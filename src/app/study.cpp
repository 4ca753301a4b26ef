// The study driver: points in, tracked modes and the study's files out.
#include "app/study.hpp"
#include "common/format.hpp"

#include "app/run_case.hpp"
#include "app/study_workers.hpp"
#include "beam/beam_theory.hpp"
#include "beam/chuck_calibration.hpp"
#include "beam/formulas.hpp"
#include "common/error.hpp"
#include "common/petsc_handle.hpp"
#include "common/stopwatch.hpp"
#include "output/csv.hpp"
#include "output/python_plots.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <ostream>
#include <sstream>
#include <thread>

namespace coremodal {
namespace fs = std::filesystem;

int StudyResult::n_failed() const {
    return static_cast<int>(std::count_if(points.begin(), points.end(), [](const StudyPoint& p) { return !p.ok; }));
}

namespace {


std::string minutes_or_seconds(double s) { return s < 120 ? significant(s, 3) + " s" : significant(s / 60, 3) + " min"; }

// ---- running the points ----------------------------------------------------

double first_bending_hz(const RunReport& report) {
    if (report.beam.fe_first_bending_hz > 0) return report.beam.fe_first_bending_hz;
    for (const Mode& m : report.modes.modes)
        if (m.label.type == "bending") return m.frequency_hz;
    return 0;
}


std::string progress_line(const StudyPoint& p, int n_points, double left_s) {
    std::string line = "[" + std::to_string(p.index + 1) + "/" + std::to_string(n_points) + "] " + p.description + ": ";
    if (!p.ok) {
        line += "FAILED: " + p.error;
    } else {
        line += p.f1_hz ? "f1 " + significant(*p.f1_hz) + " Hz" : "no bending mode";
        if (p.k) line += ", k " + significant(*p.k, 3);
        if (p.v_safe_m_s) line += ", v_safe " + significant(*p.v_safe_m_s, 3) + " m/s";
    }
    line += "  (" + significant(p.time_s, 3) + " s";
    if (left_s > 0) line += ", ~" + minutes_or_seconds(left_s) + " left";
    return line + ")";
}

}  // namespace

unsigned jobs_for(unsigned requested, const CaseSweep& sweep) {
    if (mpi_size() > 1) return 1;
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    return std::max(1u, std::min<unsigned>(requested ? requested : cores, static_cast<unsigned>(sweep.n_points())));
}

void run_point(Scene scene, StudyPoint& p) {
    Stopwatch watch;
    try {
        RunOptions run;
        run.quiet = true;
        run.write_results = false;
        // A point's k is f1 over I-7's f2 (derive_point_values): the FE
        // free-span solve would cost a third of a chuck point for nothing.
        run.chuck_factor_by_fe = false;
        const RunReport report = run_scene(std::move(scene), run);
        p.model_level = report.model.level;
        p.n_dofs = report.model.n_dofs;
        for (const Mode& m : report.modes.modes) p.modes.push_back({m.index, m.frequency_hz, m.label, m.signature});
        if (const double f1 = first_bending_hz(report); f1 > 0) p.f1_hz = f1;
        p.ok = true;
    } catch (const std::exception& e) {  // InputError, SolveError, PETSc: the point fails, the study goes on
        p.error = e.what();
    }
    p.time_s = watch.seconds();
}

void derive_point_values(StudyPoint& p, const Scene& scene, const SweepOptions& options) {
    p.supports = scene.supports.kind == SupportKind::free      ? "free"
                 : scene.supports.kind == SupportKind::clamped ? "clamped"
                                                               : "chucks";
    p.diameter_m = rest_roll_section(scene).Dp;
    if (!p.ok || !p.f1_hz || scene.supports.kind == SupportKind::free) return;  // not in a stand: no k, no v_safe
    p.v_safe_m_s = safe_web_speed(*p.f1_hz, p.diameter_m, options.safe_factor);
    if (const std::optional<ChuckFactorI7> c = chuck_factor_of(scene, *p.f1_hz)) {
        p.li_m = c->li_m, p.span_m = c->span_m, p.f_i7_hz = c->f_i7_hz, p.k = c->k;
        p.chuck_groups = calibration_groups(scene, c->li_m, c->span_m);
    }
}

StudyResult run_sweep(const CaseSweep& sweep, const StudyRunOptions& options, std::ostream& progress) {
    const bool say = mpi_rank() == 0 && !options.quiet;
    Stopwatch total;
    StudyResult result;
    const int n = sweep.n_points();
    result.points.resize(static_cast<size_t>(n));

    // Every point's scene first (milliseconds each): refused combinations are
    // reported before hours of solving, not after.
    std::vector<std::optional<Scene>> scenes(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        StudyPoint& p = result.points[static_cast<size_t>(i)];
        p.index = i;
        p.value_index = sweep.value_indices(i);
        p.description = sweep.describe(i);
        try {
            scenes[static_cast<size_t>(i)] = sweep.scene(i);
        } catch (const InputError& e) {
            p.error = e.what();
            if (say) progress << "  refused: " << p.error << std::endl;
        }
    }
    const int n_to_run = static_cast<int>(std::count_if(scenes.begin(), scenes.end(), [](auto& s) { return s.has_value(); }));
    if (n_to_run == 0)
        throw InputError("no point of the " + sweep.case_file() + " sweep can be read; the first: " +
                         result.points.front().error);

    std::vector<int> todo;
    for (int i = 0; i < n; ++i)
        if (scenes[static_cast<size_t>(i)]) todo.push_back(i);
    // Progress in the order the points finish; the time left from the mean
    // time of a point so far, spread over the jobs.
    int n_done = 0;
    double point_time = 0;
    const bool children = options.jobs > 1 && mpi_size() == 1 && todo.size() > 1 && sweep.from_file();
    const unsigned jobs = children ? std::min<unsigned>(options.jobs, static_cast<unsigned>(todo.size())) : 1;
    const auto finished = [&](int i) {
        StudyPoint& p = result.points[static_cast<size_t>(i)];
        derive_point_values(p, *scenes[static_cast<size_t>(i)], sweep.options());
        point_time += p.time_s;
        ++n_done;
        const double left = point_time / n_done * (n_to_run - n_done) / jobs;
        if (say) progress << "  " << progress_line(p, n, left) << std::endl;
    };
    if (children) {
        run_points_in_children(sweep, todo, jobs, options.program, result.points, finished);
    } else {
        for (int i : todo) {
            run_point(*scenes[static_cast<size_t>(i)], result.points[static_cast<size_t>(i)]);
            finished(i);
        }
    }
    result.time_s = total.seconds();
    return result;
}

StudyResult run_and_track(const CaseSweep& sweep, const std::string& command, const std::filesystem::path& out_dir,
                          bool quiet, unsigned jobs) {
    const bool root = mpi_rank() == 0;
    const unsigned n_jobs = jobs_for(jobs, sweep);
    if (root && !quiet)
        std::cout << command << ": " << sweep.n_points() << " points of " << sweep.case_file() << " (mesh "
                  << (sweep.options().mesh_level.empty() ? "of the case" : sweep.options().mesh_level) << ", "
                  << (sweep.options().modes ? std::to_string(sweep.options().modes) + " modes" : std::string("modes of the case"))
                  << " each, " << n_jobs << " at a time); results in " << out_dir.string() << std::endl;
    StudyResult result = run_sweep(sweep, {quiet, n_jobs}, std::cout);
    if (root) track_modes(sweep, result);
    return result;
}

void track_modes(const CaseSweep& sweep, StudyResult& result) {
    int next_track = 1;
    for (StudyPoint& p : result.points) {
        if (!p.ok) continue;
        p.groups = group_modes(p.modes);
        std::optional<int> from = sweep.predecessor(p.index);
        while (from && !result.points[static_cast<size_t>(*from)].ok) from = sweep.predecessor(*from);
        p.predecessor = from;
        if (!from) {
            p.tracks = start_tracks(p.groups, next_track);
            continue;
        }
        const StudyPoint& q = result.points[static_cast<size_t>(*from)];
        std::vector<int> previous_tracks;
        for (const TrackStep& s : q.tracks) previous_tracks.push_back(s.track);
        p.tracks = follow_tracks(q.groups, previous_tracks, p.groups, next_track);
    }
}

// ---- study.csv and study.json ----------------------------------------------

namespace {

// Column suffix of a parameter in SI ("_m", "_Pa"); "" for plain numbers and text.
std::string unit_suffix(const SweepParameter& p) {
    if (!p.numeric) return "";
    switch (p.dimension) {
        case Dimension::length: return "_m";
        case Dimension::pressure: return "_Pa";
        case Dimension::density: return "_kg_m3";
        case Dimension::frequency: return "_hz";
        case Dimension::stiffness_per_area: return "_N_m3";
        case Dimension::angle: return "_rad";
        case Dimension::speed: return "_m_s";
        case Dimension::mass: return "_kg";
        case Dimension::stiffness: return "_N_m";
        case Dimension::rotational_stiffness: return "_N_m_rad";
        case Dimension::dimensionless: return "";
    }
    return "";
}

std::string number(double v) { return significant(v, 10); }
std::string number(const std::optional<double>& v) { return v ? number(*v) : ""; }

std::string parameter_cells(const CaseSweep& sweep, const StudyPoint& p) {
    std::string out;
    for (size_t j = 0; j < sweep.parameters().size(); ++j) {
        const SweepParameter& par = sweep.parameters()[j];
        const int v = p.value_index[j];
        out += ',';
        out += par.numeric ? number(par.si[static_cast<size_t>(v)]) : csv_field(par.labels[static_cast<size_t>(v)]);
    }
    return out;
}

std::string point_cells(const StudyPoint& p) {
    return number(p.f1_hz) + "," + number(p.k) + "," + number(p.li_m) + "," + number(p.span_m) + "," +
           number(p.f_i7_hz) + "," + number(p.diameter_m) + "," + number(p.v_safe_m_s) + "," +
           (p.ok ? std::to_string(p.n_dofs) : std::string()) + "," + number(p.time_s);
}

}  // namespace

std::string parameter_column(const SweepParameter& p) { return p.name + unit_suffix(p); }

std::string study_csv(const CaseSweep& sweep, const StudyResult& result) {
    std::ostringstream out;
    out << "point";
    for (const SweepParameter& p : sweep.parameters()) out << "," << csv_field(parameter_column(p));
    out << ",status,predecessor,track,label,type,n,m,multiplicity,frequency_hz,mac_previous,ambiguous,new_track,"
           "f1_hz,k,li_m,span_m,f_i7_hz,diameter_m,v_safe_m_s,n_dofs,time_s,error\n";
    for (const StudyPoint& p : result.points) {
        const std::string head = std::to_string(p.index + 1) + parameter_cells(sweep, p);
        if (!p.ok) {
            out << head << ",failed,,,,,,,,,,,," << point_cells(p) << "," << csv_field(p.error) << "\n";
            continue;
        }
        const std::string from = p.predecessor ? std::to_string(*p.predecessor + 1) : "";
        for (size_t k = 0; k < p.groups.size(); ++k) {
            const ModeGroup& grp = p.groups[k];
            const TrackStep& t = p.tracks[k];
            out << head << ",ok," << from << "," << t.track << "," << csv_field(label_text(grp.label)) << ","
                << grp.label.type << "," << grp.label.n << "," << grp.label.m << "," << grp.members.size() << ","
                << number(grp.frequency_hz) << "," << number(t.mac_previous) << "," << (t.ambiguous ? 1 : 0) << ","
                << (t.new_track ? 1 : 0) << "," << point_cells(p) << ",\n";
        }
    }
    return out.str();
}

std::vector<int> diameter_parameters(const CaseSweep& sweep, const StudyResult& result) {
    // Relative change of the diameter that counts as a change.
    constexpr double kDiameterChange = 1e-9;
    std::vector<int> out;
    const auto& points = result.points;
    for (size_t j = 0; j < sweep.parameters().size(); ++j) {
        bool changes = false;
        for (size_t a = 0; a < points.size() && !changes; ++a)
            for (size_t b = a + 1; b < points.size() && !changes; ++b) {
                if (!points[a].ok || !points[b].ok) continue;
                bool only_j = points[a].value_index[j] != points[b].value_index[j];
                for (size_t q = 0; q < sweep.parameters().size(); ++q)
                    if (q != j && points[a].value_index[q] != points[b].value_index[q]) only_j = false;
                if (only_j && std::abs(points[a].diameter_m - points[b].diameter_m) >
                                  kDiameterChange * std::max(points[a].diameter_m, points[b].diameter_m))
                    changes = true;
            }
        if (changes) out.push_back(static_cast<int>(j));
    }
    return out;
}

std::string study_json(const CaseSweep& sweep, const StudyResult& result, const std::string& kind) {
    toml::array parameters;
    for (const SweepParameter& p : sweep.parameters()) {
        toml::array keys, labels, values;
        for (const auto& k : p.keys) keys.push_back(k);
        for (const auto& l : p.labels) labels.push_back(l);
        for (double v : p.si) values.push_back(v);
        parameters.push_back(toml::table{{"name", p.name},
                                         {"column", parameter_column(p)},
                                         {"keys", keys},
                                         {"numeric", p.numeric},
                                         {"unit", p.numeric ? si_unit(p.dimension) : ""},
                                         {"labels", labels},
                                         {"values", values}});
    }
    toml::array diameter;
    for (int j : diameter_parameters(sweep, result)) diameter.push_back(sweep.parameters()[static_cast<size_t>(j)].name);
    const SweepOptions& o = sweep.options();
    toml::table options{{"mesh", o.mesh_level.empty() ? "(the case's own [mesh])" : o.mesh_level},
                        {"modes", o.modes},  // 0: the case's own [analysis]
                        {"safe_factor", o.safe_factor}};
    if (o.web_speed_m_s) options.insert("web_speed_m_s", *o.web_speed_m_s);
    toml::table t{{"kind", kind},
                  {"case", sweep.case_name()},
                  {"case_file", sweep.case_file()},
                  {"n_points", sweep.n_points()},
                  {"n_failed", result.n_failed()},
                  {"time_s", result.time_s},
                  {"parameters", parameters},
                  {"diameter_parameters", diameter},
                  {"options", options}};
    std::ostringstream out;
    out << toml::json_formatter{t} << "\n";
    return out.str();
}

// ---- König's chart: where v_safe crosses the web speed -----------------------

std::vector<SpeedCrossing> safe_speed_crossings(const CaseSweep& sweep, const StudyResult& result,
                                                double web_speed_m_s) {
    const std::vector<int> diameter = diameter_parameters(sweep, result);
    if (diameter.empty()) return {};
    const auto is_diameter = [&](size_t j) { return std::count(diameter.begin(), diameter.end(), int(j)) > 0; };
    // Curves: the points that share the values of every other parameter.
    std::map<std::vector<int>, std::vector<const StudyPoint*>> curves;
    for (const StudyPoint& p : result.points) {
        if (!p.ok || !p.v_safe_m_s) continue;
        std::vector<int> key;
        for (size_t j = 0; j < p.value_index.size(); ++j) key.push_back(is_diameter(j) ? -1 : p.value_index[j]);
        curves[key].push_back(&p);
    }
    std::vector<SpeedCrossing> out;
    for (auto& [key, pts] : curves) {
        std::sort(pts.begin(), pts.end(), [](auto* a, auto* b) { return a->diameter_m < b->diameter_m; });
        SpeedCrossing c;
        for (size_t j = 0; j < key.size(); ++j)
            if (key[j] >= 0)
                c.curve += (c.curve.empty() ? "" : ", ") + sweep.parameters()[j].name + " = " +
                           sweep.parameters()[j].labels[static_cast<size_t>(key[j])];
        c.d_min_m = pts.front()->diameter_m, c.d_max_m = pts.back()->diameter_m;
        c.v_min_m_s = c.v_max_m_s = *pts.front()->v_safe_m_s;
        for (const StudyPoint* p : pts)
            c.v_min_m_s = std::min(c.v_min_m_s, *p->v_safe_m_s), c.v_max_m_s = std::max(c.v_max_m_s, *p->v_safe_m_s);
        for (size_t i = 0; i + 1 < pts.size(); ++i) {
            const double d0 = pts[i]->diameter_m, d1 = pts[i + 1]->diameter_m;
            const double v0 = *pts[i]->v_safe_m_s, v1 = *pts[i + 1]->v_safe_m_s;
            // The roll becomes unsafe as paper is used up: v_safe falls below the web speed as D falls.
            if (v0 < web_speed_m_s && v1 >= web_speed_m_s && d1 > d0)
                c.change_diameters_m.push_back(d0 + (web_speed_m_s - v0) * (d1 - d0) / (v1 - v0));
        }
        out.push_back(std::move(c));
    }
    return out;
}

// ---- plots and report ------------------------------------------------------

StudyFiles write_study_files(const fs::path& dir, const CaseSweep& sweep, const StudyResult& result,
                             const std::string& kind, bool plots) {
    write_text_file(dir / "study.csv", study_csv(sweep, result));
    write_text_file(dir / "study.json", study_json(sweep, result, kind));
    StudyFiles files;
    files.plot_problem = plots ? run_python_plot("study-plot", dir) : "switched off (--no-plots)";
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".png") files.pngs.push_back(entry.path().filename().string());
    std::sort(files.pngs.begin(), files.pngs.end());
    return files;
}

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
           "subspace (docs/studies.md).\n\n| track | label (first point) | points | f min [Hz] | f max [Hz] | "
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
    report_tracks(out, r);
    report_failures(out, r);
    out << "## Plots\n\n";
    if (!plot_problem.empty()) out << "Plots were not drawn: " << plot_problem << ".\n\n";
    for (const std::string& png : pngs) out << "![" << png << "](" << png << ")\n\n";
    out << "Files: `study.csv` (one row per point and tracked mode), `study.json` (the study's parameters), this "
           "report.\n";
    return out.str();
}

}  // namespace coremodal
