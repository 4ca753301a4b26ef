// Scenes for verification tests, built in code so that the solver is tested
// independently of the case-file parser.
#pragma once

#include "analyses/run/run.hpp"
#include "assembly/chuck_supports.hpp"
#include "effects/web.hpp"
#include "assembly/petsc_system.hpp"
#include "geometry/section_mesh.hpp"
#include "geometry/tube_model.hpp"
#include "geometry/tube_section.hpp"
#include "models/part_materials.hpp"
#include "models/solid/gravity_contact.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "scene/chuck_contact.hpp"
#include "scene/scene.hpp"
#include "support/test_materials.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace coremodal::testing {

inline Scene steel_tube(double d_out, double d_in, double length, int wall, int around, int along,
                        int n_modes = 12) {
    Scene s;
    s.name = "steel_tube";
    s.source_file = "(test)";
    s.core = {d_in, d_out, length, OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850)};
    s.supports.kind = SupportKind::free;
    s.mesh.level = "custom";
    s.mesh.n_wall = wall;
    s.mesh.n_around = around;
    s.mesh.n_along = along;
    s.analysis.n_modes = n_modes;
    return s;
}

inline Scene clamp_both_ends(Scene s, double clamp_length) {
    s.supports.kind = SupportKind::clamped;
    s.supports.clamps = {{"left", 0.0, clamp_length}, {"right", s.core.length - clamp_length, s.core.length}};
    return s;
}

inline RunReport solve_quietly(const Scene& s) {
    RunOptions options;
    options.quiet = true;
    options.write_results = false;
    return run_scene(s, options);
}

// The same without the chuck factor's free-span solve (for f1 alone).
inline RunReport solve_without_chuck_factor(const Scene& s) {
    RunOptions options;
    options.quiet = true;
    options.write_results = false;
    options.chuck_factor_by_fe = false;
    return run_scene(s, options);
}

// The k-th (1-based) mode of a type, counting each degenerate pair once.
inline const Mode& nth_of_type(const RunReport& r, const std::string& type, int k = 1) {
    int seen = 0;
    double last = -1;
    for (const auto& m : r.modes.modes) {
        if (m.label.type != type) continue;
        if (last > 0 && std::abs(m.frequency_hz - last) < 1e-6 * last) continue;  // partner of a pair
        last = m.frequency_hz;
        if (++seen == k) return m;
    }
    throw std::runtime_error("no mode " + std::to_string(k) + " of type " + type);
}

}  // namespace coremodal::testing

namespace coremodal::testing {

// A paperboard core (76 x 15 mm) of the given length, small mesh.
inline Scene paper_core(double length, int around = 16, int along = 24) {
    Scene s = steel_tube(0.106, 0.076, length, 2, around, along, 8);
    s.name = "paper_core";
    s.core.material = paperboard();
    return s;
}

// Steel chucks at both ends: 110 mm inserted, 0.5 mm radial clearance, a
// 60 mm shaft 150 mm long, one band 60 mm wide ending at the body's end
// (centre 80 mm), so that a rigid clamp over the band meshes identically.
inline Scene with_chucks(Scene s, InterfaceKind interface, double k_normal = 3.1e10) {
    ChuckSpec c;
    c.name = "left";
    c.inserted_length = 0.11;
    c.body_diameter = s.core.inner_diameter - 2 * 0.5e-3;
    c.shaft_diameter = 0.06;
    c.shaft_length = 0.15;
    c.material = OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850);
    c.expanding = {{0.08, 0.06, 0, 0}};
    c.interface.kind = interface;
    c.interface.normal_stiffness = k_normal;
    c.interface.tangential_stiffness = 0.82 * k_normal;
    s.supports.kind = SupportKind::chucks;
    s.supports.chucks = {c, c};
    s.supports.chucks[1].name = "right";
    return s;
}

// The chucks' bearings made elastic: radial (N/m) and tilting (N m/rad)
// springs, through a frame mass (kg) on a frame spring (N/m) when given.
inline Scene on_elastic_bearings(Scene s, double radial, double tilting, std::optional<double> frame_mass = {},
                                 std::optional<double> frame_stiffness = {}) {
    for (ChuckSpec& c : s.supports.chucks) {
        c.bearing.rigid = false;
        c.bearing.radial_stiffness = radial;
        c.bearing.tilting_stiffness = tilting;
        c.bearing.frame_mass = frame_mass;
        c.bearing.frame_stiffness = frame_stiffness;
    }
    return s;
}

// The mesh run_scene builds for a generated scene (same nodes, same order).
inline Mesh generated_mesh(const Scene& s) {
    GmshSession gmsh;
    build_tube_model(make_tube_section(s), s.supports.clamps, s.mesh.element);
    Mesh mesh = read_current_gmsh_mesh("test mesh");
    add_frame_nodes(s, mesh);
    return mesh;
}

// A news web 80 um thick over a 1.2 m span, leaving at angle_deg, with
// Baum's shear modulus (effects/web.hpp).
inline WebSpec web_along(double angle_deg, double tension = 300, double modulus = 5e9) {
    WebSpec w;
    w.tension = tension;
    w.span = 1.2;
    w.angle = angle_deg * M_PI / 180;
    w.thickness = 80e-6;
    w.modulus = modulus;
    w.shear_modulus = default_web_shear_modulus(modulus);
    return w;
}

// The rigid-clamp scene the chucks approach: clamps over the bands.
inline Scene clamped_over_bands(Scene s) {
    s.supports.kind = SupportKind::clamped;
    s.supports.clamps = {{"left", 0.05, 0.11}, {"right", s.core.length - 0.11, s.core.length - 0.05}};
    return s;
}

// Both chucks not expanded: one-sided contact, k_n0 given (Pa/m).
inline Scene not_expanded(Scene s, double k0) {
    s = with_chucks(std::move(s), InterfaceKind::spring, k0);
    for (ChuckSpec& c : s.supports.chucks) {
        c.interface.expanded = false;
        c.interface.contact = ContactKind::one_sided;
    }
    return s;
}

// Every modulus of m times `factor` (a nearly rigid body).
inline OrthotropicMaterial stiffened(OrthotropicMaterial m, double factor) {
    for (double* E : {&m.E_r, &m.E_theta, &m.E_z, &m.G_rtheta, &m.G_rz, &m.G_thetaz}) *E *= factor;
    return m;
}

// A rigid core of bore radius `bore` on a rigid chuck, dropped by delta
// across the radial clearance c: interpenetration d(psi) = delta cos(psi) - c
// (psi from the top), the stack law's pressure, and its upward force over
// the inserted length (N).
inline double rigid_contact_force(double delta, double c, double bore, double inserted, const StackContact& law) {
    const int n = 20000;
    double F = 0;
    for (int i = 0; i < n; ++i) {
        const double psi = -M_PI / 2 + M_PI * (i + 0.5) / n;
        F += law.pressure(delta * std::cos(psi) - c) * std::cos(psi) * M_PI / n;
    }
    return F * bore * inserted;
}

// The drop at which the rigid contact carries `load` (bisection: the force rises with the drop).
inline double rigid_contact_drop(double load, double c, double bore, double inserted, const StackContact& law) {
    double lo = c, hi = 2 * c;
    for (int i = 0; i < 200; ++i)
        (rigid_contact_force((lo + hi) / 2, c, bore, inserted, law) < load ? lo : hi) = (lo + hi) / 2;
    return (lo + hi) / 2;
}

// The scene at another model level.
inline Scene at_level(Scene s, ModelChoice level) {
    s.model = level;
    return s;
}

// The r-z section a harmonic or coupled run meshes, with its materials.
struct Section {
    SectionMesh mesh;
    std::vector<PartMaterial> materials;
};
inline Section section_of(const Scene& s) {
    Section out{make_section_mesh(make_tube_section(s), s.supports.clamps), {}};
    out.materials = part_materials(s, out.mesh.part_names, "generated section");
    return out;
}

// with_chucks' geometry, for closed forms of its one-sided contact.
constexpr double kChuckClearance = 0.5e-3;  // m, radial
constexpr double kChuckBore = 0.038;        // m, the core's bore radius
constexpr double kChuckInserted = 0.11;     // m

// The 3D solid's static contact under gravity (models/solid/gravity_contact).
inline GravityContact solid_static_contact(const Scene& s) {
    const Mesh mesh = generated_mesh(s);
    const ChuckSupports supports = chuck_supports(s, mesh);
    const DofMap dofs = make_dof_map(mesh.n_nodes(), supports.eliminated, supports.ties);
    const OperatorSet system =
        assemble_petsc(mesh, part_materials(s, mesh.part_names, "test mesh"), dofs, supports.couplings);
    return solve_gravity_contact(system, dofs, supports, support_effects(s), Printer{false});
}

// A rigid core on rigid chucks not expanded: core and chucks 1000 x stiffer,
// so that only the contact layer (k_n0 = 1e8 Pa/m, u0 = 200 um) deforms; it
// closes an arc of tens of degrees at pressures where the law's exponential matters.
inline Scene rigid_core_not_expanded(int around) {
    Scene s = not_expanded(paper_core(0.5, around, 16), 1e8);
    s.core.material = stiffened(s.core.material, 1e3);
    for (ChuckSpec& c : s.supports.chucks) c.material = stiffened(c.material, 1e3);
    return s;
}

// Two runs of one scene give the same modes (eigenvalues to `epsilon`).
inline void check_same_eigenvalues(const RunReport& a, const RunReport& b, double epsilon) {
    REQUIRE(a.modes.modes.size() == b.modes.modes.size());
    for (size_t i = 0; i < a.modes.modes.size(); ++i)
        CHECK(a.modes.modes[i].eigenvalue == Approx(b.modes.modes[i].eigenvalue).epsilon(epsilon));
}

// A coupled run against the solid at 16 and 32 around, mode by mode: the
// same type (and n when `same_n`), and the frequency within the solid's own
// circumferential error. The solid at 32 around is off the converged value
// by less than its change from 16 to 32 around whenever it converges at
// least at first order in theta; 2e-4 more covers its quadratic arcs (mass
// 1e-5 low) and the coupled truncation (kCoupledTolerance).
inline void check_within_solid_error(const RunReport& coupled, const RunReport& solid16, const RunReport& solid32,
                                     bool same_n) {
    REQUIRE(solid32.modes.modes.size() == coupled.modes.modes.size());
    REQUIRE(solid16.modes.modes.size() == coupled.modes.modes.size());
    for (size_t i = 0; i < coupled.modes.modes.size(); ++i) {
        const Mode &a = coupled.modes.modes[i], &b = solid32.modes.modes[i], &b16 = solid16.modes.modes[i];
        INFO("mode " << i + 1 << ": coupled " << a.frequency_hz << " Hz " << a.label.type << " n=" << a.label.n
                     << ", solid 32 around " << b.frequency_hz << " Hz " << b.label.type << " n=" << b.label.n
                     << ", 16 around " << b16.frequency_hz << " Hz");
        CHECK(a.label.type == b.label.type);
        if (same_n) CHECK(a.label.n == b.label.n);
        const double solid_error = std::abs(b16.frequency_hz - b.frequency_hz);
        CHECK(std::abs(a.frequency_hz - b.frequency_hz) <= solid_error + 2e-4 * b.frequency_hz);
    }
}

}  // namespace coremodal::testing
