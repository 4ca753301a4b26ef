// The completeness count of a spinning operator set (gyroscopic_solver.hpp),
// neg Q(omega) of the Hermitian Q(omega) = K(Omega) - omega^2 M + i omega Omega G
// with K(Omega) = K + K_sigma + Omega^2 K_Omega, for many (Omega, omega) on
// one set: a Campbell sweep counts twice per speed and wave number.
//
// Two savings over count_gyroscopic_below, both exact:
//
// 1. Mirrored families. When the set is two families (a, b) with
//        K-like = [[S, 0], [0, S]] (every stiffness-like term and M),
//        G = [[0, Gab], [-Gab, 0]], Gab symmetric
//    (a spinning harmonic of wave number n >= 1, spinning_harmonic.hpp),
//    then Q = [[A, iB], [-iB, A]] with A = S(Omega) - omega^2 M_S and
//    B = omega Omega Gab, and the unitary U = [[I, I], [-iI, iI]] / sqrt 2
//    gives U^H Q U = diag(A + B, A - B): neg Q = neg(A + B) + neg(A - B),
//    two real symmetric matrices of one family's size, where the general
//    count factors the real form [[A, -B], [B, A]] of four times that size.
//    The structure is checked when the counter is built, to
//    kMirrorTolerance of each block's 1-norm (the blocks are copies of one
//    assembled matrix, equal to the last bit in practice; a difference below
//    the LDL^T's own rounding cannot change a count it can trust); a set
//    without it is counted on the real form, as count_gyroscopic_below.
// 3. Split families. When the set's DOFs fall in two sets (P, T) that no
//    symmetric term couples and G couples only each other,
//        K-like = [[K_PP, 0], [0, K_TT]],  G = [[0, G_PT], [G_TP, 0]]
//    (n = 0 of a spinning harmonic: L_0 turns u_r into u_theta and back,
//    the meridional and the tangential DOFs, spinning_harmonic.hpp), the
//    diagonal unitary D = diag(I, i I) makes Q real: D^H Q D = A + omega
//    Omega S G with S = diag(-I, I) (D^H i G D has -G_PT and G_TP in its
//    blocks), real symmetric of the set's size where the real form has
//    twice it. Checked as the mirror is; otherwise the real form.
// 2. One symbolic factorisation. Every matrix counted has one nonzero
//    pattern (the union of the terms'), so MUMPS analyses it once and each
//    count is one numeric LDL^T factorisation; the inertia is Sylvester's,
//    as in negative_eigenvalue_count (petsc_algebra.hpp).
#pragma once

#include "assembly/operator_set.hpp"
#include "common/petsc_handle.hpp"

#include <memory>
#include <optional>

namespace coremodal {

class GyroscopicInertia {
public:
    // `families`: where the two families sit in a vector of the set (both
    // given or neither); the mirrored structure is used when it holds, else
    // the split one (3).
    GyroscopicInertia(const OperatorSet& operators, IS first_family = nullptr, IS second_family = nullptr);
    ~GyroscopicInertia();
    GyroscopicInertia(const GyroscopicInertia&) = delete;
    GyroscopicInertia& operator=(const GyroscopicInertia&) = delete;

    // neg Q(omega) at spin speed `spin` (both rad/s), the Hermitian matrix's
    // own count (count_gyroscopic_below's value).
    long negative_count(double spin, double omega) { return negative_count(spin, spin * spin, omega); }
    // The same with the gyroscopic term at `spin` and the centrifugal one at
    // `spin_squared` apart (Q is affine in the two: a convexity argument
    // counts at the corners of a region of them, projected_gyroscopic.hpp).
    long negative_count(double spin, double spin_squared, double omega);
    // neg of the Hermitian combination  stiffness (K + K_sigma) + centrifugal K_Omega
    // + mass M + coupling i G  of the set's terms: negative_count(spin,
    // spin_squared, omega) is {1, spin_squared, -omega^2, omega spin}; the
    // effective stiffness at a speed, K(Omega) + omega_0^2 M, is {1, Omega^2, omega_0^2, 0}.
    struct Combination {
        double stiffness = 0, centrifugal = 0, mass = 0, coupling = 0;
    };
    long negative_count(const Combination& c);
    bool uses_mirrored_families() const;
    bool uses_split_families() const;
    // With mirrored families: one family's blocks (header, 1) on one nonzero
    // pattern, K + K_sigma (S), K_Omega (null without the term), M_S and the
    // coupling Gab of G = [[0, Gab], [-Gab, 0]]; all null otherwise.
    struct FamilyBlocks {
        Mat stiffness = nullptr, centrifugal = nullptr, mass = nullptr, coupling = nullptr;
    };
    FamilyBlocks family_blocks() const;

private:
    struct Pattern;
    std::unique_ptr<Pattern> pattern_;
};

}  // namespace coremodal
