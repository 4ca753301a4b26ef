// report.html from report.md: the markdown subset of coremodal's reports as
// HTML, pictures carried in the page, nothing that could leave the file.
// (The page in a real browser: python/tests/test_report_html.py.)
#include "output/report_html.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace coremodal;
namespace fs = std::filesystem;

namespace {

struct Folder {
    fs::path path = fs::temp_directory_path() / ("coremodal_test_report_html_" + std::to_string(::getpid()));
    Folder() { fs::create_directories(path); }
    ~Folder() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
    void write(const std::string& name, const std::string& bytes) const {
        std::ofstream(path / name, std::ios::binary) << bytes;
    }
};

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("base64 is RFC 4648's, padding included", "[output][report_html]") {
    // RFC 4648, section 10 (test vectors).
    CHECK(base64("") == "");
    CHECK(base64("f") == "Zg==");
    CHECK(base64("fo") == "Zm8=");
    CHECK(base64("foo") == "Zm9v");
    CHECK(base64("foob") == "Zm9vYg==");
    CHECK(base64("fooba") == "Zm9vYmE=");
    CHECK(base64("foobar") == "Zm9vYmFy");
    CHECK(base64(std::string("\xff\x00\x80", 3)) == "/wCA");
}

TEST_CASE("Headings, tables, lists and inline marks become their HTML", "[output][report_html]") {
    const Folder folder;
    const std::string md = "# Core 76 <x15>\n\nIntro with `a|b` and **bold *inner* x** and *em*, "
                           "5 * 3 stays.\n\n## Modes\n\n| mode | f (Hz) |\n|---|---:|\n| 1 | **12.5** |\n"
                           "| `x|y` | 3 |\n\n- one\n  more\n  - nested\n- two\n\n1. first\n2. second\n";
    const std::string html = report_html(md, folder.path);
    CHECK(has(html, "<title>Core 76 &lt;x15&gt;</title>"));
    CHECK(has(html, "<h1>Core 76 &lt;x15&gt;</h1>"));
    CHECK(has(html, "<h2>Modes</h2>"));
    CHECK(has(html, "<code>a|b</code>"));
    CHECK(has(html, "<strong>bold <em>inner</em> x</strong>"));
    CHECK(has(html, "<em>em</em>"));
    CHECK(has(html, "5 * 3 stays"));
    CHECK(has(html, "<thead>\n<tr><th>mode</th><th style=\"text-align:right\">f (Hz)</th></tr>"));
    CHECK(has(html, "<tr><td>1</td><td style=\"text-align:right\"><strong>12.5</strong></td></tr>"));
    CHECK(has(html, "<td><code>x|y</code></td>"));  // a | inside code does not split the cell
    CHECK(has(html, "<ul>\n<li>one more\n<ul>\n<li>nested</li>\n</ul>\n</li>\n<li>two</li>\n</ul>"));
    CHECK(has(html, "<ol>\n<li>first</li>\n<li>second</li>\n</ol>"));
}

TEST_CASE("Pictures travel inside the page; a missing one is said, links are text", "[output][report_html]") {
    const Folder folder;
    const std::string png("\x89PNG\r\n\x1a\n", 8);  // the bytes do not matter here, only that they are carried
    folder.write("spectrum.png", png);
    const std::string html =
        report_html("![spectrum](spectrum.png)\n\n![gone](gone.png)\n\nsee [the docs](docs/reference/results.md)\n", folder.path);
    CHECK(has(html, "<img alt=\"spectrum\" src=\"data:image/png;base64," + base64(png) + "\">"));
    CHECK(has(html, "picture gone.png is missing"));
    CHECK_FALSE(has(html, "src=\"gone.png\""));
    CHECK(has(html, "see the docs (docs/reference/results.md)"));
    // Nothing may be fetched: no href, no external src, a policy that forbids it.
    CHECK_FALSE(has(html, "href="));
    CHECK_FALSE(has(html, "<script"));
    CHECK(has(html, "Content-Security-Policy\" content=\"default-src 'none'; img-src data:"));
}

TEST_CASE("write_report_html writes beside report.md, and nothing without it", "[output][report_html]") {
    const Folder folder;
    write_report_html(folder.path);
    CHECK_FALSE(fs::exists(folder.path / "report.html"));
    folder.write("report.md", "# t\n\nbody\n");
    write_report_html(folder.path);
    std::ifstream in(folder.path / "report.html");
    const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(has(html, "<p>body</p>"));
}
