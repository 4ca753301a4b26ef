#include "analyses/run/rigid_comparison.hpp"
#include "output/side_by_side.hpp"

#include "support/test_modes.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;
using coremodal::testing::mode;

namespace {

}  // namespace

TEST_CASE("The rigid variant clamps each end over the span of its expanding elements", "[app][chucks]") {
    Scene s;
    s.core.length = 4.32;
    ChuckSpec c;
    c.name = "left";
    c.expanding = {{0.10, 0.08, 0, 0}, {0.25, 0.08, 3, 1.0}};
    s.supports.kind = SupportKind::chucks;
    s.supports.chucks = {c, c};
    s.supports.chucks[1].name = "right";
    const Scene rigid = rigid_clamp_variant(s);
    REQUIRE(rigid.supports.kind == SupportKind::clamped);
    REQUIRE(rigid.supports.clamps.size() == 2);
    CHECK(rigid.supports.clamps[0].z_start == Approx(0.06));  // 0.10 - 0.04
    CHECK(rigid.supports.clamps[0].z_end == Approx(0.29));    // 0.25 + 0.04
    CHECK(rigid.supports.clamps[1].z_start == Approx(4.32 - 0.29));
    CHECK(rigid.supports.clamps[1].z_end == Approx(4.32 - 0.06));
    CHECK(rigid.supports.chucks.empty());
}

TEST_CASE("Modes pair by type, n and order, whatever their axial count m", "[app][chucks]") {
    const std::vector<Mode> elastic = {mode(1, 55, "bending", 1, 0), mode(2, 55, "bending", 1, 0),
                                       mode(3, 150, "bending", 1, 2), mode(4, 318, "torsion", 0, 0)};
    const std::vector<Mode> rigid = {mode(1, 66, "bending", 1, 0), mode(2, 66, "bending", 1, 0),
                                     mode(3, 176, "bending", 1, 4), mode(4, 339, "torsion", 0, 0),
                                     mode(5, 628, "axial", 0, 0)};
    const auto rows = pair_by_label(elastic, rigid);
    REQUIRE(rows.size() == 5);
    CHECK(rows[0].rigid_index == 1);
    CHECK(rows[1].rigid_index == 2);
    CHECK(rows[2].rigid_index == 3);  // m = 2 against m = 4: still the second bending pair
    CHECK(rows[2].shift_percent() == Approx(100 * (150.0 / 176 - 1)));
    CHECK(rows[3].rigid_index == 4);
    CHECK(rows[4].elastic_index == 0);  // the rigid run's axial mode has no partner
    CHECK(rows[4].rigid_index == 5);
    CHECK(rows[4].shift_percent() == 0);
    CHECK(side_by_side_csv(rows).find("bending,1,2,3,150,3,176,") != std::string::npos);
}
