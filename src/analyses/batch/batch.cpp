#include "analyses/batch/batch.hpp"

#include "common/child_process.hpp"
#include "common/error.hpp"
#include "output/results_folder.hpp"
#include "scene/toml_text.hpp"

#include <toml++/toml.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>


namespace coremodal {
namespace fs = std::filesystem;
namespace {

// ---- a small JSON reader: enough for summary.json ---------------------------

struct JsonValue {
    enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
    double number = 0;
    std::string text;
    std::vector<std::pair<std::string, JsonValue>> members;  // object
    std::vector<JsonValue> items;                             // array
};

class JsonParser {
public:
    explicit JsonParser(const std::string& text) : t_(text) {}

    JsonValue document() {
        JsonValue v = value(0);
        if (peek() != '\0') fail("unexpected text after the value");
        return v;
    }

private:
    const std::string& t_;
    std::size_t p_ = 0;

    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("invalid JSON at character " + std::to_string(p_ + 1) + ": " + what);
    }
    char peek() {
        while (p_ < t_.size() && (t_[p_] == ' ' || t_[p_] == '\t' || t_[p_] == '\n' || t_[p_] == '\r')) ++p_;
        return p_ < t_.size() ? t_[p_] : '\0';
    }
    void expect(char c) {
        if (peek() != c) fail(std::string("expected '") + c + "'");
        ++p_;
    }
    bool literal(const char* word) {
        const std::size_t n = std::strlen(word);
        if (t_.compare(p_, n, word) != 0) return false;
        p_ += n;
        return true;
    }

    JsonValue value(int depth) {
        if (depth > 256) fail("nested too deeply");
        JsonValue v;
        const char c = peek();
        if (c == '{') {
            ++p_;
            v.kind = JsonValue::Kind::object;
            if (peek() == '}') return ++p_, v;
            for (;;) {
                if (peek() != '"') fail("expected a key");
                std::string key = string();
                expect(':');
                v.members.emplace_back(std::move(key), value(depth + 1));
                if (peek() == ',') {
                    ++p_;
                    continue;
                }
                expect('}');
                return v;
            }
        }
        if (c == '[') {
            ++p_;
            v.kind = JsonValue::Kind::array;
            if (peek() == ']') return ++p_, v;
            for (;;) {
                v.items.push_back(value(depth + 1));
                if (peek() == ',') {
                    ++p_;
                    continue;
                }
                expect(']');
                return v;
            }
        }
        if (c == '"') {
            v.kind = JsonValue::Kind::string;
            v.text = string();
            return v;
        }
        if (literal("true") || literal("false")) {
            v.kind = JsonValue::Kind::boolean;
            v.number = t_[p_ - 1] == 'e' && t_[p_ - 2] == 'u';
            return v;
        }
        if (literal("null")) return v;
        if (c == '-' || (c >= '0' && c <= '9')) {
            const char* begin = t_.c_str() + p_;
            char* end = nullptr;
            v.kind = JsonValue::Kind::number;
            v.number = std::strtod(begin, &end);
            if (end == begin) fail("bad number");
            p_ += static_cast<std::size_t>(end - begin);
            return v;
        }
        fail(c == '\0' ? std::string("unexpected end") : std::string("unexpected '") + c + "'");
    }

    std::string string() {
        ++p_;  // opening quote
        std::string s;
        while (p_ < t_.size() && t_[p_] != '"') {
            char c = t_[p_++];
            if (c != '\\') {
                s += c;
                continue;
            }
            if (p_ >= t_.size()) break;
            c = t_[p_++];
            switch (c) {
                case 'b': s += '\b'; break;
                case 'f': s += '\f'; break;
                case 'n': s += '\n'; break;
                case 'r': s += '\r'; break;
                case 't': s += '\t'; break;
                case 'u': {
                    if (p_ + 4 > t_.size()) fail("bad \\u escape");
                    const unsigned cp = static_cast<unsigned>(std::stoul(t_.substr(p_, 4), nullptr, 16));
                    p_ += 4;
                    if (cp < 0x80) {
                        s += static_cast<char>(cp);
                    } else if (cp < 0x800) {
                        s += static_cast<char>(0xC0 | (cp >> 6));
                        s += static_cast<char>(0x80 | (cp & 0x3F));
                    } else {
                        s += static_cast<char>(0xE0 | (cp >> 12));
                        s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
                        s += static_cast<char>(0x80 | (cp & 0x3F));
                    }
                    break;
                }
                default: s += c;  // \" \\ \/
            }
        }
        if (p_ >= t_.size()) fail("unterminated string");
        ++p_;  // closing quote
        return s;
    }
};

const JsonValue* json_find(const JsonValue& root, const std::string& path) {
    const JsonValue* v = &root;
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t dot = std::min(path.find('.', start), path.size());
        const std::string key = path.substr(start, dot - start);
        if (v->kind != JsonValue::Kind::object) return nullptr;
        const JsonValue* next = nullptr;
        for (const auto& [k, member] : v->members)
            if (k == key) next = &member;
        if (!next) return nullptr;
        v = next;
        start = dot + 1;
    }
    return v;
}

// ---- child processes ---------------------------------------------------------

std::string read_text(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string program_name(const std::string& program) {
    std::error_code ec;
    const fs::path real = fs::read_symlink(program, ec);
    return ec ? program : real.string();
}

void run_one(BatchCase& c, const BatchOptions& o, std::vector<std::string>& env) {
    const bool winder = is_winder_file(c.file);
    std::vector<std::string> args = {program_name(o.program), winder ? "winder" : "run", c.file, "--output",
                                     c.result_dir, "--quiet"};
    if (winder) c.note = "a two-drum winder (coremodal winder): its frequencies and crossings are in its report.md";
    if (o.mesh_level) {
        if (winder)
            c.note += "; a beam model: --mesh " + *o.mesh_level + " not applied";
        else if (case_has_mesh_file(c.file))
            c.note = "own mesh file: --mesh " + *o.mesh_level + " not applied";
        else
            args.insert(args.end(), {"--mesh", *o.mesh_level});
    }
    const ChildExit child = run_child(o.program, args, env, c.log_file);
    if (!child.started()) {
        c.error = "cannot start " + args[0] + ": " + std::strerror(child.spawn_error);
        return;
    }
    const int status = child.status;
    c.time_s = child.wall_s;

    const std::string message = first_error_line(read_text(c.log_file));
    if (WIFSIGNALED(status)) {
        c.error = "crashed: signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
        if (!message.empty()) c.error += ": " + message;
        return;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        c.error = !message.empty() ? message
                                   : "exit code " + std::to_string(WEXITSTATUS(status)) + " without a message";
        return;
    }
    const fs::path summary = fs::path(c.result_dir) / "summary.json";
    if (!fs::exists(summary)) {
        c.error = "finished without writing " + summary.string();
        return;
    }
    if (winder) {  // no f1 or safe speed of one roll: the winder's answer is its crossing table
        c.ok = true;
        return;
    }
    try {
        read_batch_summary(c, read_text(summary.string()));
        c.ok = true;
    } catch (const std::exception& e) {
        c.error = summary.string() + ": " + e.what();
    }
}

}  // namespace

std::optional<double> json_number(const std::string& json, const std::string& path) {
    const JsonValue root = JsonParser(json).document();
    const JsonValue* v = json_find(root, path);
    if (!v || v->kind != JsonValue::Kind::number) return std::nullopt;
    return v->number;
}

std::optional<std::string> json_string(const std::string& json, const std::string& path) {
    const JsonValue root = JsonParser(json).document();
    const JsonValue* v = json_find(root, path);
    if (!v || v->kind != JsonValue::Kind::string) return std::nullopt;
    return v->text;
}


void read_batch_summary(BatchCase& c, const std::string& summary_json) {
    const JsonValue root = JsonParser(summary_json).document();
    auto number = [&](const std::string& path) -> std::optional<double> {
        const JsonValue* v = json_find(root, path);
        if (!v || v->kind != JsonValue::Kind::number || !std::isfinite(v->number)) return std::nullopt;
        return v->number;
    };
    if (!json_find(root, "beam.fe_first_bending_hz")) throw std::runtime_error("no beam.fe_first_bending_hz");
    // The writer stores null when no bending mode was found among the modes (0 before).
    const auto f1 = number("beam.fe_first_bending_hz");
    c.f1_hz = f1 && *f1 > 0 ? f1 : std::nullopt;
    const auto ratio = number("beam.fe_over_timoshenko");
    c.fe_over_timoshenko = ratio && *ratio > 0 ? ratio : std::nullopt;
    c.diameter_m = number("case.rest_paper.outer_diameter");
    if (!c.diameter_m) c.diameter_m = number("case.core.outer_diameter");
    const JsonValue* supports = json_find(root, "case.supports.type");
    const bool free_free = supports && supports->kind == JsonValue::Kind::string && supports->text == "free";
    c.v_safe_m_s.reset();
    if (c.f1_hz && c.diameter_m && !free_free) c.v_safe_m_s = kSafeSpeedFactor * M_PI * *c.diameter_m * *c.f1_hz;
}

namespace {
// The parsed case file, or an empty table when it cannot be read (its run
// then reports why).
toml::table case_table_or_empty(const std::string& case_file) {
    try {
        return parse_toml_text(read_input_file(case_file, "case file"), case_file);
    } catch (const std::exception&) {
        return {};
    }
}
}  // namespace

bool case_has_mesh_file(const std::string& case_file) {
    return case_table_or_empty(case_file)["mesh"]["file"].is_string();
}

bool is_winder_file(const std::string& case_file) { return case_table_or_empty(case_file).contains("winder"); }

std::vector<std::string> batch_case_files(const std::vector<std::string>& inputs) {
    std::vector<std::string> files;
    for (const auto& input : inputs) {
        std::error_code ec;
        if (fs::is_directory(input, ec)) {
            std::vector<std::string> found;
            for (const auto& entry : fs::directory_iterator(input, ec))
                if (entry.path().extension() == ".toml" && !fs::is_directory(entry.path(), ec))
                    found.push_back(entry.path().string());
            if (ec) throw InputError("cannot read folder " + input + ": " + ec.message());
            if (found.empty()) throw InputError("no *.toml case files in folder " + input);
            std::sort(found.begin(), found.end());
            files.insert(files.end(), found.begin(), found.end());
        } else if (fs::exists(input, ec)) {
            files.push_back(input);
        } else {
            throw InputError("no such case file or folder: " + input);
        }
    }
    if (files.empty()) throw InputError("no case files given");
    return files;
}

std::vector<BatchCase> run_batch(const BatchOptions& o, std::ostream& progress) {
    const auto files = batch_case_files(o.inputs);
    // OUT is written in place, so that finished cases can be read while
    // the others run: an earlier batch there moves to OUT.previous first.
    start_folder_in_place(o.output_dir, o.force);

    // One result folder per case, named by the file stem; a stem seen before
    // (the same name in two folders) gets -2, -3, ...
    std::vector<BatchCase> cases;
    std::map<std::string, int> seen;
    for (const auto& f : files) {
        BatchCase c;
        c.file = f;
        const std::string stem = fs::path(f).stem().string();
        const int n = ++seen[stem];
        c.name = n == 1 ? stem : stem + "-" + std::to_string(n);
        c.result_dir = (fs::path(o.output_dir) / c.name).string();
        c.log_file = (fs::path(o.output_dir) / (c.name + ".log")).string();
        cases.push_back(std::move(c));
    }

    unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
    jobs = std::min<unsigned>(jobs, static_cast<unsigned>(cases.size()));
    std::vector<std::string> env = child_environment(jobs > 1);

    progress << "batch: " << cases.size() << (cases.size() == 1 ? " case, " : " cases, ") << jobs
             << " at a time, results in " << o.output_dir << std::endl;

    std::size_t width = 0;
    for (const auto& c : cases) width = std::max(width, c.name.size());
    std::atomic<std::size_t> next{0};
    std::mutex lock;
    std::size_t finished = 0;
    auto worker = [&] {
        for (std::size_t i; (i = next++) < cases.size();) {
            BatchCase& c = cases[i];
            try {
                run_one(c, o, env);
            } catch (const std::exception& e) {
                c.ok = false;
                c.error = e.what();
            }
            std::lock_guard<std::mutex> guard(lock);
            char head[64], time[64];
            std::snprintf(head, sizeof head, "[%zu/%zu] ", ++finished, cases.size());
            std::snprintf(time, sizeof time, "%.1f s", c.time_s);
            progress << head << c.name << std::string(width - c.name.size(), ' ')
                     << (c.ok ? "  ok " + std::string(time) : "  FAILED: " + c.error + "  (" + time + ")")
                     << (c.note.empty() ? "" : "  [" + c.note + "]") << std::endl;
        }
    };
    std::vector<std::thread> threads;
    for (unsigned j = 0; j < jobs; ++j) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
    return cases;
}


}  // namespace coremodal
