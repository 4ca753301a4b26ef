#include "assembly/chuck_supports.hpp"

#include "common/error.hpp"
#include "effects/support_effects.hpp"
#include "effects/web.hpp"
#include "element/face.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

namespace coremodal {
namespace {

// Gauss points per direction on a spring layer: N_a N_b of quadratic faces
// on a curved face needs a little more than 3.
constexpr int kSpringLayerGauss = 4;
constexpr int kBearingGauss = 3;  // exact for the quadratic face's N_a N_b

using FaceCoords = Eigen::Matrix<double, Eigen::Dynamic, 3>;

FaceCoords face_coords(const Mesh& mesh, const FaceSet& set, int f) {
    FaceCoords x(set.nodes_per_face, 3);
    for (int a = 0; a < set.nodes_per_face; ++a)
        for (int d = 0; d < 3; ++d) x(a, d) = mesh.nodes[set.face(f)[a]][d];
    return x;
}

const FaceSet& faces_of(const Mesh& mesh, const std::string& group) {
    const auto it = mesh.face_groups.find(group);
    if (it == mesh.face_groups.end())
        throw SolveError("the mesh has no quadrilateral faces in group '" + group +
                         "' (elastic chucks need the generated mesh)");
    return it->second;
}

// Finds, for a core bore node, the chuck node facing it: same direction from
// the axis, same z. Generated meshes put them there exactly.
class FacingNodes {
public:
    FacingNodes(const Mesh& mesh, const std::vector<int>& chuck_nodes) : mesh_(mesh) {
        for (int n : chuck_nodes) index_[key(mesh.nodes[n])] = n;
    }
    int operator()(int core_node) const {
        const auto k = key(mesh_.nodes[core_node]);
        for (long dx : {0L, -1L, 1L})
            for (long dy : {0L, -1L, 1L})
                for (long dz : {0L, -1L, 1L})
                    if (auto it = index_.find({k[0] + dx, k[1] + dy, k[2] + dz}); it != index_.end()) return it->second;
        throw SolveError("no chuck node faces core node " + std::to_string(core_node) +
                         ": the chuck and core meshes do not match around or along");
    }

private:
    // Direction to 1e-6 rad, z to 0.1 micrometre: far finer than any element.
    static std::array<long, 3> key(const std::array<double, 3>& x) {
        const double r = std::hypot(x[0], x[1]);
        return {std::lround(x[0] / r * 1e6), std::lround(x[1] / r * 1e6), std::lround(x[2] * 1e7)};
    }
    const Mesh& mesh_;
    std::map<std::array<long, 3>, int> index_;
};

// Quadrature points on the part of a bore face that an expanding element
// covers. Segment edges need not fall on element edges: the face is cut at
// them (found by bisection on the angle along the face's circumferential
// direction) and each piece integrated, so the covered area is exact.
std::vector<FacePoint> covered_points(const ChuckPlacement& chuck, const FaceCoords& x) {
    const auto theta_at = [&](double xi, double eta) {
        const Eigen::Vector3d p = face_point(x, xi, eta);
        return std::atan2(p[1], p[0]);
    };
    // Which reference direction runs around the axis?
    const bool around_is_xi = std::abs(std::remainder(theta_at(1, 0) - theta_at(-1, 0), 2 * M_PI)) >
                              std::abs(std::remainder(theta_at(0, 1) - theta_at(0, -1), 2 * M_PI));
    const auto theta_along = [&](double s) { return around_is_xi ? theta_at(s, 0) : theta_at(0, s); };
    // Cuts: the reference coordinates where a segment edge crosses the face.
    std::vector<double> cuts = {-1, 1};
    const double t0 = theta_along(-1);
    const double span = std::remainder(theta_along(1) - t0, 2 * M_PI);
    for (const ExpandingElement& e : chuck.expanding) {
        if (e.segments == 0) continue;  // a band has no edge around
        for (const Arc& arc : contact_arcs(e))
            for (double angle : {arc.from, arc.to}) {
                const double d = std::remainder(angle - t0, 2 * M_PI);
                if (d * span <= 0 || std::abs(d) >= std::abs(span)) continue;
                double lo = -1, hi = 1;  // theta runs monotonically along the face
                for (int it = 0; it < 60; ++it) {
                    const double mid = (lo + hi) / 2;
                    (std::remainder(theta_along(mid) - t0, 2 * M_PI) / span < d / span ? lo : hi) = mid;
                }
                cuts.push_back((lo + hi) / 2);
            }
    }
    std::sort(cuts.begin(), cuts.end());
    std::vector<FacePoint> points;
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double a = cuts[i], b = cuts[i + 1];
        const Eigen::Vector3d mid = around_is_xi ? face_point(x, (a + b) / 2, 0) : face_point(x, 0, (a + b) / 2);
        if (b - a < 1e-12 || !chuck.covers(mid[2], std::atan2(mid[1], mid[0]))) continue;
        const auto piece = around_is_xi ? face_quadrature(x, kSpringLayerGauss, a, b, -1, 1)
                                        : face_quadrature(x, kSpringLayerGauss, -1, 1, a, b);
        points.insert(points.end(), piece.begin(), piece.end());
    }
    return points;
}

// The spring layer (effects/support_effects.hpp) over one bore face: the
// relative displacement (core - chuck) at each covered point against D per
// unit bore area.
CouplingElement spring_layer_face(const Mesh& mesh, const ChuckEffects& chuck, const FaceSet& set, int f,
                                  const FacingNodes& facing, double& covered_area) {
    const int n = set.nodes_per_face;
    CouplingElement e;
    for (int a = 0; a < n; ++a) e.nodes.push_back(set.face(f)[a]);
    for (int a = 0; a < n; ++a) e.nodes.push_back(facing(set.face(f)[a]));
    Eigen::MatrixXd Kab = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    for (const FacePoint& p : covered_points(chuck.placement, face_coords(mesh, set, f))) {
        covered_area += p.area_weight;
        const Eigen::Matrix3d D = chuck.spring_layer->per_area(std::atan2(p.x[1], p.x[0]));
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) Kab.block<3, 3>(3 * a, 3 * b) += p.area_weight * p.N[a] * p.N[b] * D;
    }
    e.terms.push_back({SpringLayer::kTerm, spring_between(Kab)});
    return e;
}

// A one-sided contact (a chuck not expanded): every bore face over the body
// is a candidate; whether a point closes is the static solve's to find.
void add_contact_faces(const Mesh& mesh, int chuck_index, const FaceSet& bore, const FacingNodes& facing,
                       ChuckSupports& out) {
    for (int f = 0; f < bore.n_faces(); ++f) {
        ContactFace face;
        face.chuck = chuck_index;
        for (int a = 0; a < bore.nodes_per_face; ++a) {
            face.core_nodes.push_back(bore.face(f)[a]);
            face.chuck_nodes.push_back(facing(bore.face(f)[a]));
        }
        for (const FacePoint& p : face_quadrature(face_coords(mesh, bore, f), kSpringLayerGauss))
            face.points.push_back({p.N, p.x, p.area_weight});
        out.couplings.push_back(contact_coupling(face, [](size_t) { return Eigen::Matrix3d::Zero(); }));
        out.contact_faces.push_back(std::move(face));
    }
}

void hold_core_by_chuck(const Mesh& mesh, int chuck_index, const ChuckEffects& chuck, ChuckSupports& out) {
    const std::string& name = chuck.placement.chuck;
    const std::string core_group = "interface_" + name + "_core";
    const FaceSet& bore = faces_of(mesh, core_group);
    const FacingNodes facing(mesh, mesh.node_groups.at("interface_" + name + "_chuck"));
    if (chuck.one_sided) {
        add_contact_faces(mesh, chuck_index, bore, facing, out);
        return;
    }
    if (chuck.spring_layer) {
        for (int f = 0; f < bore.n_faces(); ++f)
            out.couplings.push_back(spring_layer_face(mesh, chuck, bore, f, facing, out.coupled_area_m2));
        return;
    }
    // Bonded: every bore node on an expanding element shares its chuck node's DOFs.
    for (int node : mesh.node_groups.at(core_group)) {
        const auto& x = mesh.nodes[node];
        if (chuck.placement.covers(x[2], std::atan2(x[1], x[0]))) out.ties.push_back({node, facing(node)});
    }
    for (int f = 0; f < bore.n_faces(); ++f)
        for (const FacePoint& p : covered_points(chuck.placement, face_coords(mesh, bore, f)))
            out.coupled_area_m2 += p.area_weight;
}

// The stand (effects/support_effects.hpp): a rigid bearing eliminates the
// shaft end face; bearing springs spread over it, to the ground or to the
// frame node when there is a frame mass.
void hold_chuck_by_bearing(const Mesh& mesh, const ChuckEffects& chuck, ChuckSupports& out) {
    const std::string group = "bearing_" + chuck.placement.chuck;
    if (!chuck.bearing_springs) {
        const auto& nodes = mesh.node_groups.at(group);
        out.eliminated.insert(out.eliminated.end(), nodes.begin(), nodes.end());
        return;
    }
    const FaceSet& face = faces_of(mesh, group);
    double area = 0, second_moment = 0;
    for (int f = 0; f < face.n_faces(); ++f)
        for (const FacePoint& p : face_quadrature(face_coords(mesh, face, f), kBearingGauss)) {
            area += p.area_weight;
            second_moment += p.area_weight * p.x[0] * p.x[0];
        }
    const Eigen::Vector3d c = chuck.bearing_springs->per_face_area(area, second_moment);
    const int frame_node = chuck.frame ? mesh.node_groups.at("frame_" + chuck.placement.chuck).at(0) : -1;
    if (chuck.frame)
        out.grounded.push_back(frame_node);
    else
        out.grounded.insert(out.grounded.end(), face.faces.begin(), face.faces.end());
    for (int f = 0; f < face.n_faces(); ++f) {
        const int n = face.nodes_per_face, m = n + (chuck.frame ? 1 : 0);
        CouplingElement e;
        e.nodes.assign(face.face(f), face.face(f) + n);
        if (chuck.frame) e.nodes.push_back(frame_node);
        Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * m, 3 * m);
        for (const FacePoint& p : face_quadrature(face_coords(mesh, face, f), kBearingGauss)) {
            Eigen::VectorXd N(m);  // relative displacement: face minus frame
            N.head(n) = p.N;
            if (chuck.frame) N[n] = -1;
            for (int a = 0; a < m; ++a)
                for (int b = 0; b < m; ++b)
                    K.block<3, 3>(3 * a, 3 * b) += p.area_weight * N[a] * N[b] * c.asDiagonal().toDenseMatrix();
        }
        e.terms.push_back({BearingSprings::kTerm, std::move(K)});
        out.couplings.push_back(std::move(e));
    }
    if (chuck.frame) {  // the frame: a lumped mass on a spring to the ground, in all three directions
        CouplingElement frame;
        frame.nodes = {frame_node};
        frame.terms = {{Term::stiffness, chuck.frame->stiffness * Eigen::MatrixXd::Identity(3, 3)},
                       {Term::mass, chuck.frame->mass * Eigen::MatrixXd::Identity(3, 3)}};
        out.couplings.push_back(std::move(frame));
    }
}

// ---- the paper web's line (effects/web.hpp) --------------------------------

// Angle a - b folded into (-pi, pi].
double angle_between(double a, double b) { return std::remainder(a - b, 2 * M_PI); }

double polar_angle(const Eigen::Vector3d& x) { return std::atan2(x[1], x[0]); }

// The around-the-axis coordinate of the face point at `along` (the other
// coordinate) where the surface's polar angle is theta: bisection, the
// angle being monotone across one face.
double around_coordinate(const FaceCoords& x, bool around_is_xi, double along, double theta) {
    const auto at = [&](double s) {
        return angle_between(polar_angle(around_is_xi ? face_point(x, s, along) : face_point(x, along, s)), theta);
    };
    double lo = -1, hi = 1;
    const bool rising = at(hi) > at(lo);
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        ((at(mid) > 0) == rising ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
}

// The web's springs per unit length on the line theta = const of one face of
// the roll's outer surface, or nothing when the line misses the face. A line
// on the edge of two faces belongs to the one on its counter-clockwise side.
std::optional<CouplingElement> web_line_face(const Mesh& mesh, const FaceSet& set, int f, double theta,
                                             const Eigen::Matrix3d& k_line) {
    const FaceCoords x = face_coords(mesh, set, f);
    double lowest = M_PI, highest = -M_PI;
    for (int a = 0; a < 4; ++a) {
        const double d = angle_between(polar_angle(x.row(a).transpose()), theta);
        lowest = std::min(lowest, d), highest = std::max(highest, d);
    }
    // (A face opposite the line has corners near +-pi: its span is not small.)
    if (!(lowest <= 0 && highest > 0 && highest - lowest < M_PI)) return std::nullopt;
    const bool around_is_xi = std::abs(angle_between(polar_angle(x.row(1).transpose()), polar_angle(x.row(0).transpose()))) >
                              std::abs(angle_between(polar_angle(x.row(3).transpose()), polar_angle(x.row(0).transpose())));
    const int n = set.nodes_per_face;
    CouplingElement e;
    e.nodes.assign(set.face(f), set.face(f) + n);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    // 3-point Gauss along the line integrates its quartic energy exactly.
    const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    for (int q = 0; q < 3; ++q) {
        const double s = around_coordinate(x, around_is_xi, g[q], theta);
        const double xi = around_is_xi ? s : g[q], eta = around_is_xi ? g[q] : s;
        Eigen::VectorXd N, dN_dxi, dN_deta;
        face_shape(n, xi, eta, N, dN_dxi, dN_deta);
        const Eigen::Vector3d tangent = x.transpose() * (around_is_xi ? dN_deta : dN_dxi);
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) K.block<3, 3>(3 * a, 3 * b) += w[q] * tangent.norm() * N[a] * N[b] * k_line;
    }
    e.terms.push_back({Term::stiffness, std::move(K)});
    return e;
}

// The web's span on the line of the roll's outer surface it leaves from
// (effects/web.hpp): springs to the ground over every face it crosses.
void hold_roll_by_web(const Scene& scene, const Mesh& mesh, ChuckSupports& out) {
    const std::string group = scene.rest_paper ? "rest_paper_outer" : "core_outer";
    const auto it = mesh.face_groups.find(group);
    if (it == mesh.face_groups.end())
        throw InputError(scene.source_file + ": [web] at the solid level needs the generated mesh (its faces '" + group +
                         "'); expected no [mesh] file, or model = \"beam\"");
    const double theta = polar_angle(web_tangent_normal(*scene.web));
    const Eigen::Matrix3d k_line = web_line_stiffness(*scene.web);
    for (int f = 0; f < it->second.n_faces(); ++f)
        if (std::optional<CouplingElement> e = web_line_face(mesh, it->second, f, theta, k_line)) {
            out.grounded.insert(out.grounded.end(), e->nodes.begin(), e->nodes.end());
            out.couplings.push_back(std::move(*e));
        }
}

}  // namespace

void add_frame_nodes(const Scene& scene, Mesh& mesh) {
    for (const ChuckEffects& chuck : support_effects(scene).chucks) {
        if (!chuck.frame) continue;
        mesh.node_groups["frame_" + chuck.placement.chuck] = {mesh.n_nodes()};
        mesh.nodes.push_back({0.0, 0.0, chuck.frame->z});
    }
}

ChuckSupports chuck_supports(const Scene& scene, const Mesh& mesh) {
    ChuckSupports out;
    const std::vector<ChuckEffects> chucks = support_effects(scene).chucks;
    for (size_t i = 0; i < chucks.size(); ++i) {
        const ChuckEffects& chuck = chucks[i];
        hold_core_by_chuck(mesh, static_cast<int>(i), chuck, out);
        hold_chuck_by_bearing(mesh, chuck, out);
    }
    if (scene.web) hold_roll_by_web(scene, mesh, out);
    return out;
}

}  // namespace coremodal
