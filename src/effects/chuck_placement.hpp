// Where on the core a chuck acts: the one statement of it that every model
// level reads (the section's interface segments and so the solid's bore faces
// and the harmonic's interface edges, the solid's covered points, the beam's
// stations, the rigid-clamp variant of a chuck scene).
//
// Axial positions in a ChuckSpec are measured from that chuck's own core end,
// inwards; here they become z from the left core end (z = 0). The shaft runs
// outwards from the core end to the bearing.
#pragma once

#include "scene/scene.hpp"

#include <string>
#include <utility>
#include <vector>

namespace coremodal {

// An axial range [lo, hi] of z, m.
struct ZRange {
    double lo = 0, hi = 0;
    bool holds(double z, double tol) const { return z >= lo - tol && z <= hi + tol; }
    std::pair<double, double> pair() const { return {lo, hi}; }
};

// An arc of the bore [from, to], rad (from < to; not reduced to [0, 2 pi)).
struct Arc {
    double from = 0, to = 0;
};

struct ChuckPlacement {
    std::string chuck;  // "left" or "right"
    bool right = false;
    double core_length = 0;      // m
    double inserted_length = 0;  // m, body inside the core
    double shaft_length = 0;     // m, core end to the bearing
    std::vector<ExpandingElement> expanding;

    // z of a point `offset` from this chuck's core end, inwards.
    double z_at(double offset) const { return right ? core_length - offset : offset; }
    // z of the bearing (the shaft end): below 0 on the left, beyond the core on the right.
    double bearing_z() const { return right ? core_length + shaft_length : -shaft_length; }
    ZRange element_range(const ExpandingElement& e) const;
    ZRange body_range() const;
    // Is the bore point (z, theta) on an expanding element? Bands cover all
    // angles; N segments are centred at theta = 2 pi k / N. Edges count as on
    // (within 1e-9 m, 1e-9 rad).
    bool covers(double z, double theta) const;
};

ChuckPlacement chuck_placement(const Scene& scene, const ChuckSpec& chuck);

// The arcs an expanding element presses on: [0, 2 pi] for a band, else one
// arc of segment_angle centred at 2 pi k / N per segment.
std::vector<Arc> contact_arcs(const ExpandingElement& e);

}  // namespace coremodal
