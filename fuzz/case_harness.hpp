// The fuzz target's body: one case file's text through the case reader,
// the scene description and the beam model level (a [winder] file: the
// winder reader and its beam model; a [selection] file: its reader and the
// core-selection numbers; a [traction] file: its reader and the model at every
// speed; a fit's measurements file: its reader, its parameters resolved
// against a fixed case and that case solved at the ends of the fit's search).
// Shared by the libFuzzer
// target (fuzz/case_fuzzer.cpp, built by scripts/fuzz.sh) and the test that
// replays every input the fuzzer ever crashed on (tests/fuzz_regressions/,
// tests/unit/fuzz/test_fuzz_regressions.cpp).
#pragma once

#include <string>
#include <string_view>

namespace coremodal::fuzz {

enum class Outcome {
    invalid,       // the reader refused the text with an InputError (a located message)
    solved,        // a valid scene, and its beam-level modes
    not_solvable,  // a valid scene the beam level refused (InputError) or could not solve (SolveError)
};

// Every outcome above is correct behaviour. Anything else is a bug and
// escapes: an exception of another type (std::logic_error from an internal
// assertion, std::out_of_range, ...) or a std::logic_error thrown here for a
// result that breaks an invariant (a frequency that is not a finite number).
// `path` names the case in messages and resolves a relative [mesh] file.
Outcome run_case_text(std::string_view text, const std::string& path = "fuzz.toml");

}  // namespace coremodal::fuzz
