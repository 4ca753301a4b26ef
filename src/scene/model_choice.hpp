// The model level a case asks for (`model = ...`, --model): one of the four
// levels, or "auto" for the cheapest that represents the whole scene
// (models/choose.hpp picks it). The words here are the only spelling of a
// level: the case reader, --model, summary.json and every message convert
// through to_string and parse_model_choice. What a level can do is asked of
// scene/level_traits.hpp, never by comparing a name.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace coremodal {

enum class ModelChoice { automatic, beam, harmonic, coupled, solid };

// "auto", "beam", "harmonic", "coupled" or "solid": the case file's and summary.json's word.
std::string to_string(ModelChoice choice);

// The choice a word names, or nothing.
std::optional<ModelChoice> parse_model_choice(std::string_view word);

// The choice a resolved scene or a result names by its word (Scene::model,
// ModelInfo::level: written by the reader, --model or chosen_level, so
// always one of the words).
ModelChoice model_choice_named(std::string_view word);

// The choice a command line's --model names; an InputError naming the
// option and the words it takes for any other word.
ModelChoice model_option(const std::string& word);

// Every word, in the order the case reader's and --model's messages list them.
const std::vector<std::string_view>& model_choice_words();

inline std::ostream& operator<<(std::ostream& out, ModelChoice choice) { return out << to_string(choice); }

// summary.json writes the word, never the enum's number (found by nlohmann::json through ADL).
template <typename Json>
void to_json(Json& json, ModelChoice choice) {
    json = to_string(choice);
}

}  // namespace coremodal
