// Writing a whole text file at once (reports, CSV, JSON, worker records).
#pragma once

#include <filesystem>
#include <string>

namespace coremodal {

// Writes `text` to `path` byte for byte (no newline translation); throws
// std::runtime_error naming the path and the system's reason ("No space
// left on device") if the file cannot be written or closed.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace coremodal
