// The tables, summary.json, report.md and console lines of `coremodal select`.
#include "output/selection_report.hpp"

#include "common/format.hpp"
#include "output/csv.hpp"
#include "output/summary_json.hpp"
#include "output/text_file.hpp"

#include <sstream>

namespace coremodal {
namespace {

constexpr const char* kPaper = "M. Ilomäki, \"On the durability of cores and rest roll dynamics\"";

std::string g(double v, int digits = 5) { return significant(v, digits); }
std::string width_text(double w) { return w >= kMaxSelectionWidth ? ">= " + g(kMaxSelectionWidth) : g(w, 4); }
std::string yes_no(bool b) { return b ? "yes" : "no"; }

// kg of reel per metre of width at the chart's diameter.
double reel_mass_per_width(const SelectionScene& s, const Stand& st, const CoreGrade& c) {
    return paper_roll_mass(c, st.roll_diameter, 1.0, s.paper_density);
}

std::string selection_csv(const SelectionScene& s, const SelectionResult& r) {
    std::ostringstream out;
    out << "stand,core,test_chuck_weight_kN,chuck_scale,winder_factor,max_roll_weight_kN,max_roll_mass_kg,"
           "speed_width_m,speed_criterion,next_criterion,next_speed_m_s,stiffness_factor,i7_width_m,weight_width_m,max_width_m,governing,"
           "reel_mass_kg_per_m,core_mass_kg_per_m,price_per_m\n";
    for (std::size_t i = 0; i < s.stands.size(); ++i)
        for (std::size_t j = 0; j < s.cores.size(); ++j) {
            const CoreInStand& c = r.table[i][j];
            if (!c.fits) continue;
            out << csv_field(s.stands[i].name) << "," << csv_field(s.cores[j].name) << ","
                << g(c.weight.test_chuck_weight_n / 1e3, 6) << "," << g(c.weight.chuck_scale, 6) << ","
                << g(c.weight.winder_factor, 6) << "," << g(c.weight.weight_n / 1e3, 6) << "," << g(c.max_mass_kg, 6)
                << "," << g(c.speed_width_m, 6) << "," << csv_field(c.speed_verdict.governing) << ","
                << csv_field(c.speed_verdict.next) << "," << g(c.speed_verdict.next_speed_m_s, 6) << ","
                << g(c.speed_verdict.stiffness_factor, 6) << "," << g(c.i7_width_m, 6) << "," << g(c.weight_width_m, 6) << "," << g(c.max_width_m, 6) << ","
                << c.governing << "," << g(reel_mass_per_width(s, s.stands[i], s.cores[j]), 6) << "," << g(c.core_mass_per_m, 6)
                << "," << (s.cores[j].price_per_m ? g(*s.cores[j].price_per_m, 6) : "") << "\n";
        }
    return out.str();
}

std::string reels_csv(const SelectionScene& s, const SelectionResult& r) {
    std::ostringstream out;
    out << "reel,stand,width_m,diameter_m,web_speed_m_s,core,reel_mass_kg,max_roll_mass_kg,weight_ok,safe_speed_m_s,"
           "speed_criterion,speed_ok,passes\n";
    for (std::size_t k = 0; k < s.reels.size(); ++k) {
        const Reel& reel = s.reels[k];
        const ReelCheck& c = r.reels[k];
        for (std::size_t j = 0; j < s.cores.size(); ++j) {
            const ReelVerdict& v = c.cores[j];
            if (!v.fits) continue;
            out << k + 1 << "," << csv_field(reel.stand) << "," << g(reel.width, 6) << "," << g(reel.diameter, 6) << ","
                << g(c.web_speed, 6) << "," << csv_field(s.cores[j].name) << "," << g(v.mass_kg, 6) << ","
                << g(r.table[c.stand][j].max_mass_kg, 6) << "," << yes_no(v.weight_ok) << ","
                << g(v.safe_speed_m_s, 6) << "," << csv_field(v.speed_governing) << "," << yes_no(v.speed_ok) << "," << yes_no(v.passes()) << "\n";
        }
    }
    return out.str();
}

Json stand_cores_json(const SelectionScene& s, const SelectionResult& r, std::size_t i) {
    Json cores = Json::array();
    for (std::size_t j = 0; j < s.cores.size(); ++j) {
            const CoreInStand& c = r.table[i][j];
            if (!c.fits) continue;
            cores.push_back(Json{{"core", s.cores[j].name},
                             {"method", c.weight.method},
                             {"test_chuck_weight_n", c.weight.test_chuck_weight_n},
                             {"chuck_scale", c.weight.chuck_scale},
                             {"winder_factor", c.weight.winder_factor},
                             {"max_roll_weight_n", c.weight.weight_n},
                             {"max_roll_mass_kg", c.max_mass_kg},
                             {"speed_width_m", c.speed_width_m},
                             {"speed_criterion", c.speed_verdict.governing},
                             {"next_criterion", c.speed_verdict.next},
                             {"next_speed_m_s", c.speed_verdict.next_speed_m_s},
                             {"stiffness_factor", c.speed_verdict.stiffness_factor},
                             {"i7_width_m", c.i7_width_m},
                             {"weight_width_m", c.weight_width_m},
                             {"max_width_m", c.max_width_m},
                             {"governing", c.governing}});
    }
    return cores;
}

Json reels_json(const SelectionScene& s, const SelectionResult& r) {
    Json reels = Json::array();
    for (std::size_t k = 0; k < s.reels.size(); ++k) {
        const ReelCheck& c = r.reels[k];
        Json passing = Json::array();
        for (std::size_t j = 0; j < s.cores.size(); ++j)
            if (c.cores[j].passes()) passing.push_back(s.cores[j].name);
        reels.push_back(Json{{"stand", s.reels[k].stand},
                         {"width_m", s.reels[k].width},
                         {"diameter_m", s.reels[k].diameter},
                         {"web_speed_m_s", c.web_speed},
                         {"passing_cores", passing},
                         {"lightest", c.lightest ? Json(s.cores[*c.lightest].name) : Json()},
                         {"cheapest", c.cheapest ? Json(s.cores[*c.cheapest].name) : Json()}});
    }
    return reels;
}

std::string summary_json(const SelectionScene& s, const SelectionResult& r, double seconds) {
    Json stands = Json::array();
    for (std::size_t i = 0; i < s.stands.size(); ++i) {
        const Stand& st = s.stands[i];
        stands.push_back(Json{{"name", st.name},
                          {"chuck_length_m", st.chuck_length},
                          {"li_m", st.li},
                          {"chuck_factor", st.chuck_factor},
                          {"web_speed_m_s", st.web_speed},
                          {"safe_factor", st.safe_factor},
                          {"amplitude_limit_m", st.amplitude_limit},
                          {"winder", st.winder},
                          {"centre_winder_factor", st.centre_winder_factor},
                          {"chuck_length_exponent", st.chuck_length_exponent},
                          {"rest_roll_diameter_m", st.rest_roll_diameter},
                          {"roll_diameter_m", st.roll_diameter},
                          {"cores", stand_cores_json(s, r, i)}});
    }
    // The same head as every command's summary.json (output/summary_json.hpp).
    Json j = summary_head("select", s.name, s.source, s.description);
    j["source"] = kPaper;
    j["failure_probability"] = s.failure_probability;
    j["confidence"] = s.confidence;
    j["cycles"] = s.cycles;
    j["paper_density_kg_m3"] = s.paper_density;
    j["width_criterion"] = "the limits verdict at the beam level, calibrated to the stand's chuck factor k";
    j["width_assumptions"] = string_array(r.assumptions);
    j["defaults_used"] = string_array(s.defaults);
    j["stands"] = stands;
    j["reels"] = reels_json(s, r);
    j["timing_s"] = Json{{"total", seconds}};
    return json_text(j);
}

// One stand's section of report.md: its inputs and the table of its cores.
void stand_markdown(std::ostream& md, const SelectionScene& s, const SelectionResult& r, std::size_t i) {
    const Stand& st = s.stands[i];
    md << "\n## Stand " << st.name << "\n\n"
       << g(st.chuck_length * 1e3, 4) << " mm unwinder chucks (li = " << g(st.li * 1e3, 4) << " mm, k = "
       << g(st.chuck_factor, 3) << "), " << st.winder << " winder (factor " << g(st.winder_factor(), 3)
       << "), chuck-length exponent " << g(st.chuck_length_exponent, 3) << ", " << g(st.web_speed, 4)
       << " m/s, safe factor " << g(st.safe_factor, 3) << ", amplitude limit ±"
       << g(st.amplitude_limit * 1e3, 3) << " mm, rest roll " << g(st.rest_roll_diameter * 1e3, 4)
       << " mm, reels of " << g(st.roll_diameter * 1e3, 4) << " mm.\n\n| core | weight at the test chuck [kN] | x chuck | x winder | max roll [kN] | max roll [kg] | "
          "width for the speed [m] | speed criterion there (next, m/s) | E_z factor | I-7 alone [m] | width for the weight [m] | "
          "max reel width [m] | governed by | method |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (std::size_t j = 0; j < s.cores.size(); ++j) {
        const CoreInStand& c = r.table[i][j];
        if (!c.fits) continue;
        md << "| " << s.cores[j].name << " | " << g(c.weight.test_chuck_weight_n / 1e3, 4) << " | "
           << g(c.weight.chuck_scale, 4) << " | " << g(c.weight.winder_factor, 3) << " | "
           << g(c.weight.weight_n / 1e3, 4) << " | " << g(c.max_mass_kg, 4) << " | " << width_text(c.speed_width_m)
           << " | " << c.speed_verdict.governing << " (" << c.speed_verdict.next << " "
           << g(c.speed_verdict.next_speed_m_s, 4) << ") | " << g(c.speed_verdict.stiffness_factor, 4) << " | "
           << width_text(c.i7_width_m) << " | " << g(c.weight_width_m, 4) << " | " << width_text(c.max_width_m) << " | " << c.governing
           << " | " << c.weight.method << " |\n";
    }
}

// The reels asked, one row each, a column per core.
void reels_markdown(std::ostream& md, const SelectionScene& s, const SelectionResult& r) {
    md << "\n## The reels asked\n\n| reel | stand | width [m] | diameter [mm] | speed [m/s] |";
    for (const CoreGrade& c : s.cores) md << " " << c.name << " |";
    md << " lightest | cheapest |\n|---|---|---|---|---|";
    for (std::size_t j = 0; j < s.cores.size() + 2; ++j) md << "---|";
    md << "\n";
    for (std::size_t k = 0; k < s.reels.size(); ++k) {
        const ReelCheck& c = r.reels[k];
        md << "| " << k + 1 << " | " << s.reels[k].stand << " | " << g(s.reels[k].width, 4) << " | "
           << g(s.reels[k].diameter * 1e3, 4) << " | " << g(c.web_speed, 4) << " |";
        for (const ReelVerdict& v : c.cores)
            if (!v.fits) md << " does not fit the chucks |";
            else md << " " << (v.passes() ? "passes" : std::string("fails:") + (v.weight_ok ? "" : " weight") +
                                                      (v.speed_ok ? "" : " speed (" + v.speed_governing + ")"))
               << " (" << g(v.mass_kg, 4) << " kg) |";
        md << " " << (c.lightest ? s.cores[*c.lightest].name : "-") << " | "
           << (c.cheapest ? s.cores[*c.cheapest].name : "-") << " |\n";
    }
}

}  // namespace

void write_selection_tables(const std::filesystem::path& dir, const SelectionScene& scene, const SelectionResult& r,
                            double seconds) {
    write_text_file(dir / "selection.csv", selection_csv(scene, r));
    write_text_file(dir / "reels.csv", reels_csv(scene, r));
    write_text_file(dir / "summary.json", summary_json(scene, r, seconds));
}

std::vector<std::string> selection_console_lines(const SelectionScene& s, const SelectionResult& r) {
    std::vector<std::string> lines;
    for (const std::string& a : r.assumptions) lines.push_back("assumed: " + a);
    for (std::size_t i = 0; i < s.stands.size(); ++i) {
        const Stand& st = s.stands[i];
        lines.push_back("stand " + st.name + ": " + g(st.chuck_length * 1e3, 4) + " mm chucks (k = " +
                        g(st.chuck_factor, 3) + "), " + st.winder + " winder, " + g(st.web_speed, 4) +
                        " m/s, safe factor " + g(st.safe_factor, 3) + ", rest roll " +
                        g(st.rest_roll_diameter * 1e3, 4) + " mm");
        for (std::size_t j = 0; j < s.cores.size(); ++j) {
            const CoreInStand& c = r.table[i][j];
            if (!c.fits) continue;
            lines.push_back("  core " + s.cores[j].name + ": max roll " + g(c.max_mass_kg, 4) + " kg (" +
                            g(c.weight.weight_n / 1e3, 4) + " kN), width for the speed " + width_text(c.speed_width_m) +
                            " m (" + c.speed_verdict.governing + "; I-7 alone " + width_text(c.i7_width_m) +
                            " m), for the weight at " + g(st.roll_diameter * 1e3, 4) + " mm " +
                            g(c.weight_width_m, 4) + " m: max reel width " + width_text(c.max_width_m) + " m (" +
                            c.governing + ")");
        }
    }
    for (std::size_t k = 0; k < s.reels.size(); ++k) {
        const ReelCheck& c = r.reels[k];
        std::string line = "reel " + std::to_string(k + 1) + " (" + s.reels[k].stand + ", " + g(s.reels[k].width, 4) +
                           " m x " + g(s.reels[k].diameter * 1e3, 4) + " mm, " + g(c.web_speed, 4) + " m/s): ";
        std::string passing;
        for (std::size_t j = 0; j < s.cores.size(); ++j)
            if (c.cores[j].passes()) passing += (passing.empty() ? "" : ", ") + s.cores[j].name;
        line += passing.empty() ? "no core passes" : "passes " + passing;
        if (c.lightest) line += "; lightest " + s.cores[*c.lightest].name;
        if (c.cheapest) line += "; cheapest " + s.cores[*c.cheapest].name;
        lines.push_back(line);
    }
    return lines;
}

std::string selection_report_markdown(const SelectionScene& s, const SelectionResult& r,
                                      const std::vector<std::string>& pngs, const std::string& plot_problem) {
    std::ostringstream md;
    md << "# Core selection: " << s.name << "\n\n"
       << "Which core grade carries which reel in which stand, after " << kPaper
       << " (durability {16}-{32}; the chart in the form of Figs. 18-19). docs/how-to/durability.md, \"Choosing a core\".\n\n"
       << "- failure probability P = " << g(s.failure_probability) << ", confidence C = " << g(100 * s.confidence, 4)
       << " %, " << g(s.cycles) << " winding-unwinding cycle(s)\n"
       << "- reel weight from the stand's roll diameter, paper " << g(s.paper_density, 4)
       << " kg/m^3 (core included)\n"
       << "- width search: the widest reel whose rest roll passes the `coremodal limits` verdict against the web "
          "speed (bracketed to " << g(kWidthTolerance * 1e3, 2) << " mm); \"I-7 alone\" is I-5 with I-7 and k, "
          "the quick estimate\n"
       << "- weight limit: the core's reduced durability curve at the test chuck, times (stand chuck / test "
          "chuck)^exponent, times the winder factor\n";
    for (const std::string& a : r.assumptions) md << "- " << a << "\n";
    if (!s.defaults.empty()) {
        md << "\nDefaults used (not in the file):\n\n";
        for (const std::string& d : s.defaults) md << "- `" << d << "`\n";
    }
    for (std::size_t i = 0; i < s.stands.size(); ++i) stand_markdown(md, s, r, i);
    if (!s.reels.empty()) reels_markdown(md, s, r);
    md << "\n## Chart\n\n";
    for (const std::string& p : pngs) md << "![" << p << "](" << p << ")\n";
    if (pngs.empty()) md << "No picture: " << plot_problem << "\n";
    md << "\nFiles: selection.csv, reels.csv, summary.json.\n";
    return md.str();
}

}  // namespace coremodal
