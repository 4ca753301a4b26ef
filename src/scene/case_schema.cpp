#include "scene/case_schema.hpp"

#include "common/join.hpp"
#include "scene/units.hpp"

#include <algorithm>
#include <cmath>
#include <cctype>

namespace coremodal {

std::string_view default_material(std::string_view owner) {
    if (owner == "core") return kDefaultCoreMaterial;
    if (owner == "rest_paper") return kDefaultRestPaperMaterial;
    if (owner == "chuck") return kDefaultChuckMaterial;
    return "";
}

std::string child_table(std::string_view parent, std::string_view key, std::string_view support_type) {
    if (key == "material") return "material";
    if (parent == "supports" && (key == "left" || key == "right")) return support_type == "chucks" ? "chuck" : "clamp";
    return std::string(key);
}

const KeySpec* find_key(std::string_view table, std::string_view key) {
    for (const KeySpec& spec : case_schema())
        if (spec.table == table && spec.key == key) return &spec;
    return nullptr;
}

std::vector<std::string_view> keys_of(std::string_view table) {
    std::vector<std::string_view> out;
    for (const KeySpec& spec : case_schema())
        if (spec.table == table) out.push_back(spec.key);
    return out;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    const auto low = [](char c) {
        return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    };
    // Optimal string alignment distance on three rolling rows.
    std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = low(a[i - 1]) == low(b[j - 1]) ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && low(a[i - 1]) == low(b[j - 2]) && low(a[i - 2]) == low(b[j - 1]))
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        before.swap(previous);
        previous.swap(current);
    }
    return previous[b.size()];
}

std::string_view nearest(std::string_view word, const std::vector<std::string_view>& candidates) {
    // A typo changes a few characters; more than a third of the word is a
    // different word, and suggesting it would mislead.
    constexpr std::size_t kShortWord = 3;  // "nu", "E": one slip at most
    const std::size_t allowed =
        word.size() <= kShortWord ? 1 : std::max<std::size_t>(2, word.size() / 3);
    std::string_view best;
    std::size_t best_distance = allowed + 1;
    for (std::string_view c : candidates) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_distance) {
            best = c;
            best_distance = d;
        }
    }
    return best;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& candidates, char quote) {
    const std::string_view near = nearest(word, candidates);
    return near.empty() ? "" : "; did you mean " + (quote + std::string(near) + quote) + "?";
}

std::string did_you_mean_or_choices(std::string_view word, const std::vector<std::string_view>& candidates) {
    const std::string typo = did_you_mean(word, candidates);
    return typo.empty() ? "; expected one of " + join(candidates) : typo;
}

std::optional<std::string> out_of_range(const KeySpec& spec, double v, std::string_view plain_number) {
    if (spec.min_exclusive && !(v > spec.min))
        return "must be " + (spec.min == 0 ? std::string("positive")
                                           : "larger than " + format_quantity(spec.min, spec.dimension));
    if (!spec.min_exclusive && v < spec.min)
        return "must be " + (spec.min == 0 ? std::string("zero or positive")
                                           : "at least " + format_quantity(spec.min, spec.dimension));
    if (!(v > spec.max)) return std::nullopt;
    std::string why = "is too large: expected at most " + format_quantity(spec.max, spec.dimension);
    if (!plain_number.empty() && spec.dimension != Dimension::dimensionless)
        why += std::string("; plain numbers are in ") + si_unit(spec.dimension) +
               (spec.dimension == Dimension::length
                    ? ", for millimetres write \"" + std::string(plain_number) + " mm\""
                    : "");
    return why;
}

std::optional<std::string> integer_out_of_range(const KeySpec& spec, std::int64_t v) {
    // Compared as doubles: the bounds are far inside both ranges.
    if (static_cast<double>(v) >= spec.min && static_cast<double>(v) <= spec.max) return std::nullopt;
    return "is out of range; expected " + std::to_string(static_cast<long long>(spec.min)) + " to " +
           std::to_string(static_cast<long long>(spec.max));
}

}  // namespace coremodal
