#include "assembly/operator_set.hpp"

#include "common/error.hpp"

namespace coremodal {

Mat OperatorSet::operator[](Term term) const {
    const auto it = matrices.find(term);
    COREMODAL_ASSERT(it != matrices.end());
    return it->second.get();
}

std::vector<Term> OperatorSet::terms() const {
    std::vector<Term> present;
    for (Term t : kAllTerms)
        if (has(t)) present.push_back(t);
    return present;
}

bool OperatorSet::quadratic() const {
    for (Term t : terms())
        if (makes_problem_quadratic(t)) return true;
    return false;
}

EffectiveStiffness::EffectiveStiffness(const OperatorSet& ops, double spin) : matrix_(ops.K()) {
    const bool prestress = ops.has(Term::geometric_stiffness), centrifugal = ops.has(Term::centrifugal) && spin != 0;
    if (!prestress && !centrifugal) return;
    COREMODAL_PETSC(MatDuplicate(ops.K(), MAT_COPY_VALUES, sum_.out()));
    if (prestress) COREMODAL_PETSC(MatAXPY(sum_, 1.0, ops[Term::geometric_stiffness], DIFFERENT_NONZERO_PATTERN));
    if (centrifugal) COREMODAL_PETSC(MatAXPY(sum_, spin * spin, ops[Term::centrifugal], DIFFERENT_NONZERO_PATTERN));
    COREMODAL_PETSC(MatSetOption(sum_, MAT_SYMMETRIC, PETSC_TRUE));
    matrix_ = sum_.get();
}

}  // namespace coremodal
