#include "scene/model_choice.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace coremodal {
namespace {

// In the order of the messages that list them (the case reader's, --model's).
constexpr std::array<std::pair<ModelChoice, std::string_view>, 5> kWords{{{ModelChoice::solid, "solid"},
                                                                          {ModelChoice::harmonic, "harmonic"},
                                                                          {ModelChoice::coupled, "coupled"},
                                                                          {ModelChoice::automatic, "auto"},
                                                                          {ModelChoice::beam, "beam"}}};

}  // namespace

std::string to_string(ModelChoice choice) {
    const auto* found = std::find_if(kWords.begin(), kWords.end(), [&](const auto& w) { return w.first == choice; });
    return std::string(found->second);
}

std::optional<ModelChoice> parse_model_choice(std::string_view word) {
    const auto* found = std::find_if(kWords.begin(), kWords.end(), [&](const auto& w) { return w.second == word; });
    if (found == kWords.end()) return std::nullopt;
    return found->first;
}

ModelChoice model_choice_named(std::string_view word) {
    const std::optional<ModelChoice> choice = parse_model_choice(word);
    COREMODAL_ASSERT(choice);
    return *choice;
}

ModelChoice model_option(const std::string& word) {
    if (const auto choice = parse_model_choice(word)) return *choice;
    std::string words;
    for (const auto& w : kWords) words += (words.empty() ? "" : ", ") + std::string(w.second);
    throw InputError("--model " + word + ": unknown model level; expected one of " + words);
}

const std::vector<std::string_view>& model_choice_words() {
    static const std::vector<std::string_view> words = [] {
        std::vector<std::string_view> out;
        for (const auto& w : kWords) out.push_back(w.second);
        return out;
    }();
    return words;
}

}  // namespace coremodal
