#include "modes/tracking.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coremodal {

std::string label_text(const ModeLabel& label) {
    if (label.type == "rigid") return "rigid";
    return label.type + " n=" + std::to_string(label.n) + " m=" + std::to_string(label.m);
}

namespace {

bool same_label(const ModeLabel& a, const ModeLabel& b) {
    return a.type == b.type && a.n == b.n && a.m == b.m;
}

double relative_gap(double f_low, double f_high) {
    return (f_high - f_low) / std::max(std::abs(f_high), std::numeric_limits<double>::min());
}

// Whether mode `next` joins the group that ends with mode `last`.
bool joins_group(const ModeGroup& group, const ModeSummary& last, const ModeSummary& next) {
    if (last.label.type == "rigid" && next.label.type == "rigid") return true;
    if (last.label.type == "rigid" || next.label.type == "rigid") return false;
    const double gap = relative_gap(last.frequency_hz, next.frequency_hz);
    if (gap < kDegenerateGap) return true;
    // A split pair: two members at most, same family.
    return group.members.size() == 1 && gap < kSplitPairGap && next.label.n >= 1 && same_label(last.label, next.label);
}

}  // namespace

std::vector<ModeGroup> group_modes(const std::vector<ModeSummary>& modes) {
    std::vector<ModeGroup> groups;
    for (size_t i = 0; i < modes.size(); ++i) {
        const ModeSummary& m = modes[i];
        if (groups.empty() || !joins_group(groups.back(), modes[groups.back().members.back()], m))
            groups.push_back({{}, m.frequency_hz, m.label, {}});
        groups.back().members.push_back(static_cast<int>(i));
        if (!m.signature.empty()) groups.back().signatures.push_back(m.signature);
    }
    // A group with some members lacking a signature compares by label.
    for (ModeGroup& g : groups)
        if (g.signatures.size() != g.members.size()) g.signatures.clear();
    return groups;
}

double group_mac(const ModeGroup& a, const ModeGroup& b) {
    if (a.signatures.empty() || b.signatures.empty()) return same_label(a.label, b.label) ? 1.0 : 0.0;
    return subspace_mac(a.signatures, b.signatures);
}

std::vector<int> assign_maximum(const std::vector<std::vector<double>>& weight) {
    // Hungarian algorithm with potentials (shortest augmenting paths), on the
    // cost -weight of a matrix padded to n_rows <= n_cols by transposition.
    const int rows = static_cast<int>(weight.size());
    const int cols = rows ? static_cast<int>(weight.front().size()) : 0;
    if (rows == 0 || cols == 0) return std::vector<int>(rows, -1);
    const bool transposed = rows > cols;
    const int n = transposed ? cols : rows, m = transposed ? rows : cols;
    const auto cost = [&](int i, int j) { return transposed ? -weight[j - 1][i - 1] : -weight[i - 1][j - 1]; };
    constexpr double kInf = std::numeric_limits<double>::infinity();
    std::vector<double> u(n + 1, 0), v(m + 1, 0);
    std::vector<int> p(m + 1, 0), way(m + 1, 0);  // p[j]: row matched to column j (1-based), 0 none
    for (int i = 1; i <= n; ++i) {
        p[0] = i;
        int j0 = 0;
        std::vector<double> minv(m + 1, kInf);
        std::vector<char> used(m + 1, 0);
        do {
            used[j0] = 1;
            const int i0 = p[j0];
            double delta = kInf;
            int j1 = 0;
            for (int j = 1; j <= m; ++j) {
                if (used[j]) continue;
                const double cur = cost(i0, j) - u[i0] - v[j];
                if (cur < minv[j]) minv[j] = cur, way[j] = j0;
                if (minv[j] < delta) delta = minv[j], j1 = j;
            }
            for (int j = 0; j <= m; ++j) {
                if (used[j]) u[p[j]] += delta, v[j] -= delta;
                else minv[j] -= delta;
            }
            j0 = j1;
        } while (p[j0] != 0);
        do {
            const int j1 = way[j0];
            p[j0] = p[j1];
            j0 = j1;
        } while (j0 != 0);
    }
    std::vector<int> result(rows, -1);
    for (int j = 1; j <= m; ++j) {
        if (p[j] == 0) continue;
        if (transposed) result[j - 1] = p[j] - 1;
        else result[p[j] - 1] = j - 1;
    }
    return result;
}

std::vector<TrackStep> start_tracks(const std::vector<ModeGroup>& groups, int& next_track_id) {
    std::vector<TrackStep> steps(groups.size());
    for (TrackStep& s : steps) s.track = next_track_id++;
    return steps;
}

std::vector<TrackStep> follow_tracks(const std::vector<ModeGroup>& previous, const std::vector<int>& previous_tracks,
                                     const std::vector<ModeGroup>& current, int& next_track_id) {
    COREMODAL_ASSERT(previous.size() == previous_tracks.size());
    // weight[c][p]: MAC of current group c against previous group p.
    std::vector<std::vector<double>> weight(current.size(), std::vector<double>(previous.size(), 0.0));
    for (size_t c = 0; c < current.size(); ++c)
        for (size_t p = 0; p < previous.size(); ++p) weight[c][p] = group_mac(current[c], previous[p]);
    const std::vector<int> match = assign_maximum(weight);

    std::vector<TrackStep> steps(current.size());
    for (size_t c = 0; c < current.size(); ++c) {
        TrackStep& s = steps[c];
        const int p = match[c];
        if (p < 0 || weight[c][p] < kNewTrackMac) {
            s.track = next_track_id++;
            s.new_track = true;
            if (p >= 0) s.mac_previous = weight[c][p];
            continue;
        }
        const double best = weight[c][p];
        s.track = previous_tracks[p];
        s.mac_previous = best;
        // A rival: another previous group for this one, or another current group for that one.
        bool rival = false;
        for (size_t q = 0; q < previous.size(); ++q)
            if (static_cast<int>(q) != p && weight[c][q] > best - kCloseCandidateMac) rival = true;
        for (size_t d = 0; d < current.size(); ++d)
            if (d != c && weight[d][p] > best - kCloseCandidateMac) rival = true;
        s.ambiguous = best < kAmbiguousMac || rival;
    }
    return steps;
}

}  // namespace coremodal
