// Case 11 (cases/11-two-drum-winder.toml) keeps the results pasted in it:
// three of its diameters solved in-process (the full sweep is the command's).
#include "winder/winder_estimate.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;

TEST_CASE("Case 11, the two-drum winder, keeps its pasted results", "[winder][cases]") {
    const WinderScene s = read_winder_file(COREMODAL_SOURCE_DIR "/cases/11-two-drum-winder.toml");
    CHECK(s.sweep.points == 57);
    // d, antisymmetric drum mode of the model, its estimate, symmetric drum mode (Hz, as pasted).
    const struct {
        double d, antisymmetric, estimate, symmetric;
    } rows[] = {{0.4, 20.586, 20.587, 23.562}, {1.1, 24.156, 24.157, 25.777}, {1.8, 23.936, 23.936, 24.326}};
    for (const auto& row : rows) {
        CAPTURE(row.d);
        const WinderModel m = build_winder_model(s, row.d);
        const WinderModes modes = solve_winder_modes(m, s.damping, s.sweep.max_frequency);
        CHECK(modes.verification.complete);
        const DrumFrequencyEstimate e = estimate_drum_frequency(m, modes);
        CHECK(e.drum_alone_hz == Approx(21.652).epsilon(5e-5));  // pasted to 5 digits
        const auto& anti = e.family[static_cast<int>(DrumFamily::antisymmetric)];
        const auto& sym = e.family[static_cast<int>(DrumFamily::symmetric)];
        CHECK(anti.model_hz == Approx(row.antisymmetric).epsilon(5e-5));
        CHECK(anti.drum_hz == Approx(row.estimate).epsilon(5e-5));
        CHECK(sym.model_hz == Approx(row.symmetric).epsilon(5e-5));
    }
}
