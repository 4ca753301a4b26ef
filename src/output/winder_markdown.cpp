// report.md and the console lines of `coremodal winder`.
#include "common/format.hpp"
#include "output/winder_report.hpp"
#include "scene/units.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace coremodal {
namespace {

// Diameters shown in the report's per-diameter tables at most: the first,
// the last and evenly spread ones between (the CSV and JSON hold them all).
constexpr int kTableRows = 7;

std::string hz(double f) { return formatted("%.3f", f); }

std::vector<size_t> table_rows(size_t n) {
    std::vector<size_t> rows;
    const size_t shown = std::min<size_t>(n, kTableRows);
    for (size_t i = 0; i < shown; ++i) {
        const size_t row = shown == 1 ? 0 : (i * (n - 1) + (shown - 1) / 2) / (shown - 1);
        if (rows.empty() || rows.back() != row) rows.push_back(row);
    }
    return rows;
}

void scene_section(std::ostringstream& md, const WinderScene& s, const WinderSweepResult& r) {
    const WinderDrums& d = s.drums;
    const WinderRolls& rl = s.rolls;
    md << "## The scene\n\n| part | values |\n|---|---|\n";
    md << "| drums (front, rear) | " << millimetres(d.outer_diameter) << " x " << millimetres(d.wall) << " wall, "
       << significant(d.length) << " m bearing to bearing, " << d.material << ", bearings "
       << format_quantity(d.bearing_stiffness_vertical, Dimension::stiffness) << " vertical / "
       << format_quantity(d.bearing_stiffness_horizontal, Dimension::stiffness) << " horizontal, gap "
       << millimetres(d.gap) << " |\n";
    md << "| rolls | " << rl.count << " x " << significant(rl.width) << " m (" << roll_model_name(rl.model)
       << "), core " << millimetres(rl.core_inner_diameter) << " / " << millimetres(rl.core_outer_diameter)
       << ", paper " << significant(rl.paper_density) << " kg/m^3, radial modulus "
       << format_quantity(rl.radial_modulus, Dimension::pressure) << ", nu " << significant(rl.poisson) << ", d from "
       << millimetres(rl.diameter_start) << " to " << millimetres(rl.diameter_end) << " |\n";
    md << "| rider | " << millimetres(s.rider.outer_diameter) << " x " << millimetres(s.rider.wall) << ", "
       << significant(s.rider.length) << " m, supports "
       << format_quantity(s.rider.support_stiffness, Dimension::stiffness) << ", line load "
       << significant(s.rider.line_load) << " N/m |\n";
    md << "| web speed | " << significant(s.web_speed, 5) << " m/s (" << significant(s.web_speed * 60, 5) << " m/min) |\n";
    md << "| damping ratios | drums " << s.damping.drums << ", nips " << s.damping.nips << ", rider " << s.damping.rider
       << " |\n";
    md << "| model | beam level, " << r.n_dofs << " DOFs, bending only; " << s.sweep.points << " diameters, modes up to "
       << significant(s.sweep.max_frequency) << " Hz |\n\n";
    if (!s.defaults.empty()) {
        md << "Defaults in use (paper: Jorkama & von Hertzen's example; assumed: ours, check them):\n\n";
        for (const std::string& line : s.defaults) md << "- `" << line << "`\n";
        md << "\n";
    }
}

void nip_section(std::ostringstream& md, const WinderSweepResult& r) {
    md << "## The nips (Jorkama)\n\n"
          "k = pi E / (2 (1 - nu^2) (ln(2d/a) - 1)) per unit length; the drum line load from the roll's "
          "equilibrium unless given.\n\n"
          "| d | alpha | roll mass | drum P | a | delta | k drum | rider P | k rider |\n"
          "|---|---|---|---|---|---|---|---|---|\n";
    for (size_t i : table_rows(r.points.size())) {
        const SweepPoint& p = r.points[i];
        const WinderState& st = p.state;
        md << "| " << millimetres(p.roll_diameter) << " | " << formatted("%.1f", st.geometry.nip_angle * 180 / M_PI)
           << " deg | " << significant(st.roll_mass_per_width) << " kg/m | " << significant(st.drum_line_load)
           << " N/m | " << millimetres(st.drum_nip.half_width) << " | " << millimetres(st.drum_nip.deflection) << " | "
           << significant(st.drum_nip.stiffness_per_length / 1e6) << " MN/m^2 | " << significant(st.rider_line_load)
           << " N/m | " << significant(st.rider_nip.stiffness_per_length / 1e6) << " MN/m^2 |\n";
    }
    md << "\n";
}

void estimate_section(std::ostringstream& md, const WinderSweepResult& r) {
    md << "## The lowest drum frequency against the estimate\n\n"
          "The estimate is **our derivation**, not the paper's eq. 9 (whose text was not available): a "
          "two-mode Rayleigh-Ritz of the drum's first mode on its bearings and the rolls moving with it, "
          "for isotropic bearings and a soft rider (docs/how-to/winder.md). Symmetric: both drums towards the rolls "
          "(rolls vertical); antisymmetric: one towards, one away (rolls horizontal). The model column is the "
          "model's mode with most of that drum motion.\n\n"
          "| d | drum alone | symmetric: estimate | model | antisymmetric: estimate | model | heavy-roll limit |\n"
          "|---|---|---|---|---|---|---|\n";
    bool isotropic = true;
    for (size_t i : table_rows(r.points.size())) {
        const DrumFrequencyEstimate& e = r.points[i].estimate;
        isotropic = isotropic && e.isotropic;
        md << "| " << millimetres(r.points[i].roll_diameter) << " | " << hz(e.drum_alone_hz);
        for (const auto& f : e.family) md << " | " << hz(f.drum_hz) << " | " << hz(f.model_hz);
        md << " | " << hz(e.family[0].heavy_roll_hz) << " |\n";
    }
    md << "\n(Hz.) ";
    if (!isotropic) md << "**The bearings are not isotropic: the estimate does not apply.** ";
    md << "A rider presses the rolls down and stiffens their vertical motion, which the estimate leaves out: "
          "expect the symmetric model column above the estimate when the rider carries load.\n\n";
}

void crossing_section(std::ostringstream& md, const WinderScene& s, const WinderSweepResult& r) {
    md << "## Crossings of the roll harmonics with drum-dominated modes\n\n"
          "f_k = k v / (pi d), k = 1.." << s.sweep.harmonics << "; X/F at the " << drum_side_name(s.sweep.response_drum)
       << " drum's centre, " << direction_name(s.sweep.response_direction)
       << ", at the mode's frequency at the crossing diameter (modal superposition, modal damping).\n\n";
    if (r.crossings.empty()) {
        md << "No harmonic crosses a drum-dominated mode between " << millimetres(s.rolls.diameter_start) << " and "
           << millimetres(s.rolls.diameter_end) << " (below " << significant(s.sweep.max_frequency) << " Hz).\n\n";
        return;
    }
    md << "| d | harmonic | f | track | mode f at d | type | zeta | X/F |\n|---|---|---|---|---|---|---|---|\n";
    for (const Crossing& c : r.crossings)
        md << "| " << millimetres(c.roll_diameter) << " | " << c.harmonic << " | " << hz(c.frequency_hz) << " Hz | "
           << c.track << " | " << hz(c.mode_frequency_hz) << " Hz | " << body_kind_name(c.type) << " | "
           << formatted("%.4f", c.damping_ratio) << " | " << significant(c.resonance_response, 3) << " m/N |\n";
    md << "\n";
}

void checks_section(std::ostringstream& md, const WinderSweepResult& r) {
    double residual = 0, orthonormality = 0;
    int complete = 0;
    for (const SweepPoint& p : r.points) {
        residual = std::max(residual, p.verification.max_relative_residual);
        orthonormality = std::max(orthonormality, p.verification.max_orthonormality_error);
        complete += p.verification.complete ? 1 : 0;
    }
    md << "## Checks\n\n- largest relative residual ||Kx - lambda Mx|| / (||K|| ||x||): " << significant(residual, 2)
       << "\n- largest |X^T M X - I|: " << significant(orthonormality, 2) << "\n- none missed (Sylvester count of K - "
       << "sigma M above the last mode) at " << complete << " of " << r.points.size() << " diameters\n- time: "
       << significant(r.time_s, 3) << " s\n\n";
}

}  // namespace

std::string winder_report_markdown(const WinderScene& s, const WinderSweepResult& r, const std::vector<std::string>& pngs,
                                   const std::string& plot_problem) {
    std::ostringstream md;
    md << "# Two-drum winder: " << s.name << "\n\n";
    if (!s.description.empty()) md << s.description << "\n\n";
    md << "`coremodal winder " << s.source_file << "`: the natural frequencies of the winder as the rolls grow, "
          "the rolls' rotation harmonics against the drum-dominated ones, and the response at a drum's centre "
          "(docs/how-to/winder.md).\n\n";
    scene_section(md, s, r);
    nip_section(md, r);
    estimate_section(md, r);
    md << "## The crossing diagram\n\n";
    for (const std::string& png : pngs) md << "![" << png << "](" << png << ")\n\n";
    if (!plot_problem.empty()) md << "No picture: " << plot_problem << ".\n\n";
    crossing_section(md, s, r);
    checks_section(md, r);
    md << "Files: winder.csv (every mode at every diameter), crossings.csv, response.csv (|X/F| at each harmonic), "
          "summary.json.\n";
    return md.str();
}

std::string winder_console_summary(const WinderScene& s, const WinderSweepResult& r) {
    std::ostringstream out;
    out << "winder: " << r.points.size() << " roll diameters from " << millimetres(s.rolls.diameter_start) << " to "
        << millimetres(s.rolls.diameter_end) << ", " << r.n_dofs << " DOFs, " << significant(r.time_s, 3) << " s\n";
    const DrumFrequencyEstimate& first = r.points.front().estimate;
    out << "  drum alone: " << hz(first.drum_alone_hz) << " Hz\n";
    for (const Crossing& c : r.crossings)
        out << "  harmonic " << c.harmonic << " crosses a " << body_kind_name(c.type)
            << " mode at d = " << millimetres(c.roll_diameter) << ", " << hz(c.mode_frequency_hz)
            << " Hz: X/F = " << significant(c.resonance_response, 3) << " m/N (zeta "
            << formatted("%.4f", c.damping_ratio) << ")\n";
    if (r.crossings.empty()) out << "  no harmonic crosses a drum-dominated mode\n";
    return out.str();
}

}  // namespace coremodal
