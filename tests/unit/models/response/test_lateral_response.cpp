// The truncated basis' direct solve (models/response/lateral_response):
// the sparse LU with the kept modes' own damping by Woodbury's identity
// against the complete basis' dense LU of the same system, built so that
// both are the one linear system: the modes above the truncated basis carry
// no own damping in either.
#include "models/response/lateral_response.hpp"
#include "models/response/response_loads.hpp"
#include "beam/beam_model.hpp"
#include "effects/damping.hpp"
#include "scene/case_file.hpp"
#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <optional>
#include <vector>

using namespace coremodal;
using cd = std::complex<double>;

namespace {

// The forced-response tests' small clamped rest roll (support/tiny_case.hpp).
Scene clamped_roll() {
    return parse_case_text(testing::kClampedRestRoll, "roll.toml");
}

}  // namespace

TEST_CASE("The truncated basis' sparse direct solve is the complete basis' dense one", "[response][analyses]") {
    const Scene scene = clamped_roll();
    const BeamModelResult rest = solve_beam_model(scene);
    const double f1 = rest.modes.front().frequency_hz;
    std::optional<LateralResponse> truncated =
        LateralResponse::truncated(rest.network, rest.lambda_scale, 2 * M_PI * 6 * f1, scene.analysis.tolerance);
    REQUIRE(truncated);
    LateralResponse complete(rest.network, rest.lambda_scale);
    const int n = truncated->n_modes();
    REQUIRE(n >= 2);
    REQUIRE(n < complete.n_modes());
    // Own ratios on the kept modes (different per mode), none above them, with
    // a Rayleigh part on every mode: D = alpha M + beta K + M Phi_n diag Phi_n^T M
    // in both.
    const RayleighDamping rayleigh{0.3, 1e-6};
    std::vector<std::optional<double>> kept, every(static_cast<size_t>(complete.n_modes()));
    for (int j = 0; j < n; ++j) {
        // The same mode in both bases (the lowest n, simple eigenvalues here).
        REQUIRE(truncated->eigenvalue(j) == Approx(complete.eigenvalue(j)).epsilon(1e-8));
        kept.push_back(0.01 + 0.005 * j);
        every[static_cast<size_t>(j)] = kept.back();
    }
    truncated->set_damping(rayleigh, kept);
    complete.set_damping(rayleigh, every);
    ExcitationSpec x;
    x.bow_m = 0.5e-3;
    const ResponseLoads loads = build_response_loads(scene, x, rest.network, complete, {});
    REQUIRE(!loads.orders.empty());
    const OrderLoad& load = loads.orders.front();
    for (const double share : {0.3, 0.98, 1.0, 2.5}) {  // below, near, at and above the first bending mode
        const double spin = 2 * M_PI * share * f1, omega = load.order * spin;
        const Eigen::VectorXcd f = complete.to_rows(load.at(spin));
        const Eigen::VectorXcd dense = complete.direct(f, spin, omega);
        const Eigen::VectorXcd sparse = truncated->direct(f, spin, omega);
        // One linear system by two factorisations: round-off times its
        // condition near resonance (1 / (2 zeta) ~ 50).
        CHECK((sparse - dense).norm() / dense.norm() < 1e-8);
    }
}
