// A run with pictures draws its first bending mode swinging (a strip of
// frames, and a GIF where python has PIL) and report.md shows it; modes.xdmf
// lists the modes as time steps.
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

// The shipped clamped core at the harmonic level: its first mode is bending
// (788 display nodes, a second or two).
const std::string kCase = COREMODAL_SOURCE_DIR "/cases/02-clamped-76x15.toml";

// Width and height from a PNG's IHDR chunk (0 x 0 if it is not a PNG).
std::pair<unsigned, unsigned> png_size(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    unsigned char header[24] = {};
    in.read(reinterpret_cast<char*>(header), sizeof header);
    if (!in || header[1] != 'P' || header[2] != 'N' || header[3] != 'G') return {0, 0};
    auto word = [&](int at) {
        return unsigned(header[at]) << 24 | unsigned(header[at + 1]) << 16 | unsigned(header[at + 2]) << 8 |
               unsigned(header[at + 3]);
    };
    return {word(16), word(20)};
}

}  // namespace

TEST_CASE("A run's report shows the first bending mode swinging", "[app][cli][report][pictures]") {
    TempDir dir("animation");
    const Run r = run_coremodal(dir, "run '" + kCase + "' --model harmonic -o out -q");
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    const fs::path out = dir.path / "out";
    const std::string report = slurp(out / "report.md");
    CHECK(report.find("![mode 1 swinging](mode_01_frames.png)") != std::string::npos);
    const auto [width, height] = png_size(out / "mode_01_frames.png");
    CHECK(width == 1000);  // python/coremodal/frames.py STRIP_WIDTH_PX
    CHECK(height > 300);   // five side views
    if (fs::exists(out / "mode_01.gif")) CHECK(report.find("([animated](mode_01.gif))") != std::string::npos);

    // modes.xdmf: the modes of modes.csv (a header line, a line per mode)
    // are the time steps 1..K.
    std::ifstream csv(out / "modes.csv");
    int n_modes = -1;
    for (std::string line; std::getline(csv, line);) ++n_modes;
    REQUIRE(n_modes >= 4);
    const std::string xdmf = slurp(out / "modes.xdmf");
    CHECK(xdmf.find("CollectionType=\"Temporal\"") != std::string::npos);
    for (int t = 1; t <= n_modes; ++t)
        CHECK(xdmf.find("<Time Value=\"" + std::to_string(t) + "\"/>") != std::string::npos);
    CHECK(xdmf.find("<Time Value=\"" + std::to_string(n_modes + 1) + "\"/>") == std::string::npos);
}
