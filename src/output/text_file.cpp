#include "output/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace coremodal {

void write_text_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    // Closed here and checked: the bytes reach the disk at close, and a full
    // disk then fails where an unchecked close would leave 0 bytes behind.
    out.close();
    if (!out) throw std::runtime_error("cannot write " + path.string() + " (" + std::strerror(errno) + ")");
}

}  // namespace coremodal
