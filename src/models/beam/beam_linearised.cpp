// The beam level's eigenvalue change (models/linearised.hpp): the network's
// modes at p and, for the scenes at p(1 ± h), the difference of the assembled
// network matrices on the free DOFs of the scene at p.
#include "models/beam/beam_level.hpp"
#include "models/linearised.hpp"

#include <memory>

namespace coremodal {

Linearised BeamLevel::linearise(const Scene& scene) {
    auto result = std::make_shared<BeamModelResult>(solve_beam_model(scene));
    auto base = std::make_shared<NetworkMatrices>(assemble_network(result->network));
    std::vector<Mode> all;
    for (size_t i = 0; i < result->modes.size(); ++i) {
        const BeamMode& b = result->modes[i];
        Mode mode;
        mode.index = static_cast<int>(i) + 1;
        mode.eigenvalue = b.eigenvalue;
        mode.frequency_hz = b.frequency_hz;
        mode.label = b.label;
        all.push_back(std::move(mode));
    }
    Linearised lin;
    lin.modes = distinct_modes(all);
    lin.eigenvalues = eigenvalues_of(lin.modes, all);
    const std::vector<DistinctMode> modes = lin.modes;
    const std::vector<double> lambdas = lin.eigenvalues;
    lin.delta_lambda = [result, base, modes, lambdas](const Scene& plus,
                                                      const Scene& minus) -> std::optional<std::vector<double>> {
        const NetworkMatrices p = assemble_network(build_beam_network(plus, {}));
        const NetworkMatrices m = assemble_network(build_beam_network(minus, {}));
        if (p.free_dofs != base->free_dofs || m.free_dofs != base->free_dofs) return std::nullopt;
        const Eigen::SparseMatrix<double> dK = p.K - m.K, dM = p.M - m.M;
        std::vector<double> out;
        for (size_t i = 0; i < modes.size(); ++i) {
            const Eigen::VectorXd& shape = result->modes.at(modes[i].index - 1).shape;
            Eigen::VectorXd x(base->free_dofs.size());
            for (size_t r = 0; r < base->free_dofs.size(); ++r) x[r] = shape[base->free_dofs[r]];
            const double xMx = x.dot(base->M * x);
            out.push_back((x.dot(dK * x) - lambdas[i] * x.dot(dM * x)) / xMx);
        }
        return out;
    };
    return lin;
}

}  // namespace coremodal
