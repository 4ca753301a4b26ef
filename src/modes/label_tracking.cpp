#include "modes/label_tracking.hpp"

#include "modes/tracking.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

std::string ModeKey::text() const {
    std::string s = label_text(ModeLabel{.type = type, .n = n, .m = m});
    if (occurrence > 1) s += " #" + std::to_string(occurrence);
    return s;
}

std::vector<DistinctMode> distinct_modes(const std::vector<Mode>& modes) {
    std::vector<DistinctMode> out;
    for (const Mode& mode : modes) {
        const ModeLabel& l = mode.label;
        if (l.type == "rigid" || l.type == "mixed") continue;
        // A partner: the latest distinct mode of the same label, within the tolerance.
        DistinctMode* partner = nullptr;
        int same_label = 0;
        for (auto& d : out)
            if (d.key.type == l.type && d.key.n == l.n && d.key.m == l.m) {
                partner = &d;
                ++same_label;
            }
        if (partner && std::abs(mode.frequency_hz - partner->frequency_hz) <=
                           kDegenerateTolerance * std::max(mode.frequency_hz, partner->frequency_hz)) {
            ++partner->multiplicity;
            continue;
        }
        out.push_back({{l.type, l.n, l.m, same_label + 1}, mode.frequency_hz, mode.index, 1});
    }
    return out;
}

bool has_mode_type(const std::vector<Mode>& modes, const std::string& type) {
    const std::vector<DistinctMode> distinct = distinct_modes(modes);
    return std::any_of(distinct.begin(), distinct.end(), [&](const DistinctMode& d) { return d.key.type == type; });
}

namespace {

const DistinctMode* find_key(const std::vector<DistinctMode>& modes, const ModeKey& key) {
    for (const auto& d : modes)
        if (d.key == key) return &d;
    return nullptr;
}

// The role of `d` among the last run's modes: the name of the last role
// whose type's first mode it is, or "".
std::string role_of(const DistinctMode& d, const std::vector<DistinctMode>& last, const std::vector<ModeRole>& roles) {
    std::string role;
    for (const auto& [name, type] : roles) {
        const auto first_of_type =
            std::find_if(last.begin(), last.end(), [&, type = type](const DistinctMode& x) { return x.key.type == type; });
        if (first_of_type != last.end() && first_of_type->key == d.key) role = name;
    }
    return role;
}

}  // namespace

std::vector<LabelTrack> track_by_label(const std::vector<std::vector<DistinctMode>>& runs,
                                       const std::vector<ModeRole>& roles) {
    std::vector<LabelTrack> tracks;
    if (runs.empty()) return tracks;
    const auto& last = runs.back();
    for (const auto& d : last) {
        const bool everywhere = std::all_of(runs.begin(), runs.end(),
                                            [&](const auto& run) { return find_key(run, d.key) != nullptr; });
        std::string role = role_of(d, last, roles);
        if (!everywhere && role.empty()) continue;
        LabelTrack t;
        t.key = d.key;
        t.role = std::move(role);
        for (const auto& run : runs) {
            const DistinctMode* x = find_key(run, d.key);
            t.frequency_hz.push_back(x ? std::optional<double>(x->frequency_hz) : std::nullopt);
        }
        tracks.push_back(std::move(t));
    }
    return tracks;
}

}  // namespace coremodal
