#include "beam/eigenvalue_scale.hpp"

#include "beam/beam_theory.hpp"
#include "common/error.hpp"
#include "effects/support_effects.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// The lowest ring modes have two waves around (n = 1 is a rigid translation).
constexpr int kLowestRingWaveNumber = 2;

// One layer of the wall: core, or rest paper.
struct WallLayer {
    double r_in, r_out;
    const OrthotropicMaterial* material;
    double thickness() const { return r_out - r_in; }
};

std::vector<WallLayer> wall_layers(const Scene& s) {
    std::vector<WallLayer> layers{{s.core.inner_diameter / 2, s.core.outer_diameter / 2, &s.core.material}};
    if (s.rest_paper)
        layers.push_back({s.core.outer_diameter / 2, s.rest_paper->outer_diameter / 2, &s.rest_paper->material});
    return layers;
}

// n^2 (n^2 - 1)^2: the thin ring's bending factor for n waves around.
double ring_factor(int n) {
    const double n2 = n * n;
    return n2 * (n2 - 1) * (n2 - 1);
}

// The bending, shear, stretching and twisting of the roll as a beam over the
// span its first bending mode is compared with (beam_span): the first mode
// of the Euler–Bernoulli beam (clamped–clamped = free–free), of the shear
// beam (a body shorter than its diameter bends in shear), of the bar in
// tension and in torsion (free–free or fixed–fixed: pi / L).
void add_beam_families(const Scene& scene, std::vector<EigenvalueEstimate>& out) {
    const BeamSection s = beam_section(scene);
    // Clamp zones that meet leave no span: the core's length still bounds it.
    const double L = beam_span(scene) > 0 ? beam_span(scene) : scene.core.length;
    const double k_bend = kBeta1L / L, k = M_PI / L;
    out.push_back({"bending", std::pow(k_bend, 4) * s.EI / s.rho_A});
    out.push_back({"shear bending", k * k * s.kappa_GA / s.rho_A});
    out.push_back({"axial", k * k * s.EA / s.rho_A});
    out.push_back({"torsion", k * k * s.GJ / s.rho_J});
}

// The wall as a thin ring of the core's length (docs/theory/methods.md, "The eigenvalue scale"):
//   in its plane, n waves:  omega^2 = D / (m R^4) n^2 (n^2 - 1)^2 / (n^2 + 1),
//     D the wall's bending stiffness per unit length (layers about their
//     common neutral radius, E_theta), m its mass per unit area;
//   out of its plane (a ring or disc shorter than its wall bends and twists):
//     omega^2 = B / (mu R^4) n^2 (n^2 - 1)^2 / (n^2 + B / C),
//     B = E_theta t L^3 / 12, C = G J of the t x L section, mu = rho t L;
//   breathing (n = 0): omega^2 = E_theta / (rho R^2).
// R is the wall's middle radius. A thick or shear-soft wall lies below the
// thin-ring values (by up to a factor of two in frequency: shear and
// rotary inertia): the right order of magnitude, which is all the scale needs.
void add_section_families(const Scene& scene, std::vector<EigenvalueEstimate>& out) {
    const std::vector<WallLayer> layers = wall_layers(scene);
    const double r_in = layers.front().r_in, r_out = layers.back().r_out, t = r_out - r_in;
    const double R = (r_in + r_out) / 2, L = scene.core.length;
    double Et = 0, Er = 0, rho_t = 0, Gt = 0;  // sums over the layers, per unit length of wall
    for (const WallLayer& l : layers) {
        const OrthotropicMaterial& m = *l.material;
        Et += m.E_theta * l.thickness();
        Er += m.E_theta * (l.r_out * l.r_out - l.r_in * l.r_in) / 2;
        rho_t += m.density * l.thickness();
        // Twisting the r-z section about the ring's axis shears it in the r-theta and theta-z planes.
        Gt += std::min(m.G_rtheta, m.G_thetaz) * l.thickness();
    }
    const double r_neutral = Er / Et;
    double D = 0;
    for (const WallLayer& l : layers)
        D += l.material->E_theta * (std::pow(l.r_out - r_neutral, 3) - std::pow(l.r_in - r_neutral, 3)) / 3;
    const int n = kLowestRingWaveNumber;
    const double n2 = n * n, R4 = std::pow(R, 4);
    out.push_back({"ring in-plane n = 2", D / (rho_t * R4) * ring_factor(n) / (n2 + 1)});

    out.push_back({"breathing", Et / (rho_t * R * R)});
    // Out of its plane only where the ring is shorter than its wall (a disc):
    // a longer one bends in its plane first, and the formula, which leaves
    // out the section's rotary inertia, would undershoot it by far.
    if (L >= t) return;
    const double J = (1 - 0.63 * L / t) / 3 * L * L * L * t;  // Saint-Venant torsion of t x L (L < t), Roark
    const double B = Et * L * L * L / 12, C = Gt / t * J;
    out.push_back({"ring out-of-plane n = 2", B / (rho_t * L * R4) * ring_factor(n) / (n2 + B / C)});
}

// The roll on its supports' springs, by Rayleigh quotients K / m of rigid
// trial motions (each an upper bound of the lowest eigenvalue):
//   the roll sliding on spring interfaces while the chucks stand still
//     (axially: k_t per area; sideways: (k_n + k_t) / 2 per area, averaged around),
//   everything but the frames moving sideways on elastic bearings at both ends,
//   each frame mass moving alone between its bearing and frame springs.
void add_support_families(const Scene& scene, std::vector<EigenvalueEstimate>& out) {
    const auto& chucks = scene.supports.chucks;
    if (chucks.empty()) return;
    double k_axial = 0, k_sideways = 0;
    for (const ChuckEffects& c : support_effects(scene).chucks) {
        if (!c.spring_layer) continue;
        for (const ExpandingElement& e : c.placement.expanding) {
            k_axial += c.spring_layer->axial_stiffness(e, scene.core.inner_diameter / 2);
            k_sideways += c.spring_layer->sideways_stiffness(e, scene.core.inner_diameter / 2);
        }
    }
    if (k_axial > 0) out.push_back({"roll on the chuck interfaces", std::min(k_axial, k_sideways) / scene.roll_mass()});
    double k_bearings = 0, frames = 0;
    bool all_elastic = true;
    for (const ChuckSpec& c : chucks) {
        const BearingSpec& b = c.bearing;
        all_elastic = all_elastic && !b.rigid;
        if (b.rigid) continue;
        k_bearings += b.radial_stiffness;
        if (b.frame_mass && b.frame_stiffness) {
            frames += *b.frame_mass;
            out.push_back({"frame mass on its springs", (b.radial_stiffness + *b.frame_stiffness) / *b.frame_mass});
        }
    }
    if (all_elastic && k_bearings > 0)
        out.push_back({"roll and chucks on the bearings", k_bearings / (scene.mass_from_dimensions() - frames)});
}

}  // namespace

std::vector<EigenvalueEstimate> elastic_eigenvalue_estimates(const Scene& scene, ModeFamilies families) {
    std::vector<EigenvalueEstimate> out;
    add_beam_families(scene, out);
    if (families == ModeFamilies::beam_and_section) add_section_families(scene, out);
    add_support_families(scene, out);
    return out;
}

EigenvalueEstimate elastic_eigenvalue_scale(const Scene& scene, ModeFamilies families) {
    const std::vector<EigenvalueEstimate> all = elastic_eigenvalue_estimates(scene, families);
    COREMODAL_ASSERT(!all.empty());  // the beam families always exist
    return *std::min_element(all.begin(), all.end(),
                             [](const EigenvalueEstimate& a, const EigenvalueEstimate& b) { return a.lambda < b.lambda; });
}

ModeRequest mode_request(const Scene& scene, ModeFamilies families) {
    ModeRequest r;
    r.n_modes = scene.analysis.n_modes;
    if (scene.analysis.f_max_hz) {
        r.lambda_max = std::pow(2 * M_PI * *scene.analysis.f_max_hz, 2);
        r.lambda_min = std::pow(2 * M_PI * scene.analysis.f_min_hz.value_or(0.0), 2);
    }
    r.lambda_scale = elastic_eigenvalue_scale(scene, families).lambda;
    r.tolerance = scene.analysis.tolerance;
    return r;
}

}  // namespace coremodal
