// The model error of a simpler model level against the solid's
// (analyses/converge/converge_study.hpp): role by role, from both
// extrapolations, and level by level against the solid's f0.
#include "analyses/converge/converge_study.hpp"

#include "support/converge_levels.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace coremodal;

TEST_CASE("Model error: a beam level's extrapolated values against the solid's, role by role", "[converge][beam]") {
    const ConvergeStudy study = coremodal::testing::beam_against_solid_study();
    CHECK(find_reference(study.models) == &study.models[0]);  // the solid's
    CHECK_FALSE(find_reference({study.models[1]}));

    const std::vector<ModelError> errors = model_errors(study.models);
    REQUIRE(errors.size() == 2);  // f1 and torsion: the beam has no ovalling
    CHECK(errors[0].role == "f1");
    CHECK(errors[0].f0_hz == Approx(62.0).epsilon(1e-9));
    CHECK(errors[0].solid_f0_hz == Approx(61.3).epsilon(1e-9));
    CHECK(errors[0].relative == Approx(0.7 / 61.3).epsilon(1e-7));
    CHECK(errors[1].role == "torsion");
    CHECK(errors[1].relative == Approx(-1.0 / 200).epsilon(1e-7));
    CHECK(model_errors({study.models[1]}).empty());  // no solid level, nothing to set against

    // Each beam level against the solid's f0: it levels off at the model error.
    const TrackedMode* beam_f1 = find_role(study.models[1], "f1");
    REQUIRE(beam_f1);
    const auto vs_solid = error_against_solid(*beam_f1, study.models);
    REQUIRE(vs_solid.size() == 5);
    CHECK(*vs_solid.back() == Approx((62.0 + std::pow(1.0 / 16, 4) - 61.3) / 61.3));
    CHECK(error_against_solid(*beam_f1, {study.models[1]}).empty());  // no solid level, nothing to set against

    // Predictions scale the beam's DOFs with k, not k^3.
    const auto p = predict_level_for(study.models[1], *beam_f1, 1e-9);
    REQUIRE(p);
    CHECK(p->n_dofs == Approx(48 * p->k).epsilon(1e-9));
}
