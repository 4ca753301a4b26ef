// The input of `coremodal fit` (docs/how-to/calibration.md, "Fitting the model to
// measured frequencies"):
//
//   parameters = ["core.material.E_z", "core.material.G_thetaz"]   # any key a [study] can vary
//   # or with bounds: { key = "core.material.G_rz", min = "20 MPa", max = "2 GPa" }
//   [[measurement]]
//   case = "iso-test-76x15.toml"     # relative to this file
//   mode = "bending n=1 m=0"         # matched by label (type, n, m; "#2" for a second occurrence)
//   frequency = "133.2 Hz"
//   uncertainty = "0.3 Hz"           # standard uncertainty; default 1 % of the frequency
//   model = "beam"                   # optional: the level this case is solved at (default: the case's)
//
// Checked up front: FILE:LINE:COL, key, what is wrong, what is expected.
#pragma once

#include "modes/label_tracking.hpp"

#include <toml++/toml.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

struct FitParameterSpec {
    std::string key;
    std::optional<double> min, max;  // SI, when given
    toml::source_region where;
};

struct Measurement {
    std::string case_file;  // resolved against the measurements file's folder
    std::string model;      // "" = the case's own level
    ModeKey mode;
    double frequency_hz = 0;
    double uncertainty_hz = 0;
    bool uncertainty_assumed = false;  // not given: kDefaultRelativeUncertainty of the frequency
    toml::source_region where;  // the [[measurement]] table
};

struct FitInput {
    std::string path;  // the measurements file
    std::vector<FitParameterSpec> parameters;
    std::vector<Measurement> measurements;
    // The parsed document: key nodes for messages that name the parameters.
    std::shared_ptr<toml::table> document;
    std::vector<const toml::node*> parameter_nodes;
};

// Default standard uncertainty of a measured frequency when none is given:
// 1 %, a free-hanging tap test read off a spectrum with a few tenths of a Hz
// resolution at 30-130 Hz (Ilomäki's 39.06 Hz, ISO 11093-8).
inline constexpr double kDefaultRelativeUncertainty = 0.01;

FitInput read_fit_input(const std::string& path);

// The measurements file's keys as a JSON Schema (draft-07): parameters (a
// key, or {key, min, max}), [[measurement]] {case, mode, frequency,
// uncertainty, model}; `coremodal schema --fit`.
std::string fit_json_schema();
FitInput parse_fit_input(const std::string& text, const std::string& path);

// "bending n=1 m=0" or "bending n=1 m=0 #2" -> ModeKey; nothing when it is not one.
std::optional<ModeKey> parse_mode_label(const std::string& text);

}  // namespace coremodal
