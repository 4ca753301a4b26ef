// libFuzzer target over the case reader, the scene description and the beam
// model level (fuzz/case_harness.hpp). Build and run: scripts/fuzz.sh.
// An exception that escapes run_case_text is a bug: it reaches std::terminate,
// which libFuzzer reports as a crash and saves the input.
#include "case_harness.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    coremodal::fuzz::run_case_text(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
