// The assembled operators of one independent eigenproblem: one PETSc matrix
// per named term (element/term.hpp). Stiffness and mass are always present;
// an effect adds its term only when the scene names it. The eigensolver reads
// the set and chooses the problem type from the terms it finds: K x = lambda
// M x while only (geometric) stiffness and mass are present, a quadratic
// problem once a gyroscopic or damping term is.
#pragma once

#include "common/petsc_handle.hpp"
#include "element/term.hpp"

#include <map>
#include <vector>

namespace coremodal {

struct OperatorSet {
    std::map<Term, PetscMatrix> matrices;
    double model_mass = 0;  // kg: sum of rho V over the cells plus lumped masses (all ranks)

    bool has(Term term) const { return matrices.count(term) > 0; }
    // The matrix of `term`; the term must be present (an internal error otherwise).
    Mat operator[](Term term) const;
    Mat K() const { return (*this)[Term::stiffness]; }
    Mat M() const { return (*this)[Term::mass]; }
    // Present terms in the order of kAllTerms (for the summary's list).
    std::vector<Term> terms() const;
    // A gyroscopic or damping term is present.
    bool quadratic() const;
};

// The stiffness every eigenproblem of the set sees at spin speed `spin`
// (rad/s): K, plus the geometric stiffness of a prestress and spin^2 times
// the centrifugal term when the set has them (a copy then; K itself
// otherwise). At rest (spin = 0) the centrifugal term drops out.
class EffectiveStiffness {
public:
    explicit EffectiveStiffness(const OperatorSet& ops, double spin = 0);
    Mat get() const { return matrix_; }

private:
    PetscMatrix sum_;
    Mat matrix_;
};

}  // namespace coremodal
