// The coupled-harmonic level (models/coupled, docs/theory/coupled.md "Coupled
// harmonics"): with nothing to couple it is the harmonic level; with
// segmented chucks it agrees with the 3D solid within the solid's own
// circumferential error; and it converges in N from above. The paper web's
// line: exact on a rigid roll, and with the solid on a clamped core.
#include "tube_scenes.hpp"

#include "geometry/section_mesh.hpp"
#include "geometry/tube_section.hpp"
#include "effects/web.hpp"
#include "models/coupled/coupled_level.hpp"
#include "models/coupled/coupled_system.hpp"
#include "models/part_materials.hpp"
#include "models/solve_steps.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Sparse>

#include <cmath>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

// The paper core of the chuck tests (76 x 15 mm, 1 m unless said) on spring-layer
// chucks, each band cut into `segments` pads of `angle_deg` (0: full bands).
Scene segmented_chucks(int segments, double angle_deg, int around = 16, int along = 24, double length = 1.0) {
    Scene s = with_chucks(paper_core(length, around, along), InterfaceKind::spring);
    for (ChuckSpec& c : s.supports.chucks)
        for (ExpandingElement& e : c.expanding) {
            e.segments = segments;
            e.segment_angle = angle_deg * M_PI / 180;
        }
    s.analysis.n_modes = 10;
    return s;
}

CoupledModes coupled_at(const Scene& scene, int n_max, const std::optional<LocalHarmonics>& local = std::nullopt) {
    const SectionMesh section = make_section_mesh(make_tube_section(scene), scene.supports.clamps);
    const std::vector<PartMaterial> materials = part_materials(scene, section.part_names, "generated section");
    return solve_coupled(scene, section, materials, n_max, solve_request(scene), attachments(scene), local);
}

}  // namespace

TEST_CASE("Coupled level with full bands: block diagonal, the harmonic level's eigenvalues to 1e-8", "[coupled]") {
    const Scene scene = segmented_chucks(0, 0);
    const RunReport h = solve_without_chuck_factor(at_level(scene, ModelChoice::harmonic));
    const CoupledModes c = coupled_at(scene, 4);
    CHECK(c.n_coupling_entries == 0);
    REQUIRE(c.verification.complete);
    REQUIRE(c.eigenvalues.size() >= h.modes.modes.size());
    for (size_t i = 0; i < h.modes.modes.size(); ++i) {
        const Mode& m = h.modes.modes[i];
        INFO("mode " << i + 1 << ": " << m.label.type << " n=" << m.label.n << " " << m.frequency_hz << " Hz");
        REQUIRE(m.label.n <= 4);
        CHECK(c.eigenvalues[i] == Approx(m.eigenvalue).epsilon(1e-8));
    }
    CHECK(c.mass_kg == Approx(h.model.mass_kg).epsilon(1e-12));
    SECTION("and a level asked for coupled harmonics of a scene nothing couples hands it to the harmonic level") {
        check_same_eigenvalues(solve_without_chuck_factor(at_level(scene, ModelChoice::coupled)), h, 1e-12);
    }
}

TEST_CASE("Coupled level: pads that cover the whole circumference are the full band", "[coupled]") {
    // One segment of 360 deg: I_pads = I_band for every pair, so no coupling survives.
    const CoupledModes one = coupled_at(segmented_chucks(1, 360), 3);
    const CoupledModes band = coupled_at(segmented_chucks(0, 0), 3);
    CHECK(one.n_coupling_entries == 0);
    REQUIRE(one.eigenvalues.size() >= 8);
    for (size_t i = 0; i < 8; ++i) CHECK(one.eigenvalues[i] == Approx(band.eigenvalues[i]).epsilon(1e-10));
}

TEST_CASE("Coupled level converges in N from above, in shrinking steps", "[coupled]") {
    const Scene scene = segmented_chucks(3, 60);
    std::vector<std::vector<double>> lambdas;
    for (int n_max : {4, 7, 10, 13}) {
        const CoupledModes c = coupled_at(scene, n_max);
        REQUIRE(c.verification.complete);
        CHECK(c.n_coupling_entries > 0);
        lambdas.push_back({c.eigenvalues.begin(), c.eigenvalues.begin() + 10});
    }
    std::vector<double> step(lambdas.size(), 0);
    for (size_t s = 1; s < lambdas.size(); ++s)
        for (size_t i = 0; i < 10; ++i) {
            // Nested spaces (Rayleigh-Ritz): no eigenvalue rises when harmonics are added.
            CHECK(lambdas[s][i] <= lambdas[s - 1][i] * (1 + 1e-10));
            step[s] = std::max(step[s], (lambdas[s - 1][i] - lambdas[s][i]) / lambdas[s][i]);
        }
    INFO("largest relative eigenvalue steps: " << step[1] << ", " << step[2] << ", " << step[3]);
    CHECK(step[1] > 0);
    CHECK(step[2] < step[1]);
    CHECK(step[3] < step[2]);
    CHECK(step[3] < step[1] / 4);  // measured: 0.0139, 0.0039, 0.0017 (eigenvalues, twice the frequency change)
}

TEST_CASE("Coupled level: a level reused on a like scene starts one step below its last N, and stops as a fresh one",
          "[coupled][long]") {
    const Scene first = segmented_chucks(3, 60), second = segmented_chucks(3, 60, 16, 24, 1.2);
    const Printer quiet{false};
    CoupledLevel reused, fresh;
    reused.solve(first, quiet);
    const int reach = 3;  // three pads couple n to n +- 3
    const int last = reused.convergence().back().n_max;
    const LevelModes again = reused.solve(second, quiet);
    const LevelModes alone = fresh.solve(second, quiet);
    const std::vector<CoupledStep>& steps = reused.convergence();
    INFO("first scene stopped at N = " << last << "; the second, reused: N = " << steps.front().n_max << " ... "
                                       << steps.back().n_max << ", fresh: N = " << fresh.convergence().back().n_max);
    // The search starts one step below where the last one stopped, never lower than N_s + 1.
    CHECK(steps.front().n_max == std::max(reach + 1, last - reach));
    CHECK(steps.back().max_change <= kCoupledTolerance);
    CHECK(again.verification.complete);
    // The same stopping rule: each frequency within the truncation error left
    // at a step (about 1.5 times the step, coupled_level.hpp) of the fresh
    // search's, and from below where it ends at a larger N (nested spaces).
    const int n_reused = steps.back().n_max, n_fresh = fresh.convergence().back().n_max;
    REQUIRE(again.modes.size() == alone.modes.size());
    for (size_t i = 0; i < alone.modes.size(); ++i) {
        const double a = again.modes[i].frequency_hz, b = alone.modes[i].frequency_hz;
        CHECK(std::abs(a - b) <= 3 * kCoupledTolerance * b);
        if (n_reused > n_fresh) CHECK(a <= b * (1 + 1e-10));
        if (n_reused == n_fresh) CHECK(a == Approx(b).epsilon(1e-9));
    }
}

TEST_CASE("Coupled level: harmonics kept near the pads bound the whole ones from above, and show a reach too short",
          "[coupled]") {
    // A 2.2 m core (case 10's) on three 60 deg pads per chuck, N = 7.
    const Scene scene = segmented_chucks(3, 60, 16, 40, 2.2);
    const SectionMesh section = make_section_mesh(make_tube_section(scene), scene.supports.clamps);
    const Attachments attached = attachments(scene);
    const std::optional<LocalHarmonics> local = local_harmonics(attached, section);
    REQUIRE(local);
    LocalHarmonics short_reach = *local;
    short_reach.reach_2 /= 32;  // an eighth of a diameter at n = 2
    const CoupledModes whole = coupled_at(scene, 7), kept = coupled_at(scene, 7, local),
                       cut = coupled_at(scene, 7, short_reach);
    REQUIRE(whole.verification.complete);
    REQUIRE(kept.verification.complete);
    REQUIRE(cut.verification.complete);
    CHECK(kept.dofs.n_dofs < whole.dofs.n_dofs * 3 / 4);
    const size_t n = 10;
    double kept_error = 0, cut_error = 0;
    for (size_t i = 0; i < n; ++i) {
        // A Ritz restriction of the whole: never below it.
        CHECK(kept.eigenvalues[i] >= whole.eigenvalues[i] * (1 - 1e-10));
        CHECK(cut.eigenvalues[i] >= kept.eigenvalues[i] * (1 - 1e-10));
        kept_error = std::max(kept_error, kept.eigenvalues[i] / whole.eigenvalues[i] - 1);
        cut_error = std::max(cut_error, cut.eigenvalues[i] / whole.eigenvalues[i] - 1);
    }
    const double kept_edge = zone_edge_amplitude(kept, section, *local, n);
    const double cut_edge = zone_edge_amplitude(cut, section, short_reach, n);
    INFO("default reach: eigenvalue error " << kept_error << ", zone edge " << kept_edge << "; short reach: error "
                                            << cut_error << ", zone edge " << cut_edge);
    // The default reach leaves the eigenvalues 100 times inside the N tolerance, and says so.
    CHECK(kept_error < kCoupledTolerance / 100);
    CHECK(kept_edge < kZoneEdgeTolerance);
    // A reach too short shows at the zone's edge, and the error it causes is
    // of the order of the edge amplitude squared (error / edge^2 measured
    // 1 to 44 over reaches of 1/16 to 1 times the default: docs/theory/coupled.md).
    CHECK(cut_edge > kZoneEdgeTolerance);
    CHECK(cut_error > kept_error);
    CHECK(cut_error < 100 * cut_edge * cut_edge);
}

TEST_CASE("Coupled level against the 3D solid on segmented chucks, mode by mode", "[coupled][long]") {
    const Scene scene = segmented_chucks(3, 60);
    const RunReport c = solve_without_chuck_factor(at_level(scene, ModelChoice::coupled));
    REQUIRE(c.model.level == ModelChoice::coupled);
    REQUIRE(c.modes.verification.complete);
    CHECK(c.modes.verification.max_relative_residual < 1e-8);
    CHECK(c.modes.verification.max_orthonormality_error < 1e-8);
    CHECK(c.model.mass_kg == Approx(c.model.expected_mass_kg).epsilon(1e-9));
    const RunReport coarse = solve_without_chuck_factor(at_level(segmented_chucks(3, 60, 16), ModelChoice::solid));
    const RunReport fine = solve_without_chuck_factor(at_level(segmented_chucks(3, 60, 32), ModelChoice::solid));
    check_within_solid_error(c, coarse, fine, true);
}

TEST_CASE("Coupled level: the web's line holds a rigid roll with its three springs, exactly", "[coupled][web]") {
    // A free paper core 1 m long with a web leaving at 30 deg from theta =
    // -60 deg. Moved rigidly, the roll's own stiffness does no work, so the
    // coupled K's energy minus the same without the web is the line's alone:
    // a shift along d, n or z gives k_d L, k_n L, k_z L; a turn about the axis
    // moves the line by R along d: k_d R^2 L (the section's outer line is at
    // R exactly). The shifts live in (1, cos) and (1, sin), the axial motion
    // and the turn in n = 0: the web couples those blocks.
    Scene scene = paper_core(1.0, 16, 8);
    scene.web = web_along(30, 300, 5e9);
    Scene bare = scene;
    bare.web.reset();
    const SectionMesh section = make_section_mesh(make_tube_section(scene), scene.supports.clamps);
    const std::vector<PartMaterial> materials = part_materials(scene, section.part_names, "generated section");
    const CoupledDofs dofs = coupled_dofs(scene, section, 2);
    const auto field = [&](int n, Family f, RigidMotion motion, double scale, std::vector<double>& x) {
        const CoupledBlock& block = dofs.blocks[dofs.block_of(n, f)];
        const std::vector<double> v = harmonic_rigid_field(section, block.dofs, n, motion);
        for (size_t i = 0; i < v.size(); ++i) x[block.offset + i] += scale * v[i];
    };
    const auto energy = [&](const Scene& s, const std::vector<double>& x) {
        double e = 0;
        assemble_coupled_terms(s, section, materials, dofs,
                               [&](Term t, const std::vector<int>& rows, const std::vector<int>& cols,
                                   const Eigen::MatrixXd& A) {
                                   if (t != Term::stiffness) return;
                                   for (size_t a = 0; a < rows.size(); ++a)
                                       for (size_t b = 0; b < cols.size(); ++b)
                                           if (rows[a] >= 0 && cols[b] >= 0) e += x[rows[a]] * A(a, b) * x[cols[b]];
                               });
        return e;
    };
    const auto web_energy = [&](const std::vector<double>& x) { return energy(scene, x) - energy(bare, x); };
    const WebSpec& w = *scene.web;
    const double L = 1.0, R = 0.053;
    const double k_d = w.modulus * w.thickness / w.span, k_n = w.tension / w.span;
    const double k_z = (w.shear_modulus * w.thickness + w.tension) / w.span;
    const Eigen::Vector3d d = web_direction(w), n = web_tangent_normal(w);
    const auto shift = [&](const Eigen::Vector3d& v) {
        std::vector<double> x(dofs.n_dofs, 0.0);
        field(1, Family::cos, RigidMotion::x, v.x(), x);  // x lives in (1, cos), y in (1, sin)
        field(1, Family::sin, RigidMotion::x, v.y(), x);
        return x;
    };
    CHECK(web_energy(shift(d)) == Approx(k_d * L).epsilon(1e-9));
    CHECK(web_energy(shift(n)) == Approx(k_n * L).epsilon(1e-9));
    CHECK(web_energy(shift(d + n)) == Approx((k_d + k_n) * L).epsilon(1e-9));
    std::vector<double> axial(dofs.n_dofs, 0.0), turn(dofs.n_dofs, 0.0);
    field(0, Family::cos, RigidMotion::z, 1, axial);
    field(0, Family::cos, RigidMotion::rz, 1, turn);
    CHECK(web_energy(axial) == Approx(k_z * L).epsilon(1e-9));
    CHECK(web_energy(turn) == Approx(k_d * R * R * L).epsilon(1e-9));
    SECTION("the line couples every block to every other: one independent set") {
        const std::vector<CoupledComponent> sets = coupled_components(dofs, attachments(scene));
        CHECK(sets.size() == 1);
        CHECK(attachments(scene).step() == 1);
    }
}

TEST_CASE("Coupled level: a clamped core on a web splits its bending pair as the 3D solid does", "[coupled][web][long]") {
    // A paper core 1 m long clamped over 70 mm at each end, a strong web
    // (2 kN/m, 20 GPa: k_d = 1.3e6, k_n = 1.7e3 N/m^2) leaving along +x: it
    // stiffens the bending along the web (x) far more than across it (y).
    // The coupled level against the solid at 16 and 32 around, mode by mode,
    // within the solid's own change from 16 to 32 around (plus 2e-4, the
    // coupled truncation and the solid's quadratic arcs), as for the pads.
    const auto scene_at = [](int around, ModelChoice level) {
        Scene s = clamp_both_ends(paper_core(1.0, around, 24), 0.07);
        s.web = web_along(0, 2000, 20e9);
        s.analysis.n_modes = 6;
        s.model = level;
        return s;
    };
    const RunReport c = solve_without_chuck_factor(scene_at(16, ModelChoice::automatic));
    REQUIRE(c.model.level == ModelChoice::coupled);
    REQUIRE(c.modes.verification.complete);
    CHECK(c.modes.verification.max_relative_residual < 1e-8);
    const RunReport coarse = solve_without_chuck_factor(scene_at(16, ModelChoice::solid));
    const RunReport fine = solve_without_chuck_factor(scene_at(32, ModelChoice::solid));
    const RunReport bare = solve_without_chuck_factor([&] {
        Scene s = scene_at(16, ModelChoice::harmonic);
        s.web.reset();
        return s;
    }());
    check_within_solid_error(c, coarse, fine, false);
    // The pair splits: across the web (y) it barely moves from the bare core,
    // along it (x) it rises by more than the solid's discretisation error.
    const double f_bare = nth_of_type(bare, "bending").frequency_hz;
    const double f_low = c.modes.modes[0].frequency_hz, f_high = c.modes.modes[1].frequency_hz;
    INFO("bare " << f_bare << " Hz; on the web " << f_low << " and " << f_high << " Hz");
    CHECK(f_low > f_bare);
    CHECK(f_high - f_low > 0.01 * f_bare);
}

TEST_CASE("Coupled level: the sin set of three pads is a signed copy of the cos set, and is not solved twice",
          "[coupled]") {
    // Three 60-degree pads: the sets {1, 2, 4, 5, 7} cos and sin (N = 7).
    // The sin set's K and M are S K S and S M S of the cos set's, S =
    // diag(s_n) with s_n = +1 for n = 1 mod 3 and -1 for n = 2 mod 3: the
    // pads couple n and m of one class through C(n - m) alike in both
    // families, and of opposite classes through C(n + m), whose sign the sin
    // family turns (docs/theory/coupled.md). Checked on the assembled matrices.
    const Scene scene = segmented_chucks(3, 60, 16, 8);
    const SectionMesh section = make_section_mesh(make_tube_section(scene), scene.supports.clamps);
    const std::vector<PartMaterial> materials = part_materials(scene, section.part_names, "generated section");
    const CoupledDofs all = coupled_dofs(scene, section, 7);
    const std::vector<CoupledComponent> sets = coupled_components(all, attachments(scene));
    REQUIRE(sets.size() == 4);  // n = 0 split: {0 (U, W), 3c, 6c}, {0 (V), 3s, 6s}, and the two partners
    int partners = 0;
    for (const CoupledComponent& partner : sets) {
        if (partner.partner_of < 0) continue;
        ++partners;
        const CoupledComponent& primary = sets[partner.partner_of];
        REQUIRE(partner.dofs.blocks.size() == primary.dofs.blocks.size());
        for (size_t b = 0; b < partner.dofs.blocks.size(); ++b) {
            const HarmonicFamily h = partner.dofs.blocks[b].harmonic;
            CHECK(h.family == Family::sin);
            CHECK(primary.dofs.blocks[b].harmonic == HarmonicFamily{h.n, Family::cos});
            CHECK(partner.block_sign[b] == (h.n % 3 == 1 ? 1.0 : -1.0) * partner.block_sign[0]);
        }
        const auto sparse = [&](const CoupledDofs& d, Term which) {
            std::vector<Eigen::Triplet<double>> t;
            assemble_coupled_terms(scene, section, materials, d,
                                   [&](Term term, const std::vector<int>& rows, const std::vector<int>& cols,
                                       const Eigen::MatrixXd& A) {
                                       // K: every term but the mass (the spring layer's too).
                                       if ((term == Term::mass) != (which == Term::mass)) return;
                                       for (size_t a = 0; a < rows.size(); ++a)
                                           for (size_t c = 0; c < cols.size(); ++c)
                                               if (rows[a] >= 0 && cols[c] >= 0) t.emplace_back(rows[a], cols[c], A(a, c));
                                   });
            Eigen::SparseMatrix<double> A(d.n_dofs, d.n_dofs);
            A.setFromTriplets(t.begin(), t.end());
            return A;
        };
        Eigen::VectorXd s(partner.dofs.n_dofs);
        for (size_t b = 0; b < partner.dofs.blocks.size(); ++b)
            s.segment(partner.dofs.blocks[b].offset, partner.dofs.blocks[b].dofs.n_dofs).setConstant(partner.block_sign[b]);
        for (Term t : {Term::stiffness, Term::mass}) {
            const Eigen::SparseMatrix<double> A = sparse(primary.dofs, t), B = sparse(partner.dofs, t);
            const Eigen::SparseMatrix<double> SAS = s.asDiagonal() * A * s.asDiagonal();
            CHECK((B - SAS).norm() <= 1e-13 * A.norm());
            CHECK(A.norm() > 0);
        }
    }
    CHECK(partners == 1);
    SECTION("four pads: the sets of n = 2 mod 4 are coupled through C(n + m) within their class, and are no partners") {
        const Scene four = segmented_chucks(4, 45, 16, 8);
        const std::vector<CoupledComponent> sets4 = coupled_components(coupled_dofs(four, section, 6), attachments(four));
        for (const CoupledComponent& c : sets4)
            if (c.partner_of >= 0)
                for (const CoupledBlock& b : c.dofs.blocks) CHECK(b.harmonic.n % 2 == 1);
    }
}
