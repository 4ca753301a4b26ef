// The crossing diagram: crossings of synthetic tracks computed by hand, the
// resonance response's 1/zeta scaling, and a short sweep of the default winder.
#include "winder/winder_sweep.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

std::vector<double> grid(double a, double b, int n) {
    std::vector<double> d;
    for (int i = 0; i < n; ++i) d.push_back(a + (b - a) * i / (n - 1));
    return d;
}

TrackSeries series(int id, const std::vector<double>& d, double (*f)(double), bool drum) {
    TrackSeries t;
    t.track = id;
    for (double x : d) t.frequency_hz.push_back(f(x)), t.drum.push_back(drum);
    return t;
}

}  // namespace

TEST_CASE("The roll harmonics are k v / (pi d)", "[winder][sweep]") {
    // 2000 m/min = 33.333 m/s on a 1.2 m roll: 8.8419 Hz; the 3rd harmonic 26.526 Hz.
    CHECK(roll_harmonic_hz(1, 2000.0 / 60, 1.2) == Approx(8.84194).epsilon(1e-5));
    CHECK(roll_harmonic_hz(3, 2000.0 / 60, 1.2) == Approx(26.5258).epsilon(1e-5));
}

TEST_CASE("Crossings of synthetic tracks are where the hand puts them", "[winder][sweep]") {
    const double v = 30.0;  // m/s
    const std::vector<double> d = grid(0.4, 1.8, 15);
    // A constant drum mode at 20 Hz meets harmonic k where k v / (pi d) = 20:
    //   d = k * 30 / (20 pi) = 0.477465 k  ->  k = 1: 0.477465, k = 2: 0.954930,
    //   k = 3: 1.432394 (k = 4: 1.909859 lies beyond 1.8 m).
    // A drum mode linear in 1/d, f = 10 + 6/d, meets it where (k v / pi - 6) / d = 10:
    //   k = 2: (19.098593 - 6) / 10 = 1.309859;  k = 3: (28.647890 - 6) / 10 = 2.26 (beyond);
    //   k = 1: (9.549297 - 6) / 10 = 0.354930 (before 0.4): one crossing.
    // A roll mode at 20 Hz is not drum-dominated: no crossings.
    const std::vector<TrackSeries> tracks = {
        series(1, d, [](double) { return 20.0; }, true),
        series(2, d, [](double x) { return 10.0 + 6.0 / x; }, true),
        series(3, d, [](double) { return 20.0; }, false),
    };
    const std::vector<Crossing> c = find_crossings(d, tracks, v, 4);
    REQUIRE(c.size() == 4);
    // Sorted by diameter.
    CHECK(c[0].roll_diameter == Approx(0.477465).epsilon(1e-6));
    CHECK((c[0].harmonic == 1 && c[0].track == 1));
    CHECK(c[0].frequency_hz == Approx(20.0).epsilon(1e-12));
    CHECK(c[1].roll_diameter == Approx(0.954930).epsilon(1e-6));
    CHECK((c[1].harmonic == 2 && c[1].track == 1));
    CHECK(c[2].roll_diameter == Approx(1.309859).epsilon(1e-6));
    CHECK((c[2].harmonic == 2 && c[2].track == 2));
    CHECK(c[2].frequency_hz == Approx(10.0 + 6.0 / 1.309859).epsilon(1e-6));
    CHECK(c[3].roll_diameter == Approx(1.432394).epsilon(1e-6));
    CHECK((c[3].harmonic == 3 && c[3].track == 1));
}

TEST_CASE("A track that touches a harmonic at a sweep point counts once", "[winder][sweep]") {
    // f = 20 Hz meets k = 1 at d = 30 / (20 pi) = 0.477465: put a grid point there.
    const double v = 30.0, at = v / (20.0 * M_PI);
    const std::vector<double> d = {0.4, at, 0.6};
    const std::vector<Crossing> c = find_crossings(d, {series(1, d, [](double) { return 20.0; }, true)}, v, 1);
    REQUIRE(c.size() == 1);
    CHECK(c[0].roll_diameter == Approx(at).epsilon(1e-12));
}

TEST_CASE("The response at a resonance scales as 1/zeta", "[long][winder][sweep]") {
    WinderScene s;
    s.source_file = "test.toml";
    const WinderModel m = build_winder_model(s, 1.2);
    const int dof = response_dof(m, DrumSide::front, ResponseDirection::vertical);
    double previous = 0;
    for (double scale : {1.0, 0.5, 0.25}) {
        WinderDamping damping = s.damping;
        damping.drums *= 0.1 * scale, damping.nips *= 0.1 * scale, damping.rider *= 0.1 * scale;
        const WinderModes modes = solve_winder_modes(m, damping, s.sweep.max_frequency);
        // The drum-dominated mode that moves the drum's centre vertically the most.
        int best = 0;
        for (int i = 0; i < modes.n_reported; ++i)
            if (modes.modes[i].type == BodyKind::drum && std::abs(modes.shapes(dof, i)) > std::abs(modes.shapes(dof, best)))
                best = i;
        const double peak = std::abs(receptance(modes, dof, modes.modes[best].frequency_hz));
        // Near the resonant term alone, x^2 / (2 zeta omega^2).
        const WinderMode& mode = modes.modes[best];
        CHECK(peak == Approx(std::pow(modes.shapes(dof, best), 2) / (2 * mode.damping_ratio * mode.eigenvalue)).epsilon(0.05));
        // Halving every ratio doubles the peak (to the off-resonant modes' share).
        if (previous > 0) CHECK(peak / previous == Approx(2.0).epsilon(0.01));
        previous = peak;
    }
}

TEST_CASE("A short sweep of the default winder tracks its modes and finds crossings", "[long][winder][sweep]") {
    WinderScene s;
    s.source_file = "test.toml";
    s.sweep.points = 8;
    const WinderSweepResult r = run_winder_sweep(s);
    REQUIRE(r.points.size() == 8);
    for (const SweepPoint& p : r.points) {
        CHECK(p.verification.complete);
        CHECK(p.harmonic_response.size() == 4u);
        for (const SweepMode& m : p.modes) CHECK(m.track > 0);
    }
    // The 2nd-4th harmonics sweep from 35-141 Hz down to 12-24 Hz, through
    // the drums' 21-25 Hz: crossings exist, each within the sweep and near its mode.
    REQUIRE(!r.crossings.empty());
    for (const Crossing& c : r.crossings) {
        CHECK(c.roll_diameter >= s.rolls.diameter_start);
        CHECK(c.roll_diameter <= s.rolls.diameter_end);
        CHECK(c.mode_frequency_hz == Approx(c.frequency_hz).epsilon(0.05));
        CHECK(c.resonance_response > 0);
    }
}
