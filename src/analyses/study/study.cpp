// The study driver: points in, tracked modes out (the study's files:
// output/study_report.hpp).
#include "analyses/study/study.hpp"

#include "analyses/study/study_workers.hpp"
#include "analyses/run/run.hpp"
#include "beam/beam_theory.hpp"
#include "beam/chuck_calibration.hpp"
#include "beam/formulas.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/petsc_handle.hpp"
#include "common/stopwatch.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <ostream>
#include <thread>

namespace coremodal {

int StudyResult::n_failed() const {
    return static_cast<int>(std::count_if(points.begin(), points.end(), [](const StudyPoint& p) { return !p.ok; }));
}

namespace {

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
        if (p.response)
            line += p.response->v_limit_m_s ? ", +-" + significant(p.response->limit_m * 1e3, 3) + " mm at " +
                                                  significant(*p.response->v_limit_m_s, 3) + " m/s"
                                            : ", +-" + significant(p.response->limit_m * 1e3, 3) + " mm not reached";
    }
    line += "  (" + significant(p.time_s, 3) + " s";
    if (left_s > 0) line += ", ~" + minutes_or_seconds(left_s) + " left";
    return line + ")";
}

}  // namespace

std::optional<ResponseSetup> response_of_point(const std::string& table, std::optional<ResponseSetup> response) {
    return table == "study" ? std::move(response) : std::nullopt;
}

unsigned jobs_for(unsigned requested, const CaseSweep& sweep) {
    if (mpi_size() > 1) return 1;
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    return std::max(1u, std::min<unsigned>(requested ? requested : cores, static_cast<unsigned>(sweep.n_points())));
}

StudyResponse study_response(const ResponseResult& r) {
    StudyResponse out;
    out.limit_m = r.limit_m;
    out.max_web_speed_m_s = r.points.back().web_speed_m_s;
    out.limit_reached = r.safe.reached, out.below_range = r.safe.below_range;
    if (r.safe.reached) out.v_limit_m_s = r.safe.web_speed_m_s, out.implied_factor = r.safe.implied_factor;
    out.max_amplitude_m = r.max_amplitude_m, out.max_amplitude_web_speed_m_s = r.max_amplitude_web_speed_m_s;
    for (const SafeSpeed& s : r.speeds_at_rest.safe) {
        if (s.safe == kSafeFactors[0]) out.v_i5_07_m_s = s.v_safe_m_s;
        if (s.safe == kSafeFactors[1]) out.v_i5_08_m_s = s.v_safe_m_s;
    }
    if (r.speeds_at_rest.koenig) out.v_koenig_m_s = r.speeds_at_rest.koenig->speed.v_krit_m_s;
    return out;
}

void run_point(Scene scene, StudyPoint& p, const std::optional<ResponseSetup>& response) {
    Stopwatch watch;
    try {
        // The forced response first, on its own copy of the scene: run_scene takes it.
        if (response) p.response = study_response(run_forced_response(scene, *response));
        RunOptions run;
        run.quiet = true;
        run.write_results = false;
        // A point's k is f1 over I-7's f2 (derive_point_values): the FE
        // free-span solve would cost a third of a chuck point for nothing.
        run.chuck_factor_by_fe = false;
        const RunReport report = run_scene(std::move(scene), run);
        p.model_level = to_string(report.model.level);
        p.n_dofs = report.model.n_dofs;
        for (const Mode& m : report.modes.modes) p.modes.push_back({m.index, m.frequency_hz, m.label, m.signature});
        if (const double f1 = first_bending_hz(report); f1 > 0) p.f1_hz = f1;
        p.ok = true;
    } catch (const std::exception& e) {  // InputError, SolveError, PETSc: the point fails, the study goes on
        p.error = e.what();
        p.response.reset();
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
    std::vector<std::optional<ResponseSetup>> responses(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        StudyPoint& p = result.points[static_cast<size_t>(i)];
        p.index = i;
        p.value_index = sweep.value_indices(i);
        p.description = sweep.describe(i);
        try {
            ResponseCase c = sweep.response_case(i);
            scenes[static_cast<size_t>(i)] = std::move(c.scene);
            responses[static_cast<size_t>(i)] = response_of_point(sweep.table(), std::move(c.response));
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
            run_point(*scenes[static_cast<size_t>(i)], result.points[static_cast<size_t>(i)], responses[static_cast<size_t>(i)]);
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

}  // namespace coremodal
