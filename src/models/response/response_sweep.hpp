// What the forced response does the same way at every model level
// (docs/theory/response.md, "The solver", steps 3-6): the sweep over the speeds,
// the peaks refined between grid speeds and labelled with the mode that
// answers, the first speed where the amplitude reaches the limit, and the
// checks of the superposition. A level hands these steps a ResponseModel:
// its loads per order, its probes and its solves (beam_response.cpp,
// harmonic_response.cpp).
#pragma once

#include "models/response/response_result.hpp"

#include <Eigen/Dense>

#include <vector>

namespace coremodal {

// How one speed's response is computed: the modes up to the cutoff with the
// static part of the others (the sweep), every mode at rest (where a level
// has the complete basis), or the direct solve of the full system.
enum class ResponseMethod { truncated, complete, direct };

// The mode at rest that carries most of a probe's motion (a peak's label).
struct AnsweringMode {
    ModeLabel label;
    double frequency_hz = 0;
};

// One model level's forced response: per excitation order (ascending, as
// `orders()`), the response vector on the level's unknowns at a rotation
// speed f_rot, and the orbits it gives at the probes.
class ResponseModel {
public:
    virtual ~ResponseModel() = default;
    virtual const std::vector<int>& orders() const = 0;
    virtual size_t n_probes() const = 0;
    // Per order, x on the level's unknowns at rotation speed speed_hz (Hz).
    virtual std::vector<Eigen::VectorXcd> solve(double speed_hz, ResponseMethod method) const = 0;
    virtual ProbeAmplitude at_probe(const std::vector<Eigen::VectorXcd>& x, size_t probe) const = 0;
    // The kept mode with the largest share (|eta_j| times its motion at the
    // first probe) of order `order_index`'s response at speed_hz.
    virtual AnsweringMode answering_mode(size_t order_index, double speed_hz) const = 0;
    // false: the level has only the kept modes, and the checks compare the
    // truncated sum with the direct solve (the truncation's effect).
    virtual bool has_complete_basis() const { return true; }

    // The total amplitude at the first probe (m), from the truncated sum.
    double amplitude(double speed_hz) const { return at_probe(solve(speed_hz, ResponseMethod::truncated), 0).total_m; }
};

// Steps 3-6 on `out` (points, peaks, safe, the largest amplitude, the checks'
// differences): the sweep over range.speeds_hz, peaks, the speed at
// range.limit_m, the checks. f1_hz: the first bending frequency at rest
// (I-5's implied factor); dp: the roll's outer diameter (web speeds).
// checking = none leaves the checks out (response.hpp).
void sweep_response(const ResponseModel& model, const ResponseRange& range, double f1_hz, double dp,
                    ResponseResult& out, ResponseChecking checking = ResponseChecking::full);

}  // namespace coremodal
