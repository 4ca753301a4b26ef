// Synthetic levels of a converge ladder, for tests of what is built from them
// (tracking, extrapolation, model errors, the report files): level k has
// h = 1/k, k^3 x 1000 DOFs and times ~ k^3, as a solid ladder would.
#pragma once

#include "analyses/converge/converge_study.hpp"
#include "support/test_modes.hpp"

#include <cmath>

#include <string>
#include <utility>
#include <vector>

namespace coremodal::testing {

inline LevelResult level(int k, std::vector<Mode> modes) {
    LevelResult l;
    l.step.k = k;
    l.step.h = 1.0 / k;
    l.step.counts = std::to_string(k) + "/" + std::to_string(k) + "/" + std::to_string(8 * k) + "/" +
                    std::to_string(10 * k);
    l.step.label = "k=" + std::to_string(k) + " " + l.step.counts;
    l.n_dofs = 1000L * k * k * k;
    l.runs = 3;
    l.median_s = {.mesh = 0.01 * k, .assemble = 0.1 * k, .factor_and_solve = 1.0 * k * k * k, .classify = 0.01,
                  .total = 1.2 * k * k * k};
    l.peak_memory_mb = 100.0 * k * k;
    l.modes = std::move(modes);
    return l;
}

// A solid ladder (k = 1..4) and a beam ladder (k = 1..16, DOFs ~ k) whose
// modes converge as h^4 to known values: f1 61.3 Hz (solid) and 62.0 Hz
// (beam), torsion 200 and 199 Hz, ovalling 430 Hz (solid only: the beam
// cannot have it).
inline ConvergeStudy beam_against_solid_study() {
    std::vector<LevelResult> solid_levels, beam_levels;
    for (int k = 1; k <= 4; ++k) {
        const double e = std::pow(1.0 / k, 4);
        solid_levels.push_back(level(k, {mode(1, 61.3 + e, "bending", 1, 0), mode(2, 61.3 + e, "bending", 1, 0),
                                         mode(3, 200 + 3 * e, "torsion", 0, 0), mode(4, 430 + 50 * e, "ovalling", 2, 0)}));
    }
    for (int k = 1; k <= 16; k *= 2) {
        const double e = std::pow(1.0 / k, 4);
        LevelResult l = level(k, {mode(1, 62.0 + e, "bending", 1, 0), mode(2, 62.0 + e, "bending", 1, 0),
                                  mode(3, 199 + 2 * e, "torsion", 0, 0)});
        l.n_dofs = 48L * k;
        l.median_s.total = 1e-3 * k;
        beam_levels.push_back(std::move(l));
    }
    ConvergeStudy study;
    study.case_name = "synthetic";
    study.source_file = "synthetic.toml";
    study.models.push_back(analyse_levels(ModelChoice::solid, "solid ladder", solid_levels));
    study.models.push_back(analyse_levels(ModelChoice::beam, "beam ladder", beam_levels));
    study.models[1].refined_dimensions = 1;
    study.models[1].unseen_roles = {{"ovalling", "rigid cross-sections"}};
    return study;
}

inline std::string case_path(const std::string& name) { return std::string(COREMODAL_SOURCE_DIR) + "/cases/" + name; }

}  // namespace coremodal::testing
