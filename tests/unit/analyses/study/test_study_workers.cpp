// The record a worker child hands back to its study (analyses/study/study_workers.hpp).
#include "analyses/study/study_workers.hpp"

#include <catch2/catch.hpp>

using namespace coremodal;

TEST_CASE("A point's record reads back exactly, failed or not", "[app][study]") {
    StudyPoint p;
    p.ok = true;
    p.time_s = 8.125;
    p.model_level = "solid";
    p.n_dofs = 24000;
    p.f1_hz = 32.366101234567891;
    ModeSummary bending;
    bending.index = 1;
    bending.frequency_hz = 32.366101234567891;
    bending.label.type = "bending";
    bending.label.n = 1;
    bending.label.dominant_share = 0.99;
    bending.signature = {0.1, -2.5e-7, 1.0 / 3};
    ModeSummary torsion;
    torsion.index = 2;
    torsion.frequency_hz = 57.5;
    torsion.label.type = "torsion";
    p.modes = {bending, torsion};
    StudyPoint q;
    read_point_record(point_record(p), q);
    CHECK(q.ok);
    CHECK(q.time_s == p.time_s);
    CHECK(q.model_level == "solid");
    CHECK(q.n_dofs == 24000);
    CHECK(*q.f1_hz == *p.f1_hz);
    REQUIRE(q.modes.size() == 2);
    CHECK(q.modes[0].signature == p.modes[0].signature);  // 17 digits: bit for bit
    CHECK(q.modes[0].label.type == "bending");
    CHECK(q.modes[1].signature.empty());

    StudyPoint failed;
    failed.error = "solve failed: converged 3 of 8\nsecond line";
    StudyPoint r;
    read_point_record(point_record(failed), r);
    CHECK_FALSE(r.ok);
    CHECK(r.error == failed.error);  // JSON keeps the line break
    CHECK_FALSE(r.f1_hz);

    CHECK_THROWS_WITH(read_point_record("something else\n", r), Catch::Contains("not a study point record"));
    CHECK_THROWS_WITH(read_point_record("{\"ok\": true}", r), Catch::Contains("not a study point record"));
    std::string cut = point_record(p);
    cut.resize(cut.size() / 2);
    CHECK_THROWS_WITH(read_point_record(cut, r), Catch::Contains("not a study point record (invalid JSON)"));
    std::string no_modes = point_record(failed);
    no_modes.replace(no_modes.find("\"modes\""), 7, "\"nodes\"");
    CHECK_THROWS_WITH(read_point_record(no_modes, r), Catch::Contains("study point record:") && Catch::Contains("modes"));
}
