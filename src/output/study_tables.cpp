// study.csv, study.json and the study's folder (output/study_report.hpp).
#include "output/study_report.hpp"

#include "common/format.hpp"
#include "output/csv.hpp"
#include "output/python_plots.hpp"
#include "output/summary_json.hpp"
#include "output/text_file.hpp"


#include <algorithm>
#include <sstream>

namespace coremodal {

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
        case Dimension::unbalance: return "_kg_m";
        case Dimension::line_force: return "_N_m";
        case Dimension::viscosity: return "_Pa_s";
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

// The forced response's columns (empty without [response]).
constexpr const char* kResponseColumns =
    "amplitude_limit_m,amplitude_limit_reached,v_amplitude_limit_m_s,amplitude_implied_factor,response_max_web_speed_m_s,"
    "max_amplitude_m,max_amplitude_web_speed_m_s,v_i5_07_m_s,v_i5_08_m_s,v_koenig_m_s";

std::string response_cells(const std::optional<StudyResponse>& r) {
    if (!r) return ",,,,,,,,,";
    return number(r->limit_m) + "," + (r->limit_reached ? "1" : "0") + "," + number(r->v_limit_m_s) + "," +
           number(r->implied_factor) + "," + number(r->max_web_speed_m_s) + "," + number(r->max_amplitude_m) + "," +
           number(r->max_amplitude_web_speed_m_s) + "," + number(r->v_i5_07_m_s) + "," + number(r->v_i5_08_m_s) + "," +
           number(r->v_koenig_m_s);
}

std::string point_cells(const StudyPoint& p) {
    return number(p.f1_hz) + "," + number(p.k) + "," + number(p.li_m) + "," + number(p.span_m) + "," +
           number(p.f_i7_hz) + "," + number(p.diameter_m) + "," + number(p.v_safe_m_s) + "," +
           (p.ok ? std::to_string(p.n_dofs) : std::string()) + "," + number(p.time_s) + "," + response_cells(p.response);
}

}  // namespace

std::string parameter_column(const SweepParameter& p) { return p.name + unit_suffix(p); }

std::string study_csv(const CaseSweep& sweep, const StudyResult& result) {
    std::ostringstream out;
    out << "point";
    for (const SweepParameter& p : sweep.parameters()) out << "," << csv_field(parameter_column(p));
    out << ",status,predecessor,track,label,type,n,m,multiplicity,frequency_hz,mac_previous,ambiguous,new_track,"
           "f1_hz,k,li_m,span_m,f_i7_hz,diameter_m,v_safe_m_s,n_dofs,time_s,"
        << kResponseColumns << ",error\n";
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

std::string study_json(const CaseSweep& sweep, const StudyResult& result, const std::string& kind) {
    Json parameters = Json::array();
    for (const SweepParameter& p : sweep.parameters()) {
        Json keys = Json::array(), labels = Json::array(), values = Json::array();
        for (const auto& k : p.keys) keys.push_back(k);
        for (const auto& l : p.labels) labels.push_back(l);
        for (double v : p.si) values.push_back(v);
        parameters.push_back(Json{{"name", p.name},
                                         {"column", parameter_column(p)},
                                         {"keys", keys},
                                         {"numeric", p.numeric},
                                         {"unit", p.numeric ? si_unit(p.dimension) : ""},
                                         {"labels", labels},
                                         {"values", values}});
    }
    Json diameter = Json::array();
    for (int j : diameter_parameters(sweep, result)) diameter.push_back(sweep.parameters()[static_cast<size_t>(j)].name);
    const SweepOptions& o = sweep.options();
    Json options{{"mesh", o.mesh_level.empty() ? "(the case's own [mesh])" : o.mesh_level},
                        {"modes", o.modes},  // 0: the case's own [analysis]
                        {"safe_factor", o.safe_factor}};
    if (o.web_speed_m_s) options["web_speed_m_s"] = (*o.web_speed_m_s);
    // Whether the points ran the forced response (the case has [response]).
    const bool response = std::any_of(result.points.begin(), result.points.end(),
                                      [](const StudyPoint& p) { return p.response.has_value(); });
    Json t = summary_head(kind == "calibration" ? "calibrate" : "study", sweep.case_name(), sweep.case_file(), "");
    t["kind"] = kind;
    t["n_points"] = sweep.n_points();
    t["n_failed"] = result.n_failed();
    t["parameters"] = parameters;
    t["diameter_parameters"] = diameter;
    t["options"] = options;
    t["response"] = response;
    t["timing_s"] = Json{{"total", result.time_s}};
    return json_text(t);
}

StudyFiles write_study_files(const std::filesystem::path& dir, const CaseSweep& sweep, const StudyResult& result,
                             const std::string& kind, bool plots) {
    write_text_file(dir / "study.csv", study_csv(sweep, result));
    write_text_file(dir / "study.json", study_json(sweep, result, kind));
    StudyFiles files;
    files.plot_problem = plots ? run_python_plot("study-plot", dir) : "switched off (--no-plots)";
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.path().extension() == ".png") files.pngs.push_back(entry.path().filename().string());
    std::sort(files.pngs.begin(), files.pngs.end());
    return files;
}

}  // namespace coremodal
