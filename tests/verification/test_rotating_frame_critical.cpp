// Critical speeds in co-rotating coordinates (docs/theory/rotation-solid.md, "Critical
// speeds in co-rotating coordinates"): the speeds where a mode's
// rotating-frame frequency is zero are the eigenvalues Omega^2 of the pencil
// (K, M_P - K_sigma1) (eigensolve/zero_frequency_speeds.hpp). Truths: the
// stationary frame's forward whirl, which must meet the line f = f_rot at
// exactly that speed on a body of revolution; a dense solve of the same
// pencil (its eigenvalues and its count below Omega_max^2); Rayleigh's bound
// without the centrifugal term. The pencils (K, B_r) of a rotating-frame
// frequency r f_rot likewise: the stationary frame's backward whirl and its
// order-2 crossings, and a dense solve of the complex Hermitian pencil.
#include "analyses/campbell/campbell.hpp"
#include "models/spinning_model.hpp"
#include "analyses/campbell/zero_frequency_crossings.hpp"
#include "common/error.hpp"
#include "eigensolve/projection_basis.hpp"  // apply_columns
#include "models/solid/rotating_solid.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <complex>

using namespace coremodal;

namespace {

// A clamped steel tube 106 x 76 mm, 0.6 m, clamped over 30 mm, solid.
Scene clamped_tube(int around, int along) {
    Scene tube = testing::clamp_both_ends(testing::steel_tube(0.106, 0.076, 0.6, 1, around, along, 6), 0.03);
    tube.model = ModelChoice::solid;
    return tube;
}

// The complex pencil K x = mu B_r x, B_r = -K_Omega + r^2 M - i r G_c, by a
// dense Hermitian solve (Eigen, complex: not the real form the code
// solves): its eigenvalues mu > 0, ascending.
std::vector<double> dense_ratio_pencil(const OperatorSet& ops, double r) {
    PetscInt rows = 0;
    MatGetSize(ops.K(), &rows, nullptr);
    const Eigen::Index n = static_cast<Eigen::Index>(rows);
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
    const Eigen::MatrixXd K = apply_columns(ops.K(), I), M = apply_columns(ops.M(), I);
    const Eigen::MatrixXd A = r * r * M - apply_columns(ops[Term::centrifugal], I);
    const Eigen::MatrixXd G = apply_columns(ops[Term::gyroscopic], I);
    const Eigen::MatrixXcd B = A.cast<std::complex<double>>() - std::complex<double>(0, r) * G.cast<std::complex<double>>();
    const Eigen::MatrixXcd Kc = (0.5 * (K + K.transpose())).cast<std::complex<double>>();
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXcd> solver(0.5 * (B + B.adjoint()), Kc);
    std::vector<double> out;
    for (double c : solver.eigenvalues())
        if (c > 0) out.push_back(1 / c);
    std::sort(out.begin(), out.end());
    return out;
}

// r = 0: the real pencil (K, M_P - K_sigma1), by the same dense solve.
std::vector<double> dense_pencil(const OperatorSet& ops) { return dense_ratio_pencil(ops, 0.0); }

// The frames differ on the 16 x 8 tube by 4.6e-5 of the shift n f_rot
// (test_rotating_frame.cpp); near a crossing the whirl hardly moves with
// speed, so a crossing's speed differs by as much: 1e-4, as there.
constexpr double kFrameTolerance = 1e-4;

// The clamped tube in both frames with the centrifugal term, and f1 at rest.
struct BothFrames {
    Scene tube = clamped_tube(16, 8);
    RotatingSolid stationary{tube, 6, {.frame = SpinFrame::stationary, .centrifugal_stiffening = true}};
    RotatingSolid rotating{tube, 6, {.frame = SpinFrame::rotating, .centrifugal_stiffening = true}};
    double f1 = stationary.modes_at(0.0).front().frequency_hz;
};

// How far the stationary frame's bending n = 1 whirl of direction `whirl`
// at f_rot = fc lies from the line order * fc, relative to it (the nearest).
double off_the_line(const RotatingSolid& stationary, double fc, int order, Whirl whirl) {
    double closest = 1e300;
    for (const RotatingMode& m : stationary.modes_at(fc))
        if (m.whirl == whirl && m.label.type == "bending" && m.label.n == 1)
            closest = std::min(closest, std::abs(m.frequency_hz - order * fc) / (order * fc));
    return closest;
}

// A pencil's speeds below max_hz against the dense eigenvalues mu = Omega^2:
// the count and every speed (1e-7: both solvers' tolerances, squared back).
void check_against_dense(const ZeroFrequencyModes& z, const std::vector<double>& dense, double max_hz) {
    const double max_mu = std::pow(2 * M_PI * max_hz, 2);
    const long dense_count = std::count_if(dense.begin(), dense.end(), [&](double mu) { return mu < max_mu; });
    INFO("Omega_max = " << max_hz << " Hz: counted " << z.counted << ", dense " << dense_count);
    CHECK(z.counted == dense_count);
    size_t i = 0;
    for (const ZeroFrequencyMode& m : z.modes) {
        REQUIRE(i < dense.size());
        CHECK(m.speed_hz == Approx(std::sqrt(dense[i]) / (2 * M_PI)).epsilon(1e-7));
        i += static_cast<size_t>(m.multiplicity);
    }
    CHECK(i == static_cast<size_t>(dense_count));
}

// The pencil r's mode of signed harmonic k (the lowest), or nullptr.
const ZeroFrequencyMode* with_harmonic(const ZeroFrequencyModes& z, int k) {
    for (const ZeroFrequencyMode& m : z.modes)
        if (m.harmonic == k && m.label.type == "bending") return &m;
    return nullptr;
}

}  // namespace

TEST_CASE("A body of revolution in the rotating frame: the pencil's critical speed is where the stationary "
          "frame's forward whirl meets f = f_rot",
          "[rotation][solid][rotating_frame][critical]") {
    // The first test of test_rotating_frame.cpp's tube, both frames, with
    // the centrifugal term. At the pencil's speed the stationary frame
    // (another G, another Omega^2 term, no pencil) must have its forward
    // bending whirl exactly on the order-1 line, to kFrameTolerance.
    const BothFrames t;
    const ZeroFrequencyModes z = t.rotating.zero_frequency_modes(1.3 * t.f1);
    REQUIRE_FALSE(z.modes.empty());
    const ZeroFrequencyMode& first = z.modes.front();
    CHECK(first.wave_number == 1);
    CHECK(first.multiplicity == 2);  // the pair: one forward whirl
    CHECK(first.label.type == "bending");
    CHECK(first.share > 0.99);
    CHECK(first.relative_residual < 1e-8);
    long found = 0;
    for (const ZeroFrequencyMode& m : z.modes) found += m.multiplicity;
    CHECK(found == z.counted);

    const double fc = first.speed_hz;
    const double closest = off_the_line(t.stationary, fc, 1, Whirl::forward);
    INFO("pencil: " << fc * 60 << " rpm (f1 at rest " << t.f1 << " Hz); stationary FW off the line by " << closest);
    CHECK(closest < kFrameTolerance);
    CHECK(fc > t.f1);  // the clamped tube's forward whirl and its stiffening rise with speed
}

TEST_CASE("The pencil's speeds and its count by inertia against a dense solve, with the centrifugal term and "
          "without",
          "[rotation][solid][rotating_frame][critical][long]") {
    // 1 x 8 x 4 hex20: a few hundred DOFs, so that Eigen solves the same
    // pencil whole. The count below Omega_max^2 must equal the dense
    // solve's number of eigenvalues there, at three Omega_max, and every
    // speed must match (1e-7: both solvers' tolerances, squared back).
    const Scene tube = clamped_tube(8, 4);
    double critical_off = 0, critical_on = 0, f1 = 0;
    for (bool stiffening : {false, true}) {
        INFO("centrifugal stiffening " << stiffening);
        const RotatingSolid solid(tube, 4, {.frame = SpinFrame::rotating, .centrifugal_stiffening = stiffening});
        f1 = solid.modes_at(0.0).front().frequency_hz;
        const std::vector<double> dense = dense_pencil(solid.operators());
        REQUIRE_FALSE(dense.empty());
        for (double factor : {0.9, 1.3, 4.0}) check_against_dense(solid.zero_frequency_modes(factor * f1), dense, factor * f1);
        (stiffening ? critical_on : critical_off) = std::sqrt(dense.front()) / (2 * M_PI);
    }
    // Without K_sigma1 the pencil is (K, M_P): x^T K x / x^T M_P x >= x^T K x /
    // x^T M x >= omega_1^2 (M_P leaves out the axial inertia), so the lowest
    // speed lies at or above f1 (Rayleigh); the hoop prestress raises it.
    INFO("f1 " << f1 << " Hz; critical without the term " << critical_off << " Hz, with it " << critical_on);
    CHECK(critical_off >= f1 * (1 - 1e-9));
    CHECK(critical_on > critical_off);
}

TEST_CASE("A body of revolution in the rotating frame: the pencils r = 1 to 3 give the backward order-1 and the "
          "order-2 crossings where the stationary frame's whirls meet the lines",
          "[rotation][solid][rotating_frame][critical][long]") {
    // As the first test: the stationary frame (another G and Omega^2 term,
    // no pencil) must have, at the pencil's speed, the whirl of the
    // predicted direction on the line j f_rot, to the frames' 1e-4.
    const BothFrames t;
    const double forward_1 = t.rotating.zero_frequency_modes(1.3 * t.f1).modes.front().speed_hz;
    struct Expected {
        int ratio, harmonic, order;
        Whirl whirl;
        const char* name;
    };
    // k = +1 at r = 2: (2 - 1) f_rot backward; k = -1 at r = 1: (1 + 1) f_rot
    // forward; k = +1 at r = 3: (3 - 1) f_rot backward (rotating_frame.hpp).
    for (const Expected e : {Expected{2, 1, 1, Whirl::backward, "BW order 1"},
                             Expected{1, -1, 2, Whirl::forward, "FW order 2"},
                             Expected{3, 1, 2, Whirl::backward, "BW order 2"}}) {
        INFO(e.name);
        const ZeroFrequencyModes z = t.rotating.frequency_ratio_modes(1.3 * t.f1, e.ratio);
        const ZeroFrequencyMode* m = with_harmonic(z, e.harmonic);
        REQUIRE(m != nullptr);
        CHECK(m->order == e.order);
        CHECK(m->whirl == e.whirl);
        CHECK(m->multiplicity == 1);  // k and -k are different modes once r > 0
        CHECK(m->share > 0.99);
        CHECK(m->relative_residual < 1e-8);
        long found = 0;
        for (const ZeroFrequencyMode& x : z.modes) found += x.multiplicity;
        CHECK(found == z.counted);
        const double fc = m->speed_hz;
        const double closest = off_the_line(t.stationary, fc, e.order, e.whirl);
        INFO("pencil r = " << e.ratio << ": " << fc * 60 << " rpm (f1 " << t.f1 << " Hz, FW order 1 at " << forward_1
                           << " Hz); stationary whirl off the line by " << closest);
        CHECK(closest < kFrameTolerance);
        if (e.order == 1) CHECK(fc < forward_1);  // the backward crossing lies below the forward one
    }
}

TEST_CASE("The pencils r > 0: their count by the real form's inertia and their speeds against a dense complex "
          "solve",
          "[rotation][solid][rotating_frame][critical][long]") {
    // The code solves the real symmetric form of size 2n and halves the
    // count; the truth is the complex Hermitian pencil of size n.
    const Scene tube = clamped_tube(8, 4);
    const RotatingSolid solid(tube, 4, {.frame = SpinFrame::rotating, .centrifugal_stiffening = true});
    const double f1 = solid.modes_at(0.0).front().frequency_hz;
    for (int r : {1, 2, 3}) {
        const std::vector<double> dense = dense_ratio_pencil(solid.operators(), r);
        INFO("r = " << r);
        for (double factor : {0.4, 1.3}) check_against_dense(solid.frequency_ratio_modes(factor * f1, r), dense, factor * f1);
    }
}

TEST_CASE("The pencil refuses a free structure with the reason", "[rotation][solid][rotating_frame][critical]") {
    Scene tube = testing::steel_tube(0.106, 0.076, 0.6, 1, 8, 4, 6);
    tube.model = ModelChoice::solid;
    const RotatingSolid solid(tube, 4, {.frame = SpinFrame::rotating, .centrifugal_stiffening = false});
    CHECK_THROWS_WITH(solid.zero_frequency_modes(100.0),
                      Catch::Contains("held structure") && Catch::Contains("below the rigid line"));
}

TEST_CASE("A Campbell sweep of segmented chucks reports the first order-1 critical speed from the pencil though "
          "the sweep stops below it",
          "[rotation][solid][rotating_frame][critical][long]") {
    // A coarse mesh and two modes keep it short: the rest solve, one speed,
    // the pencil. f1 = 344.2 Hz at rest on 12 x 8 cells (measured; this
    // mesh is a little stiffer, its pencil speed 351.8 Hz): the speeds are
    // set from it, and the checks only need them on either side.
    Scene s = testing::with_chucks(testing::paper_core(0.8, 8, 6), InterfaceKind::spring);
    for (ChuckSpec& c : s.supports.chucks) c.expanding[0].segments = 3, c.expanding[0].segment_angle = M_PI / 3;
    s.model = ModelChoice::solid;
    s.analysis.n_modes = 2;
    constexpr double f1 = 344.2;
    RotationSpec rotation;
    rotation.excitation_orders = {1};
    rotation.speeds_hz = {0.0, 0.5 * f1, 1.3 * f1};
    const CampbellResult r = run_campbell(s, rotation);
    INFO("f1 " << f1 << " Hz; sweep end: " << r.sweep_end);
    CHECK(r.points.size() == 2);  // 0 and 0.5 f1: 1.3 f1 lies above the first critical speed
    CHECK(r.sweep_end.find("the sweep stopped at") != std::string::npos);
    const auto pencil_crossing = [&](Whirl whirl) -> const WhirlCrossing* {
        for (const WhirlCrossing& x : r.critical)
            if (x.order == 1 && x.whirl == whirl && x.source == CrossingSource::pencil) return &x;
        return nullptr;
    };
    const WhirlCrossing* c = pencil_crossing(Whirl::forward);
    const WhirlCrossing* bw = pencil_crossing(Whirl::backward);
    REQUIRE(c != nullptr);
    REQUIRE(bw != nullptr);
    // The backward crossing (the pencil r = 2, above the sweep's last speed)
    // lies the whirl split below the forward one (2.5 % on this short core;
    // the backward whirl falls with speed, so below f1), and is the first.
    INFO("order 1: BW " << bw->speed_hz << " Hz, FW " << c->speed_hz << " Hz");
    CHECK(bw->speed_hz < c->speed_hz);
    CHECK(bw->speed_hz == Approx(f1).epsilon(0.05));
    CHECK(bw->label.type == "bending");
    CHECK(bw->label.n == 1);
    CHECK(r.first_order_one() == bw);
    CHECK(c->label.type == "bending");
    CHECK(c->speed_hz > 0.5 * f1);
    CHECK(c->speed_hz < 1.3 * f1);
    // Near f1 (the whirl split of a core is small; the prestress adds a little).
    CHECK(c->speed_hz == Approx(f1).epsilon(0.05));
    CHECK(c->web_speed_m_s == Approx(M_PI * r.roll_outer_diameter * c->speed_hz));
    const auto noted = [&](const std::string& words) {
        return std::any_of(r.notes.begin(), r.notes.end(),
                           [&](const std::string& n) { return n.find(words) != std::string::npos; });
    };
    CHECK(noted("critical speeds from the pencil (exact)"));
    CHECK(noted("the pencil r = 2"));

    // One speed above the critical speed leaves nothing to sweep: an error
    // that names the critical speed, before the modes at rest are solved.
    rotation.speeds_hz = {1.3 * f1};
    CHECK_THROWS_WITH(run_campbell(s, rotation), Catch::Contains("every [rotation] speed lies at or above") &&
                                                     Catch::Contains("forward critical speed of order 1"));
}
