#include "durability/durability_data.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "scene/units.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace coremodal {
namespace {

// The least number of points: two parameters and one degree of freedom for S_log ({24}).
constexpr int kMinimumPoints = 3;
// The first cycle count there is (Fig. 13: the x-scale starts from 0.5).
constexpr double kFirstCycles = 0.5;
constexpr const char* kWeightUnits = "N, kN, kg or t";

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

struct Field {
    std::string text;
    int column = 1;  // 1-based character column of its first character
};

std::vector<Field> split_fields(const std::string& line) {
    std::vector<Field> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        const std::string raw = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const std::size_t lead = raw.find_first_not_of(" \t");
        fields.push_back({trim(raw), static_cast<int>(start + (lead == std::string::npos ? 0 : lead)) + 1});
        if (comma == std::string::npos) return fields;
        start = comma + 1;
    }
}

class Reader {
public:
    explicit Reader(std::string source) : source_(std::move(source)) {}
    [[noreturn]] void fail(int line, int column, const std::string& what) const {
        throw InputError(source_ + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what);
    }
    const std::string& source() const { return source_; }

private:
    std::string source_;
};

std::optional<double> number(const std::string& text) {
    double v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return v;
}

// "# key = value" above the header: the test chuck.
void read_chuck_line(const Reader& r, const std::string& line, int line_no, DurabilityData& d) {
    const std::string body = trim(line.substr(1));
    const auto eq = body.find('=');
    if (eq == std::string::npos) return;  // a comment
    const std::string key = trim(body.substr(0, eq)), value = trim(body.substr(eq + 1));
    const int value_col = static_cast<int>(line.find(value, line.find('='))) + 1;
    if (key == "chuck_length") {
        try {
            d.chuck_length_m = parse_quantity(value, Dimension::length);
        } catch (const std::exception& e) {
            r.fail(line_no, value_col, "chuck_length = " + value + ": " + e.what());
        }
        if (!(d.chuck_length_m > 0) || !std::isfinite(d.chuck_length_m))
            r.fail(line_no, value_col, "chuck_length = " + value + " must be a positive length, e.g. 100 mm");
    } else if (key == "chuck_type") {
        if (value != kChuckTypes[0] && value != kChuckTypes[1])
            r.fail(line_no, value_col,
                   "chuck_type = " + value + ": expected expanding or non-expanding (the simulator's test chuck)");
        d.chuck_type = value;
    }
}

// "cycles,max_roll_weight [kN]".
void read_header(const Reader& r, const std::string& line, int line_no, DurabilityData& d) {
    const std::vector<Field> f = split_fields(line);
    if (f.size() != 2)
        r.fail(line_no, 1, "header '" + trim(line) + "' has " + std::to_string(f.size()) +
                               " columns; expected two: cycles,max_roll_weight [kN]");
    if (f[0].text != "cycles")
        r.fail(line_no, f[0].column, "column 1 is '" + f[0].text + "'; expected cycles (winding-unwinding cycles to "
                                     "delamination, from 0.5)");
    const auto open = f[1].text.find('['), close = f[1].text.rfind(']');
    if (open == std::string::npos || close == std::string::npos || close < open || close + 1 != f[1].text.size())
        r.fail(line_no, f[1].column, "column 2 '" + f[1].text + "' has no unit; expected the weight with its unit in "
                                     "brackets, e.g. max_roll_weight [kN] (" + kWeightUnits + ")");
    d.weight_name = trim(f[1].text.substr(0, open));
    d.weight_unit = trim(f[1].text.substr(open + 1, close - open - 1));
    d.weight_unit_newton = weight_unit_in_newton(d.weight_unit);
    if (d.weight_name.empty()) d.weight_name = "max_roll_weight";
    if (d.weight_unit_newton == 0)
        r.fail(line_no, f[1].column + static_cast<int>(open) + 1,
               "unit '" + d.weight_unit + "' of column 2 is not a weight; expected " + kWeightUnits);
}

void read_point(const Reader& r, const std::string& line, int line_no, DurabilityData& d) {
    const std::vector<Field> f = split_fields(line);
    if (f.size() != 2)
        r.fail(line_no, 1, "row has " + std::to_string(f.size()) + " values; expected two: cycles," +
                               d.weight_name + " [" + d.weight_unit + "]");
    const std::optional<double> x = number(f[0].text), y = number(f[1].text);
    if (!x || !std::isfinite(*x))
        r.fail(line_no, f[0].column, "cycles = '" + f[0].text + "' is not a finite number");
    if (!y || !std::isfinite(*y))
        r.fail(line_no, f[1].column, d.weight_name + " = '" + f[1].text + "' is not a finite number");
    if (*x < kFirstCycles)
        r.fail(line_no, f[0].column, "cycles = " + f[0].text + " is below 0.5; the count starts at 0.5 (a core that "
                                     "fails before the first unwinding has lasted half a cycle)");
    if (*y <= 0)
        r.fail(line_no, f[1].column, d.weight_name + " = " + f[1].text + " " + d.weight_unit +
                                         " must be positive (the roll weight the core carried)");
    d.cycles.push_back(*x);
    d.weights.push_back(*y);
    d.lines.push_back(line_no);
}

}  // namespace

double weight_unit_in_newton(const std::string& unit) {
    if (unit == "N") return 1;
    if (unit == "kN") return 1e3;
    if (unit == "kg") return kStandardGravityForWeight;
    if (unit == "t") return 1e3 * kStandardGravityForWeight;
    return 0;
}

DurabilityData parse_durability_data(const std::string& text, const std::string& source) {
    const Reader r(source);
    DurabilityData d;
    d.source = source;
    std::istringstream in(text);
    std::string line;
    int line_no = 0, header_line = 0;
    while (std::getline(in, line)) {
        ++line_no;
        if (trim(line).empty()) continue;
        if (trim(line)[0] == '#') {
            if (!header_line) read_chuck_line(r, trim(line), line_no, d);
            continue;
        }
        if (!header_line) {
            header_line = line_no;
            read_header(r, line, line_no, d);
        } else {
            read_point(r, line, line_no, d);
        }
    }
    const int where = header_line ? header_line : 1;
    if (!header_line) r.fail(1, 1, "no header line; expected cycles,max_roll_weight [kN] after the # lines");
    if (d.chuck_length_m == 0)
        r.fail(where, 1, "the test chuck's length is missing; expected a line '# chuck_length = 100 mm' above the header");
    if (d.chuck_type.empty())
        r.fail(where, 1, "the test chuck's type is missing; expected a line '# chuck_type = non-expanding' (or "
                         "expanding) above the header");
    if (static_cast<int>(d.cycles.size()) < kMinimumPoints)
        r.fail(line_no, 1, std::to_string(d.cycles.size()) + " data points; the power-law fit needs at least " +
                               std::to_string(kMinimumPoints) + " (two parameters and one degree of freedom for S_log)");
    bool distinct = false;
    for (double x : d.cycles) distinct = distinct || x != d.cycles.front();
    if (!distinct)
        r.fail(d.lines.front(), 1, "every point is at " + significant(d.cycles.front()) +
                                       " cycles; the slope b1 needs points at two or more cycle counts");
    return d;
}

DurabilityData read_durability_data(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot be read (no such file, or no permission)");
    std::ostringstream s;
    s << in.rdbuf();
    return parse_durability_data(s.str(), path);
}

}  // namespace coremodal
