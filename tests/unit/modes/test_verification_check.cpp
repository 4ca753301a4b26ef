// The verification gate (modes/verification_check.hpp; issue 33, item 7): a
// residual that is inf, NaN or above the limit, an incomplete count, a
// frequency that is not a number, a mass that does not match each make a
// reason; with no reasons nothing happens; a reason ends the run (a
// SolveError naming each) unless the user asked to keep going.
#include "modes/verification_check.hpp"

#include "common/error.hpp"

#include <catch2/catch.hpp>

#include <limits>
#include <string>

using namespace coremodal;

namespace {

Verification verified() {
    Verification v;
    v.max_relative_residual = 1e-14;
    v.max_orthonormality_error = 1e-14;
    v.negative_pivots_at_shift = 6;
    v.modes_below_shift = 6;
    v.complete = true;
    return v;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("Verified modes give no reason", "[modes][verify_gate]") {
    Mode m;
    m.index = 1, m.frequency_hz = 51.8;
    CHECK(verification_failures({m}, verified(), 1e-10).empty());
}

TEST_CASE("A residual that is inf, NaN or above 1e-6 is a reason", "[modes][verify_gate]") {
    Verification v = verified();
    v.max_relative_residual = std::numeric_limits<double>::infinity();
    REQUIRE(verification_failures({}, v, 1e-10).size() == 1);
    CHECK(contains(verification_failures({}, v, 1e-10)[0], "not a finite number"));
    v.max_relative_residual = std::numeric_limits<double>::quiet_NaN();
    CHECK(verification_failures({}, v, 1e-10).size() == 1);
    v.max_relative_residual = 2e-6;
    CHECK(contains(verification_failures({}, v, 1e-10).at(0), "is above 1e-06"));
    // A case that asks for a looser tolerance is held to it instead.
    CHECK(verification_failures({}, v, 1e-5).empty());
}

TEST_CASE("An incomplete count, a bad orthonormality and a frequency that is not a number are reasons",
          "[modes][verify_gate]") {
    Verification v = verified();
    v.complete = false;
    v.modes_below_shift = 5;
    CHECK(contains(verification_failures({}, v, 1e-10).at(0), "INCOMPLETE: the inertia count gives 6"));
    v = verified();
    v.max_orthonormality_error = 0.5;
    CHECK(contains(verification_failures({}, v, 1e-10).at(0), "not M-orthonormal"));
    Mode m;
    m.index = 3, m.frequency_hz = std::numeric_limits<double>::quiet_NaN();
    CHECK(contains(verification_failures({m}, verified(), 1e-10).at(0), "mode 3 has the frequency"));
}

TEST_CASE("A model mass more than 1 % from the dimensions' is a reason; an unknown one is not",
          "[modes][verify_gate]") {
    CHECK_FALSE(mass_mismatch(27.2134, 27.2134));
    CHECK_FALSE(mass_mismatch(100.9, 100.0));
    CHECK(mass_mismatch(101.1, 100.0).value_or("").find("does not match") != std::string::npos);
    CHECK(mass_mismatch(54.4, 27.2));  // a part counted twice
    CHECK_FALSE(mass_mismatch(12.0, 0.0));  // a user's mesh: no expected mass
}

TEST_CASE("A failed verification ends the run with every reason, unless asked to keep going", "[modes][verify_gate]") {
    const std::vector<std::string> reasons{"the largest relative residual is inf, not a finite number", "INCOMPLETE"};
    try {
        require_verified("the modes of x (beam level)", reasons, false);
        FAIL("no SolveError");
    } catch (const SolveError& e) {
        const std::string what = e.what();
        CHECK(contains(what, "the modes of x (beam level): verification failed: the largest relative residual is inf"));
        CHECK(contains(what, "; INCOMPLETE"));
        CHECK(contains(what, "--keep-going"));
    }
    const std::vector<std::string> warnings = require_verified("the modes of x", reasons, true);
    REQUIRE(warnings.size() == 1);
    CHECK(contains(warnings[0], "NOT verified"));
    CHECK(require_verified("the modes of x", {}, false).empty());
}
