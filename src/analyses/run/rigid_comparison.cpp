#include "analyses/run/rigid_comparison.hpp"

#include "effects/chuck_placement.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace coremodal {

Scene rigid_clamp_variant(const Scene& scene) {
    Scene rigid = scene;
    rigid.name = scene.name + "-rigid";
    rigid.supports = {};
    rigid.supports.kind = SupportKind::clamped;
    rigid.mesh.along_per_segment.clear();  // the clamps make other segments than the chucks
    for (const ChuckSpec& c : scene.supports.chucks) {
        // One clamp over all of the chuck's expanding elements.
        const ChuckPlacement place = chuck_placement(scene, c);
        ZRange zone = place.element_range(c.expanding.at(0));
        for (const ExpandingElement& e : c.expanding) {
            zone.lo = std::min(zone.lo, place.element_range(e).lo);
            zone.hi = std::max(zone.hi, place.element_range(e).hi);
        }
        rigid.supports.clamps.push_back(ClampSpec{c.name, zone.lo, zone.hi});
    }
    return rigid;
}

std::vector<ModeShift> pair_by_label(const std::vector<Mode>& elastic, const std::vector<Mode>& rigid) {
    // Type and n, then order: the k-th bending mode of one run with the k-th of
    // the other. The axial count m is not a key: it counts nodes over the
    // whole core, and a rigid clamp stills the overhang that a chuck moves.
    using Key = std::tuple<std::string, int>;
    const auto key = [](const Mode& m) { return Key{m.label.type, m.label.n}; };
    std::map<Key, std::vector<const Mode*>> rigid_by_label;
    for (const Mode& m : rigid) rigid_by_label[key(m)].push_back(&m);
    std::map<Key, size_t> used;
    std::vector<ModeShift> rows;
    for (const Mode& e : elastic) {
        ModeShift row{e.label.type, e.label.n, e.label.m, e.index, 0, e.frequency_hz, 0};
        auto& candidates = rigid_by_label[key(e)];
        if (size_t& k = used[key(e)]; k < candidates.size()) {
            row.rigid_index = candidates[k]->index;
            row.rigid_hz = candidates[k]->frequency_hz;
            ++k;
        }
        rows.push_back(row);
    }
    for (auto& [k, candidates] : rigid_by_label)
        for (size_t i = used[k]; i < candidates.size(); ++i) {
            const Mode& r = *candidates[i];
            rows.push_back({r.label.type, r.label.n, r.label.m, 0, r.index, 0, r.frequency_hz});
        }
    return rows;
}

}  // namespace coremodal
