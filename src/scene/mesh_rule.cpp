#include "scene/mesh_rule.hpp"

#include "common/format.hpp"
#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace coremodal {
namespace {

// The around law's fit and its safety factor (mesh_rule.hpp; the table in
// docs/validation/accuracy-by-level.md, "The mesh from the band").
constexpr double kAroundFit = 26.92, kAroundSlendernessPower = 1.585, kAroundWavePower = 1.285, kAroundOrder = 3.738,
                 kAroundSafety = 1.55;
// The along law's envelope: the free 76 x 15 mm tube's first bending pair
// (1.5 half-waves) has the largest constant of every mode measured.
constexpr double kAlongFit = 0.57, kAlongOrder = 3.7;

// One layer of the wall: the core, or the rest paper on it.
struct Layer {
    double inner_radius, outer_radius;
    const OrthotropicMaterial* material;
    double thickness() const { return outer_radius - inner_radius; }
};

std::vector<Layer> layers(const Scene& s) {
    std::vector<Layer> out = {{s.core.inner_diameter / 2, s.core.outer_diameter / 2, &s.core.material}};
    if (s.rest_paper)
        out.push_back({s.core.outer_diameter / 2, s.rest_paper->outer_diameter / 2, &s.rest_paper->material});
    return out;
}

// The lowest n-lobed mode of the wall (n >= 2). A free tube: in-plane ring
// bending, thin-ring theory (Blevins, Formulas for Natural Frequency and
// Mode Shape, 1979, table 9-1 case 1; Soedel, Vibrations of Shells and
// Plates, 3rd ed. 2004, eq. 2.7.13): f_n = n (n^2 - 1) / sqrt(n^2 + 1)
// sqrt(D / (m R^4)) / (2 pi). Ends held (clamps, chucks): the mode has at
// least one axial half-wave, lambda = pi R / L, and the membrane stretching
// it costs lifts the low n (a thin clamped shell's lowest modes lie at n = 4
// to 6): Donnell's simply supported shell (Leissa, Vibration of Shells,
// NASA SP-288, 1973, eq. 2.27 without the 1 - nu^2 terms, which lowers it),
// its bending term written as the ring's so that lambda = 0 gives the ring:
//   omega^2 m = A_z lambda^4 / (R^2 q^2) + D (q - 1)^2 n^2 / ((n^2 + 1) R^4),  q = n^2 + lambda^2,
// R the wall's mean radius, D = sum E_theta t^3 / 12, A_z = sum E_z t and
// m = sum rho t over the layers. D without the layers' composite action is
// a lower bound, as is simple support for clamped or chucked ends: f_n is
// low, so the n it lets into the band are as many as can occur, or more
// (an estimate: the run's check against the harmonic level is the backstop).
double ring_hz(const Scene& s, int n) {
    double bending = 0, membrane = 0, mass = 0;
    for (const Layer& l : layers(s)) {
        bending += l.material->E_theta * std::pow(l.thickness(), 3) / 12;
        membrane += l.material->E_z * l.thickness();
        mass += l.material->density * l.thickness();
    }
    const auto all = layers(s);
    const double radius = (all.front().inner_radius + all.back().outer_radius) / 2;
    const double lambda = s.supports.kind == SupportKind::free ? 0 : std::numbers::pi * radius / s.core.length;
    const double q = n * n + lambda * lambda;
    const double stiffness = membrane * std::pow(lambda, 4) / (radius * radius * q * q) +
                             bending * (q - 1) * (q - 1) * n * n / ((n * n + 1.0) * std::pow(radius, 4));
    return std::sqrt(stiffness / mass) / (2 * std::numbers::pi);
}

// Euler-Bernoulli bending of the whole roll over the core's length (Blevins
// 1979, table 8-1: free-free and clamped-clamped lambda_j = (j + 1/2) pi to
// within 0.5 %): f_j = lambda_j^2 / (2 pi L^2) sqrt(EI / rho A). Without shear
// it is high, so fewer bending modes are counted below a frequency.
double lambda(int j) { return (j + 0.5) * std::numbers::pi; }
double bending_hz(const Scene& s, int j) {
    double ei = 0, rho_a = 0;
    for (const Layer& l : layers(s)) {
        const double ro = l.outer_radius, ri = l.inner_radius;
        ei += l.material->E_z * std::numbers::pi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4;
        rho_a += l.material->density * std::numbers::pi * (ro * ro - ri * ri);
    }
    const double length = s.core.length;
    return lambda(j) * lambda(j) / (2 * std::numbers::pi * length * length) * std::sqrt(ei / rho_a);
}

// Torsion and axial waves along a free-free or held tube: j half-waves,
// f_j = j c / (2 L), c = sqrt(G_thetaz / rho) or sqrt(E_z / rho) of the
// core (Blevins 1979, table 8-16 and 8-19); the rest paper, a mass on it.
double rod_hz(const Scene& s, int j, double modulus) {
    double stiffness = 0, mass = 0;
    for (const Layer& l : layers(s)) {
        const double area = std::numbers::pi * (l.outer_radius * l.outer_radius - l.inner_radius * l.inner_radius);
        if (l.material == &s.core.material) stiffness += modulus * area;
        mass += l.material->density * area;
    }
    return j * std::sqrt(stiffness / mass) / (2 * s.core.length);
}

// The frequency of the last wanted mode of a count: the bending pairs, the
// ring or shell pairs (their lowest m), torsion and axial in order, after six
// rigid modes of a free body. Shell modes of higher m are not counted: the
// count is short, the estimate high, and the n it lets in more, not fewer.
double count_top_hz(const Scene& s, int n_modes) {
    const int elastic = n_modes - (s.supports.kind == SupportKind::free ? 6 : 0);
    if (elastic <= 0) return 0;
    std::vector<double> f;
    for (int k = 1; k <= elastic; ++k) {
        f.insert(f.end(), 2, bending_hz(s, k));
        f.insert(f.end(), 2, ring_hz(s, k + 1));
        f.push_back(rod_hz(s, k, s.core.material.G_thetaz));
        f.push_back(rod_hz(s, k, s.core.material.E_z));
    }
    std::sort(f.begin(), f.end());
    return f[elastic - 1];
}

int multiple_of_4(double n) { return 4 * static_cast<int>(std::ceil(n / 4)); }

double slenderest(const Scene& s) {
    double out = 0;
    for (const Layer& l : layers(s)) out = std::max(out, (l.inner_radius + l.outer_radius) / 2 / l.thickness());
    return out;
}

}  // namespace

double level_target_error(const MeshLevel& level) {
    if (level.name == "coarse") return 0.03;
    if (level.name == "fine") return 0.003;
    if (level.name == "very_fine") return 0.001;
    return 0.01;
}

BandWaves band_waves(const Scene& scene) {
    BandWaves out;
    if (scene.analysis.f_max_hz) {
        out.top_hz = *scene.analysis.f_max_hz;
    } else {
        out.top_estimated = true;
        out.top_hz = count_top_hz(scene, scene.analysis.n_modes);
    }
    // The factor keeps a mode exactly at the top (a count's last) in the band.
    const double top = out.top_hz * (1 + 1e-9);
    // Frequencies that are not finite (a wall the reader refuses) end the walks at once.
    // Not monotonic in n with held ends: every n a mesh can carry is tried.
    for (int n = 2; n <= kMaxLevelElementsAround / 2; ++n)
        if (const double f = ring_hz(scene, n); f <= top) {
            out.n_max = n;
            out.n_max_hz = f;
        }
    for (int j = 1; j <= kMaxElementsAlong && bending_hz(scene, j) <= top; ++j)
        out.half_waves = lambda(j) / std::numbers::pi;
    return out;
}

double expected_around_error(double slenderness, int n, int n_around) {
    return kAroundFit * std::pow(slenderness, kAroundSlendernessPower) * std::pow(n, kAroundWavePower) *
           std::pow(n_around, -kAroundOrder);
}

double expected_along_error(double half_waves, int n_along) {
    return kAlongFit * std::pow(half_waves / n_along, kAlongOrder);
}

MeshRule mesh_rule(const Scene& scene, double target) {
    MeshRule rule;
    rule.target = target;
    rule.band = band_waves(scene);
    rule.slenderness = slenderest(scene);
    if (rule.band.n_max >= 2) {
        const double needed =
            std::pow(kAroundSafety * kAroundFit * std::pow(rule.slenderness, kAroundSlendernessPower) *
                         std::pow(rule.band.n_max, kAroundWavePower) / target,
                     1 / kAroundOrder);
        // Written so that NaN keeps the smallest count.
        rule.around = needed > 4 ? multiple_of_4(std::min<double>(needed, kMaxLevelElementsAround)) : 4;
    }
    const double along = std::ceil(rule.band.half_waves * std::pow(kAlongFit / target, 1 / kAlongOrder));
    rule.along =
        along > kMinElementsAlong ? static_cast<int>(std::min<double>(along, kMaxElementsAlong)) : kMinElementsAlong;
    return rule;
}

std::optional<std::string> mesh_rule_text(const Scene& scene) {
    if (scene.mesh.file) return std::nullopt;
    const MeshLevel* level = find_mesh_level(scene.mesh.level);
    const double target = level ? level_target_error(*level) : level_target_error(*find_mesh_level("default"));
    const MeshRule rule = mesh_rule(scene, target);
    const BandWaves& b = rule.band;
    std::string text = "mesh from the band (docs/validation/accuracy-by-level.md, \"The mesh from the band\"): top " +
                       significant(b.top_hz, 4) + " Hz (" +
                       (b.top_estimated ? "estimated for " + std::to_string(scene.analysis.n_modes) +
                                              " modes: beam and thin-ring/shell formulas"
                                        : std::string("[analysis] band")) +
                       "), ";
    text += b.n_max >= 2
                ? "highest n = " + std::to_string(b.n_max) + " (thin ring/shell " + significant(b.n_max_hz, 4) + " Hz)"
                : std::string("no ring mode (n >= 2)");
    text += ", " + significant(b.half_waves, 2) + " axial half-waves; for " + percent(target, 2) + " (" +
            (level ? "level " + scene.mesh.level : std::string("the default level's target")) + ") it asks for ";
    if (rule.around > 0)
        text += std::to_string(rule.around) + " around (R/t " + significant(rule.slenderness, 3) + "), ";
    text += std::to_string(rule.along) + " along, 2 or more through the wall; this mesh (" +
            std::to_string(scene.mesh.n_wall) + "/" + std::to_string(scene.mesh.n_around) + "/" +
            std::to_string(scene.mesh.n_along) + " through/around/along) expects ";
    if (b.n_max >= 2)
        text += percent(expected_around_error(rule.slenderness, b.n_max, scene.mesh.n_around), 2) +
                " around (the solid level; the harmonic level is exact around) and ";
    text += percent(expected_along_error(b.half_waves, scene.mesh.n_along), 2) + " along";
    return text;
}

std::optional<std::string> explicit_mesh_warning(const Scene& scene, bool around_matters) {
    if (scene.mesh.file || scene.mesh.level != "custom") return std::nullopt;
    const MeshRule rule = mesh_rule(scene, level_target_error(*find_mesh_level("default")));
    const BandWaves& b = rule.band;
    std::vector<std::string> coarse;
    if (around_matters && b.n_max >= 2) {
        const double e = expected_around_error(rule.slenderness, b.n_max, scene.mesh.n_around);
        if (e > kExplicitMeshWarnError)
            coarse.push_back("around = " + std::to_string(scene.mesh.n_around) + " expects " + percent(e, 2) +
                             " on the band's n = " + std::to_string(b.n_max) + " modes (" +
                             std::to_string(rule.around) + " for 1 %)");
    }
    const double e = expected_along_error(b.half_waves, scene.mesh.n_along);
    if (e > kExplicitMeshWarnError)
        coarse.push_back("along = " + std::to_string(scene.mesh.n_along) + " expects " + percent(e, 2) + " on its " +
                         significant(b.half_waves, 2) + " axial half-waves (" + std::to_string(rule.along) +
                         " for 1 %)");
    if (coarse.empty()) return std::nullopt;
    std::string text = "[mesh] is coarser than the band needs (top " + significant(b.top_hz, 4) + " Hz): " + coarse[0];
    for (size_t i = 1; i < coarse.size(); ++i) text += "; " + coarse[i];
    return text + "; kept as given (docs/validation/accuracy-by-level.md, \"The mesh from the band\")";
}

}  // namespace coremodal
