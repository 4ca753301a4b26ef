// A sweep over case-file keys: the [study] and [calibration] tables
// (docs/how-to/studies.md, docs/how-to/calibration.md).
//
//   [study]
//   parameters = [
//     { key = "rest_paper.thickness", values = ["5 mm", "10 mm", "20 mm"] },
//     { key = "core.length", from = "2 m", to = "4 m", steps = 5 },
//   ]
//   mesh = "coarse"
//
// Every point of the grid (the first parameter varies slowest) is the case
// file's own document with the points' keys set, read by the normal case
// reader: a study point gets every check a case file gets. Checked up front,
// with file, line and key: the table's own keys, every key path against the
// schema, every value's type, unit and range. A point whose combination of
// values the case reader refuses (a clamp beyond a shortened core) is that
// point's error, raised by scene(point); the study reports it and goes on.
#pragma once

#include "scene/response_spec.hpp"
#include "scene/scene.hpp"
#include "scene/units.hpp"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace coremodal {

struct SweepParameter {
    std::vector<std::string> keys;    // dotted key paths, all set to the same value
    std::string name;                 // keys[0]: the column name in study.csv
    Dimension dimension = Dimension::dimensionless;
    bool numeric = false;             // quantities and integers: si holds the values
    std::vector<std::string> labels;  // each value as shown: "10 mm", "steel"
    std::vector<double> si;           // SI values (numeric parameters only)
};

struct SweepOptions {
    std::string mesh_level;                // what every point uses; "" = the case's own [mesh]
    std::string model;                     // model level of every point (--model); "" = the case's own
    int modes = 0;                         // [analysis] modes of every point; 0 = the case's own [analysis]
    double safe_factor = 0.7;              // I-5 factor for v_safe ([study] safe_factor)
    std::optional<double> web_speed_m_s;   // König's chart line ([study] web_speed)
    int holdout_every = 4;                 // [calibration]: every Nth point is held out of the fit
    double max_error = 0.05;               // [calibration]: stated error of I-7 with the fitted k
};

// Defaults of a sweep when the case file and the table do not say: fast
// meshes, few modes (docs/how-to/studies.md explains the choice).
inline constexpr std::string_view kSweepDefaultMesh = "coarse";
inline constexpr int kStudyDefaultModes = 12;
inline constexpr int kCalibrationDefaultModes = 6;

class CaseSweep {
public:
    // Reads the case file and its table `table` ("study" or "calibration").
    // mesh_override is the command line's --mesh LEVEL (wins over the table's
    // mesh). Throws InputError naming file, line and key.
    static CaseSweep read(const std::string& path, std::string_view table,
                          const std::optional<std::string>& mesh_override = std::nullopt);
    static CaseSweep from_text(std::string text, const std::string& path, std::string_view table,
                               const std::optional<std::string>& mesh_override = std::nullopt);

    const std::string& case_file() const;
    const std::string& table() const;  // "study" or "calibration"
    bool from_file() const;            // read(), not from_text(): a child process can read it again
    const std::string& case_name() const;  // the case's name (file stem unless given)
    // The plausibility warnings of the case as written (Scene::warnings):
    // printed once by the command, not once a point.
    const std::vector<std::string>& warnings() const;
    const std::vector<SweepParameter>& parameters() const;
    const SweepOptions& options() const;
    // The same sweep with every point at model level `model` (the command
    // line's --model: solid, harmonic, coupled, auto, beam); "" keeps the case's.
    CaseSweep with_model(const std::string& model) const;

    int n_points() const;
    // Which value of each parameter point i takes (0-based, parameter order).
    std::vector<int> value_indices(int point) const;
    // The point the modes of `point` are tracked from: the neighbour with the
    // previous value of the fastest parameter, or for the first point of a
    // line the first point of the previous line. None for point 0.
    std::optional<int> predecessor(int point) const;
    // "rest_paper.thickness = 10 mm, core.length = 3 m"
    std::string describe(int point) const;
    // The scene of one point. Throws InputError "point 4 (...): <the case
    // reader's message>" when the case reader refuses the combination.
    Scene scene(int point) const;
    // The same point with its [rotation] and its forced response setup
    // ([damping], [excitation], [response]; none without [response]): a
    // study over a response case runs the response at every point
    // (docs/how-to/studies.md). Throws as scene(point).
    ResponseCase response_case(int point) const;

    struct Impl;  // the case's text, the key paths and values (case_sweep_impl.hpp)

private:
    std::shared_ptr<const Impl> impl_;
};

}  // namespace coremodal
