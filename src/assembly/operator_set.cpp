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

}  // namespace coremodal
