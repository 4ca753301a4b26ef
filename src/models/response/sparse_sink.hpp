// Element matrices handed over by an assembly loop's insertion callback
// (assembly/cell_loop.hpp, TermInsert), collected per term as Eigen sparse
// matrices: the forced response's direct solve and static factor work on
// the level's operators without PETSc (eliminated DOFs, -1, dropped).
#pragma once

#include "assembly/cell_loop.hpp"

#include <Eigen/Sparse>

#include <map>
#include <vector>

namespace coremodal {

class SparseSink {
public:
    explicit SparseSink(int n_dofs) : n_(n_dofs) {}

    TermInsert insert() {
        return [this](Term t, const std::vector<int>& dofs, const Eigen::MatrixXd& A) {
            for (size_t i = 0; i < dofs.size(); ++i)
                for (size_t j = 0; j < dofs.size(); ++j)
                    if (dofs[i] >= 0 && dofs[j] >= 0 && A(i, j) != 0)
                        triplets_[t].emplace_back(dofs[i], dofs[j], A(i, j));
        };
    }

    Eigen::SparseMatrix<double> matrix(Term t) const {
        Eigen::SparseMatrix<double> out(n_, n_);
        const auto it = triplets_.find(t);
        if (it != triplets_.end()) out.setFromTriplets(it->second.begin(), it->second.end());
        return out;
    }

private:
    int n_;
    std::map<Term, std::vector<Eigen::Triplet<double>>> triplets_;
};

}  // namespace coremodal
