#include "output/report_html.hpp"

#include "output/text_file.hpp"

#include <cctype>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

namespace coremodal {
namespace fs = std::filesystem;
namespace {

// Nothing may leave the file: the browser is told so (the policy allows only
// the inline style and images carried in the page itself).
constexpr const char* kNoRequests = "default-src 'none'; img-src data:; style-src 'unsafe-inline'";

// Readable on screen and on paper, in the reader's own fonts.
constexpr const char* kStyle = R"(body{font-family:sans-serif;line-height:1.45;max-width:62em;margin:1.5em auto;padding:0 1em;color:#111;background:#fff}
h1{font-size:1.6em;border-bottom:2px solid #444;padding-bottom:.2em}h2{font-size:1.3em;margin-top:1.6em;border-bottom:1px solid #aaa}
table{border-collapse:collapse;margin:.8em 0;font-size:.92em}th,td{border:1px solid #999;padding:.25em .55em;vertical-align:top}
th{background:#e8e8e8}tr:nth-child(even) td{background:#f6f6f6}code{font-family:monospace;background:#f0f0f0;padding:0 .2em}
img{max-width:100%;height:auto;border:1px solid #ddd}.missing{color:#a00}
@media print{body{max-width:none}img{page-break-inside:avoid}})";

std::string escaped(std::string_view text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string media_type(const fs::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".png") return "image/png";
    if (ext == ".svg") return "image/svg+xml";
    if (ext == ".gif") return "image/gif";
    if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
    return "";
}

// ![alt](file) as an <img> carrying the file, or words when it cannot.
std::string picture(std::string_view alt, std::string_view target, const fs::path& folder) {
    const fs::path file = folder / std::string(target);
    const std::string type = media_type(file);
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    if (in) bytes << in.rdbuf();
    if (type.empty() || !in || bytes.str().empty())
        return "<em class=\"missing\">(picture " + escaped(target) + " is missing: " + escaped(alt) + ")</em>";
    return "<img alt=\"" + escaped(alt) + "\" src=\"data:" + type + ";base64," + base64(bytes.str()) + "\">";
}

class Inline {
public:
    Inline(std::string_view text, const fs::path& folder) : s_(text), folder_(folder) {}

    std::string html() {
        std::string out;
        while (i_ < s_.size()) {
            if (s_[i_] == '`' && span('`', "code", out)) continue;
            if (s_.substr(i_, 2) == "![" && bracketed(i_ + 1, out, true)) continue;
            if (s_[i_] == '[' && bracketed(i_, out, false)) continue;
            if (s_.substr(i_, 2) == "**" && strong(out)) continue;
            if (s_[i_] == '*' && emphasis(out)) continue;
            out += escaped(s_.substr(i_++, 1));
        }
        return out;
    }

private:
    std::string_view s_;
    const fs::path& folder_;
    std::size_t i_ = 0;

    bool span(char mark, const char* tag, std::string& out) {
        const std::size_t end = s_.find(mark, i_ + 1);
        if (end == std::string_view::npos) return false;
        out += std::string("<") + tag + ">" + escaped(s_.substr(i_ + 1, end - i_ - 1)) + "</" + tag + ">";
        i_ = end + 1;
        return true;
    }

    bool strong(std::string& out) {
        const std::size_t end = s_.find("**", i_ + 2);
        if (end == std::string_view::npos || end == i_ + 2) return false;
        out += "<strong>" + Inline(s_.substr(i_ + 2, end - i_ - 2), folder_).html() + "</strong>";
        i_ = end + 2;
        return true;
    }

    // *words*, but not a lone * ("* a diameter added") nor 2 * 3.
    bool emphasis(std::string& out) {
        if (i_ + 1 >= s_.size() || std::isspace(static_cast<unsigned char>(s_[i_ + 1]))) return false;
        const std::size_t end = s_.find('*', i_ + 1);
        if (end == std::string_view::npos || std::isspace(static_cast<unsigned char>(s_[end - 1]))) return false;
        out += "<em>" + Inline(s_.substr(i_ + 1, end - i_ - 1), folder_).html() + "</em>";
        i_ = end + 1;
        return true;
    }

    // [text](target) from `open` (the '['); an image when `image`.
    bool bracketed(std::size_t open, std::string& out, bool image) {
        const std::size_t close = s_.find("](", open);
        if (close == std::string_view::npos) return false;
        const std::size_t end = s_.find(')', close + 2);
        if (end == std::string_view::npos) return false;
        const std::string_view text = s_.substr(open + 1, close - open - 1);
        const std::string_view target = s_.substr(close + 2, end - close - 2);
        if (image) out += picture(text, target, folder_);
        else
            out += Inline(text, folder_).html() + (text == target ? "" : " (" + escaped(target) + ")");
        i_ = end + 1;
        return true;
    }
};

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::size_t indent(std::string_view line) { return line.find_first_not_of(' ') == std::string_view::npos ? 0 : line.find_first_not_of(' '); }

// A table row's cells: split at '|' outside `code` spans.
std::vector<std::string_view> cells(std::string_view row) {
    row = trimmed(row);
    if (!row.empty() && row.front() == '|') row.remove_prefix(1);
    if (!row.empty() && row.back() == '|') row.remove_suffix(1);
    std::vector<std::string_view> out;
    bool in_code = false;
    std::size_t start = 0;
    for (std::size_t i = 0; i < row.size(); ++i) {
        if (row[i] == '`') in_code = !in_code;
        if (row[i] == '|' && !in_code) {
            out.push_back(trimmed(row.substr(start, i - start)));
            start = i + 1;
        }
    }
    out.push_back(trimmed(row.substr(start)));
    return out;
}

bool is_separator_row(std::string_view row) {
    return trimmed(row).find_first_not_of("|-: ") == std::string_view::npos && row.find('-') != std::string_view::npos;
}

// Which of the list kinds a line starts, and where its text begins.
bool list_item(std::string_view line, bool& ordered, std::size_t& text_at) {
    const std::size_t at = indent(line);
    if (line.substr(at, 2) == "- " || line.substr(at, 2) == "* ") {
        ordered = false;
        text_at = at + 2;
        return true;
    }
    std::size_t d = at;
    while (d < line.size() && std::isdigit(static_cast<unsigned char>(line[d]))) ++d;
    if (d > at && line.substr(d, 2) == ". ") {
        ordered = true;
        text_at = d + 2;
        return true;
    }
    return false;
}

class Blocks {
public:
    Blocks(const std::string& markdown, const fs::path& folder) : folder_(folder) {
        std::istringstream in(markdown);
        for (std::string line; std::getline(in, line);) {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            lines_.push_back(line);
        }
    }

    std::string html() {
        while (at_ < lines_.size()) {
            const std::string_view line = lines_[at_];
            bool ordered = false;
            std::size_t text_at = 0;
            if (trimmed(line).empty()) ++at_;
            else if (heading()) continue;
            else if (trimmed(line).front() == '|') table();
            else if (list_item(line, ordered, text_at)) list(indent(line));
            else paragraph();
        }
        return out_.str();
    }

    std::string title() const {
        for (const std::string& l : lines_)
            if (l.rfind("# ", 0) == 0) return std::string(trimmed(std::string_view(l).substr(2)));
        return "coremodal report";
    }

private:
    std::vector<std::string> lines_;
    const fs::path& folder_;
    std::size_t at_ = 0;
    std::ostringstream out_;

    std::string inline_html(std::string_view text) const { return Inline(text, folder_).html(); }

    bool heading() {
        const std::string_view line = lines_[at_];
        const std::size_t level = line.find_first_not_of('#');
        if (level == 0 || level > 6 || level == std::string_view::npos || line[level] != ' ') return false;
        std::string tag = "h";
        tag += std::to_string(level);
        out_ << "<" << tag << ">" << inline_html(trimmed(line.substr(level))) << "</" << tag << ">\n";
        ++at_;
        return true;
    }

    void table() {
        std::vector<std::string_view> rows;
        while (at_ < lines_.size() && !trimmed(lines_[at_]).empty() && trimmed(lines_[at_]).front() == '|')
            rows.push_back(lines_[at_++]);
        const bool has_head = rows.size() >= 2 && is_separator_row(rows[1]);
        std::vector<std::string> align;
        if (has_head)
            for (std::string_view c : cells(rows[1]))
                align.push_back(c.size() > 1 && c.back() == ':' ? (c.front() == ':' ? "center" : "right") : "");
        const auto row_html = [&](std::string_view row, const char* tag) {
            out_ << "<tr>";
            const auto cs = cells(row);
            for (std::size_t k = 0; k < cs.size(); ++k) {
                out_ << "<" << tag;
                if (k < align.size() && !align[k].empty()) out_ << " style=\"text-align:" << align[k] << "\"";
                out_ << ">" << inline_html(cs[k]) << "</" << tag << ">";
            }
            out_ << "</tr>\n";
        };
        out_ << "<table>\n";
        if (has_head) out_ << "<thead>\n", row_html(rows[0], "th"), out_ << "</thead>\n";
        out_ << "<tbody>\n";
        for (std::size_t r = has_head ? 2 : 0; r < rows.size(); ++r) row_html(rows[r], "td");
        out_ << "</tbody>\n</table>\n";
    }

    // Items at indentation `base`; deeper items make a list inside the item
    // before them, and deeper plain lines continue it.
    void list(std::size_t base) {
        bool ordered = false;
        std::size_t text_at = 0;
        list_item(lines_[at_], ordered, text_at);
        const char* tag = ordered ? "ol" : "ul";
        out_ << "<" << tag << ">\n";
        bool open = false;
        while (at_ < lines_.size() && !trimmed(lines_[at_]).empty()) {
            const std::string_view line = lines_[at_];
            const std::size_t depth = indent(line);
            bool item_ordered = false;
            const bool item = list_item(line, item_ordered, text_at);
            const char first = trimmed(line).front();
            if (item && depth == base) {
                if (open) out_ << "</li>\n";
                out_ << "<li>" << inline_html(line.substr(text_at));
                open = true;
                ++at_;
            } else if (item && depth > base) {
                out_ << "\n";
                list(depth);
            } else if (item || first == '|' || first == '#' || (base > 0 && depth < base)) {
                break;  // the enclosing list's next item, or a table or heading
            } else {
                out_ << " " << inline_html(trimmed(line));  // the item goes on
                ++at_;
            }
        }
        if (open) out_ << "</li>\n";
        out_ << "</" << tag << ">\n";
    }

    void paragraph() {
        std::string text;
        bool ordered = false;
        std::size_t text_at = 0;
        while (at_ < lines_.size() && !trimmed(lines_[at_]).empty() && trimmed(lines_[at_]).front() != '|' &&
               lines_[at_].rfind("#", 0) != 0 && !(text.size() && list_item(lines_[at_], ordered, text_at))) {
            if (!text.empty()) text += '\n';
            text += trimmed(lines_[at_]);
            ++at_;
        }
        out_ << "<p>" << inline_html(text) << "</p>\n";
    }
};

}  // namespace

std::string base64(const std::string& bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        unsigned v = 0;
        for (std::size_t k = 0; k < 3; ++k)
            v = v << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

std::string report_html(const std::string& markdown, const fs::path& folder) {
    Blocks blocks(markdown, folder);
    const std::string body = blocks.html();
    std::ostringstream page;
    page << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         << "<meta http-equiv=\"Content-Security-Policy\" content=\"" << kNoRequests << "\">\n"
         << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         << "<title>" << escaped(blocks.title()) << "</title>\n<style>\n" << kStyle << "\n</style>\n</head>\n<body>\n"
         << body << "<hr>\n<p><small>coremodal report.html: the page of report.md, pictures included; the "
         << "numbers are also in the folder's summary.json and tables.</small></p>\n</body>\n</html>\n";
    return page.str();
}

void write_report_html(const fs::path& folder) {
    const fs::path md = folder / "report.md";
    std::error_code ec;
    if (!fs::is_regular_file(md, ec)) return;
    std::ifstream in(md, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    write_text_file(folder / "report.html", report_html(text.str(), folder));
}

}  // namespace coremodal
