#include "geometry/tube_model.hpp"

#include "common/error.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace coremodal {
namespace {

namespace geo = gmsh::model::geo;

// Tolerance for recognising a surface by its radius or z range (metres).
// Cores are millimetres thick; a micrometre separates every real boundary.
constexpr double kGeometryTolerance = 1e-6;

// A quarter of a ring of radius r at height z, from angle q * 90 degrees.
struct Ring {
    int center = 0;
    std::array<int, 4> points{};  // at 0, 90, 180, 270 degrees
    std::array<int, 4> arcs{};    // arcs[q] from points[q] to points[q + 1]
};

Ring make_ring(int center, double r, double z, int n_quarter) {
    Ring ring;
    ring.center = center;
    for (int q = 0; q < 4; ++q)
        ring.points[q] = geo::addPoint(r * std::cos(q * M_PI / 2), r * std::sin(q * M_PI / 2), z);
    for (int q = 0; q < 4; ++q) {
        ring.arcs[q] = geo::addCircleArc(ring.points[q], center, ring.points[(q + 1) % 4]);
        geo::mesh::setTransfiniteCurve(ring.arcs[q], n_quarter + 1);
    }
    return ring;
}

int structured_quad(const std::vector<int>& loop_curves) {
    const int surface = geo::addPlaneSurface({geo::addCurveLoop(loop_curves)});
    geo::mesh::setTransfiniteSurface(surface);
    geo::mesh::setRecombine(2, surface);
    return surface;
}

// The four quarter surfaces between two rings (same centre), with n_radial
// elements across. Radial lines run along the x and y axes.
std::vector<int> annulus(const Ring& in, const Ring& out, int n_radial) {
    std::array<int, 4> spokes{};
    for (int q = 0; q < 4; ++q) {
        spokes[q] = geo::addLine(in.points[q], out.points[q]);
        geo::mesh::setTransfiniteCurve(spokes[q], n_radial + 1);
    }
    std::vector<int> surfaces;
    for (int q = 0; q < 4; ++q)
        surfaces.push_back(structured_quad({spokes[q], out.arcs[q], -spokes[(q + 1) % 4], -in.arcs[q]}));
    return surfaces;
}

// A structured cross-section at height z: the core wall and rest paper as
// annuli, and optionally a solid chuck disc as an O-grid (a centre square with
// its corners on the axes, then rings at the shaft and body radii).
struct CrossSection {
    std::vector<std::pair<std::string, int>> tube;  // (part, surface)
    std::vector<int> disc_shaft, disc_outer;         // chuck disc: inside / outside the shaft radius
};

std::vector<int> tube_surfaces(const TubeSection& s, int center, double z) {
    const int n_quarter = s.n_around / 4;
    Ring inner = make_ring(center, s.layers.front().r_inner, z, n_quarter);
    std::vector<int> surfaces;
    for (const RadialLayer& layer : s.layers) {
        Ring outer = make_ring(center, layer.r_outer, z, n_quarter);
        for (int tag : annulus(inner, outer, layer.n_elements)) surfaces.push_back(tag);
        inner = outer;
    }
    return surfaces;
}

void chuck_disc(const ChuckBody& c, int n_around, int center, double z, CrossSection& out) {
    const int n_quarter = n_around / 4;
    const double a = kOGridCoreShare * c.shaft_radius;
    std::array<int, 4> corners{};
    for (int q = 0; q < 4; ++q) corners[q] = geo::addPoint(a * std::cos(q * M_PI / 2), a * std::sin(q * M_PI / 2), z);
    Ring square;  // straight edges in place of arcs
    square.points = corners;
    for (int q = 0; q < 4; ++q) {
        square.arcs[q] = geo::addLine(corners[q], corners[(q + 1) % 4]);
        geo::mesh::setTransfiniteCurve(square.arcs[q], n_quarter + 1);
    }
    out.disc_shaft.push_back(structured_quad({square.arcs[0], square.arcs[1], square.arcs[2], square.arcs[3]}));
    const auto n_across = [&](double r0, double r1) { return chuck_ring_elements(r0, r1, n_around); };
    const Ring shaft = make_ring(center, c.shaft_radius, z, n_quarter);
    for (int tag : annulus(square, shaft, n_across(a, c.shaft_radius))) out.disc_shaft.push_back(tag);
    if (c.body_radius > c.shaft_radius + kGeometryTolerance) {
        const Ring body = make_ring(center, c.body_radius, z, n_quarter);
        for (int tag : annulus(shaft, body, n_across(c.shaft_radius, c.body_radius))) out.disc_outer.push_back(tag);
    }
}

// Extrudes surfaces by dz into hexahedral layers; returns (top surface, volume) per input.
std::vector<std::pair<int, int>> extrude(const std::vector<int>& surfaces, double dz,
                                         const std::vector<double>& fractions) {
    gmsh::vectorpair in, out;
    for (int tag : surfaces) in.emplace_back(2, tag);
    geo::extrude(in, 0, 0, dz, out, std::vector<int>(fractions.size(), 1), fractions, true);
    // gmsh returns, per input surface: its top, its volume, then the lateral surfaces.
    std::vector<std::pair<int, int>> result;
    for (size_t k = 0; k + 1 < out.size(); ++k)
        if (out[k].first == 2 && out[k + 1].first == 3) result.push_back({out[k].second, out[k + 1].second});
    COREMODAL_ASSERT(result.size() == surfaces.size());
    return result;
}

// Volume tags per part name, filled as the extrusion goes.
using PartVolumes = std::map<std::string, std::vector<int>>;

struct ChuckState {
    const ChuckBody* body = nullptr;
    std::vector<int> shaft, outer;  // current top surfaces of the body's disc
    bool started = false, done = false;
};


// Extrudes `current` and replaces it by the top surfaces.
const std::vector<int>& extrude_into(std::vector<int>& current, const std::string& part, double dz,
                                     const std::vector<double>& fractions, PartVolumes& volumes) {
    std::vector<int> tops;
    for (auto [top, volume] : extrude(current, dz, fractions)) {
        tops.push_back(top);
        volumes[part].push_back(volume);
    }
    current = std::move(tops);
    return current;
}

// The whole model: the cross-section at z = 0 extruded segment by segment
// along the core; chuck discs join where a body starts and leave where it
// ends; shafts are extruded outwards from the body's end face at the core end.
PartVolumes build_volumes(const TubeSection& s) {
    PartVolumes volumes;
    const double z0 = s.segments.front().z_start;
    std::map<double, int> centers;  // one centre point per height (arcs need one)
    const auto center_at = [&](double z) {
        auto it = centers.find(z);
        return it != centers.end() ? it->second : centers[z] = geo::addPoint(0, 0, z);
    };
    // Tube surfaces, grouped per layer (4 quarters each).
    std::vector<int> tube = tube_surfaces(s, center_at(z0), z0);
    std::vector<std::string> tube_part;
    for (const RadialLayer& layer : s.layers) tube_part.insert(tube_part.end(), 4, layer.part);

    std::vector<ChuckState> chucks;
    for (const ChuckBody& c : s.chucks) {
        ChuckState state;
        state.body = &c;
        chucks.push_back(state);
    }
    const double tol = kGeometryTolerance;
    for (const AxialSegment& seg : s.segments) {
        const std::vector<double> fractions = segment_layer_fractions(seg);
        const double dz = seg.z_end - seg.z_start;
        for (ChuckState& c : chucks) {
            if (c.started || std::abs(c.body->z_body_start - seg.z_start) > tol) continue;
            CrossSection disc;
            chuck_disc(*c.body, s.n_around, center_at(seg.z_start), seg.z_start, disc);
            c.shaft = disc.disc_shaft;
            c.outer = disc.disc_outer;
            c.started = true;
            if (c.body->shaft_below) {  // the shaft hangs from the body's start face
                std::vector<int> start_face = c.shaft;
                extrude_into(start_face, "chuck_" + c.body->name, -c.body->shaft_length,
                             segment_layer_fractions({0, c.body->shaft_length, c.body->n_shaft}), volumes);
            }
        }
        // Tube layers: extruded one part at a time so volumes know their part.
        std::vector<int> next;
        for (size_t k = 0; k < tube.size(); k += 4) {
            std::vector<int> quarter(tube.begin() + k, tube.begin() + k + 4);
            for (int t : extrude_into(quarter, tube_part[k], dz, fractions, volumes)) next.push_back(t);
        }
        tube = next;
        for (ChuckState& c : chucks) {
            if (!c.started || c.done) continue;
            const std::string part = "chuck_" + c.body->name;
            extrude_into(c.shaft, part, dz, fractions, volumes);
            if (!c.outer.empty()) extrude_into(c.outer, part, dz, fractions, volumes);
            if (std::abs(c.body->z_body_end - seg.z_end) <= tol) {
                c.done = true;
                if (!c.body->shaft_below)
                    extrude_into(c.shaft, part, c.body->shaft_length,
                                 segment_layer_fractions({0, c.body->shaft_length, c.body->n_shaft}), volumes);
            }
        }
    }
    geo::synchronize();
    return volumes;
}

// Radius of a surface if it is a cylinder about z (radius equal at several
// parametric points), else a negative number.
double cylinder_radius(int surface) {
    std::vector<double> lo, hi;
    gmsh::model::getParametrizationBounds(2, surface, lo, hi);
    std::vector<double> uv;
    for (double a : {0.1, 0.5, 0.9})
        for (double b : {0.2, 0.7}) {
            uv.push_back(lo[0] + a * (hi[0] - lo[0]));
            uv.push_back(lo[1] + b * (hi[1] - lo[1]));
        }
    std::vector<double> xyz;
    gmsh::model::getValue(2, surface, uv, xyz);
    double r0 = std::hypot(xyz[0], xyz[1]);
    for (size_t k = 0; k < xyz.size(); k += 3)
        if (std::abs(std::hypot(xyz[k], xyz[k + 1]) - r0) > kGeometryTolerance) return -1;
    return r0;
}

void add_named_group(int dim, const std::vector<int>& tags, const std::string& name) {
    if (tags.empty()) return;
    int group = gmsh::model::addPhysicalGroup(dim, tags);
    gmsh::model::setPhysicalName(dim, group, name);
}

struct Box {
    double x0, y0, z0, x1, y1, z1;
};

Box bounding_box(int dim, int tag) {
    Box b{};
    gmsh::model::getBoundingBox(dim, tag, b.x0, b.y0, b.z0, b.x1, b.y1, b.z1);
    return b;
}

bool within(const Box& b, double z_start, double z_end) {
    return b.z0 >= z_start - kGeometryTolerance && b.z1 <= z_end + kGeometryTolerance;
}

// The chuck whose volume a surface bounds, or null (a core or rest paper
// surface). By volume, not by radius: with zero clearance the chuck body's
// surface lies on the core bore (two surfaces, two sets of nodes).
const ChuckBody* chuck_of_surface(int tag, const std::map<int, const ChuckBody*>& chuck_volume) {
    std::vector<int> up, down;
    gmsh::model::getAdjacencies(2, tag, up, down);
    for (int volume : up)
        if (const auto it = chuck_volume.find(volume); it != chuck_volume.end()) return it->second;
    return nullptr;
}

std::map<int, const ChuckBody*> chuck_volumes(const TubeSection& s, const PartVolumes& volumes) {
    std::map<int, const ChuckBody*> out;
    for (const ChuckBody& c : s.chucks)
        if (const auto it = volumes.find("chuck_" + c.name); it != volumes.end())
            for (int v : it->second) out[v] = &c;
    return out;
}

// Named surfaces: the cylinders of the core and rest paper, clamp zones on
// the core bore, and for chucks the facing surfaces over each expanding
// element ("interface_<chuck>_core" on the bore, "interface_<chuck>_chuck" on
// the body) and the shaft end face at the bearing ("bearing_<chuck>").
void add_surface_groups(const TubeSection& s, const std::vector<ClampSpec>& clamps, const PartVolumes& volumes) {
    const double ri = s.layers.front().r_inner, ro = s.layers.front().r_outer;
    const double e = kGeometryTolerance;
    const std::map<int, const ChuckBody*> chuck_volume = chuck_volumes(s, volumes);
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    std::map<std::string, std::vector<int>> groups;
    for (auto [dim, tag] : surfaces) {
        const Box b = bounding_box(dim, tag);
        if (std::abs(b.z1 - b.z0) < e) {  // a plane face: maybe a bearing face
            for (const ChuckBody& c : s.chucks)
                if (std::abs(b.z0 - c.z_bearing()) < e) groups["bearing_" + c.name].push_back(tag);
            continue;
        }
        const double r = cylinder_radius(tag);
        if (r < 0) continue;
        if (const ChuckBody* c = chuck_of_surface(tag, chuck_volume)) {
            if (std::abs(r - c->body_radius) < e && within(b, c->z_body_start, c->z_body_end))
                for (const auto& [chuck, zone] : s.interfaces)
                    if (chuck == c->name && within(b, zone.first, zone.second))
                        groups["interface_" + chuck + "_chuck"].push_back(tag);
        } else if (std::abs(r - ri) < e) {
            groups["core_inner"].push_back(tag);
            for (const auto& c : clamps)
                if (within(b, c.z_start, c.z_end)) groups["clamp_" + c.name].push_back(tag);
            for (const auto& [chuck, zone] : s.interfaces)
                if (within(b, zone.first, zone.second)) groups["interface_" + chuck + "_core"].push_back(tag);
        } else if (std::abs(r - ro) < e) {
            groups["core_outer"].push_back(tag);
        } else if (s.layers.size() > 1 && std::abs(r - s.layers.back().r_outer) < e) {
            groups["rest_paper_outer"].push_back(tag);
        }
    }
    for (const auto& [name, tags] : groups) add_named_group(2, tags, name);
}

// The smallest radial distance between a chuck body and the bore in the
// gmsh model. gmsh's geometry kernel merges entities that coincide (it must:
// the layers of the core, rest paper and chuck discs are extruded one part at
// a time and meet on merged surfaces), so a body filling the bore (zero
// clearance) would share its surface, and its nodes, with the core over the
// whole inserted length: bonded everywhere instead of over the expanding
// elements. Ten geometry tolerances keep the two surfaces apart; the body's
// volume changes by 2 x 1e-5 / radius (5e-4 of it in a 76 mm bore), the ties
// and spring layers join facing nodes whatever their distance, and the
// harmonic and beam levels model zero clearance exactly.
constexpr double kMinBodyClearance = 10 * kGeometryTolerance;  // m

TubeSection with_chucks_apart_from_bore(TubeSection s) {
    const double limit = s.layers.front().r_inner - kMinBodyClearance;
    for (ChuckBody& c : s.chucks) {
        c.body_radius = std::min(c.body_radius, limit);
        c.shaft_radius = std::min(c.shaft_radius, c.body_radius);
    }
    return s;
}

// gmsh puts the higher-order node of an edge (and of a face, and the centre
// of a hex27) that lies inside a plane surface or a volume half-way between
// its corners in Cartesian space: on the chord of an arc. On the core and
// rest paper every circumferential edge is an arc, and the chord's midpoint
// lies the sagitta r (1 - cos(pi / n_around)) inside it: 0.73 mm on a 76 mm
// bore with 16 elements around, more than a 1 mm wall split in two. Such a
// cell folds over (negative Jacobian) and a thicker one is kinked and far too
// stiff in ring bending (issue 33: a 0.5 m ring at 130 Hz for 51 Hz). The
// tube's cells are boxes in (r, theta, z) (structured annuli extruded along
// z: every corner lies exactly on its ring), so each higher-order node is
// placed where the trilinear map of its cell's corners in (r, theta, z) puts
// it: edge nodes at the mean radius and angle, on the arc. The cell is then
// r(xi) times the quadratic arc through three points of the unit circle: its
// Jacobian is positive whatever the wall's thickness.
void place_tube_nodes_on_cylinders(const TubeSection& s, const PartVolumes& volumes) {
    std::vector<std::size_t> tags;
    std::vector<double> xyz, params;
    gmsh::model::mesh::getNodes(tags, xyz, params, -1, -1, true, false);
    const std::size_t max_tag = tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
    std::vector<std::array<double, 3>> cylindrical(max_tag + 1);  // node tag -> (r, theta, z)
    for (size_t k = 0; k < tags.size(); ++k)
        cylindrical[tags[k]] = {std::hypot(xyz[3 * k], xyz[3 * k + 1]), std::atan2(xyz[3 * k + 1], xyz[3 * k]),
                                xyz[3 * k + 2]};
    std::map<std::size_t, std::array<double, 3>> placed;  // higher-order node tag -> (x, y, z)
    for (const RadialLayer& layer : s.layers) {
        const auto it = volumes.find(layer.part);
        if (it == volumes.end()) continue;
        for (int volume : it->second) {
            std::vector<int> types;
            std::vector<std::vector<std::size_t>> element_tags, node_tags;
            gmsh::model::mesh::getElements(types, element_tags, node_tags, 3, volume);
            for (size_t t = 0; t < types.size(); ++t) {
                std::string name;
                int dim, order, n_nodes, n_corners;
                std::vector<double> local;  // reference hexahedron [-1, 1]^3, gmsh's node order
                gmsh::model::mesh::getElementProperties(types[t], name, dim, order, n_nodes, local, n_corners);
                COREMODAL_ASSERT(n_corners == 8);
                for (size_t c = 0; c < element_tags[t].size(); ++c) {
                    const std::size_t* cell = &node_tags[t][c * n_nodes];
                    std::array<std::array<double, 3>, 8> corner{};
                    for (int a = 0; a < 8; ++a) {
                        corner[a] = cylindrical[cell[a]];
                        // Angles measured from corner 0's, so a cell across theta = pi stays whole.
                        corner[a][1] = corner[0][1] + std::remainder(corner[a][1] - corner[0][1], 2 * M_PI);
                    }
                    for (int a = 8; a < n_nodes; ++a) {
                        const double* xi = &local[3 * a];
                        std::array<double, 3> p{};  // (r, theta, z) by the trilinear map
                        for (int b = 0; b < 8; ++b) {
                            const double* xb = &local[3 * b];
                            const double w = (1 + xi[0] * xb[0]) * (1 + xi[1] * xb[1]) * (1 + xi[2] * xb[2]) / 8;
                            for (int k = 0; k < 3; ++k) p[k] += w * corner[b][k];
                        }
                        placed[cell[a]] = {p[0] * std::cos(p[1]), p[0] * std::sin(p[1]), p[2]};
                    }
                }
            }
        }
    }
    for (const auto& [tag, x] : placed) gmsh::model::mesh::setNode(tag, {x[0], x[1], x[2]}, {});
}

}  // namespace

void build_tube_model(const TubeSection& section, const std::vector<ClampSpec>& clamps,
                      const std::string& element) {
    gmsh::model::add("coremodal");
    const TubeSection s = with_chucks_apart_from_bore(section);
    const PartVolumes volumes = build_volumes(s);
    // Parts in a fixed order: core, rest paper, then the chucks.
    for (const std::string part : {"core", "rest_paper", "chuck_left", "chuck_right"})
        if (volumes.count(part)) add_named_group(3, volumes.at(part), part);
    add_surface_groups(s, clamps, volumes);
    gmsh::option::setNumber("Mesh.ElementOrder", 2);
    // Incomplete second order = 20-node serendipity hexahedra; complete = 27-node.
    gmsh::option::setNumber("Mesh.SecondOrderIncomplete", element == "hex27" ? 0 : 1);
    gmsh::model::mesh::generate(3);
    place_tube_nodes_on_cylinders(s, volumes);
}

}  // namespace coremodal
