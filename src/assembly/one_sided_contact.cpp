#include "assembly/one_sided_contact.hpp"

#include "common/error.hpp"

#include <cmath>

namespace coremodal {

double interpenetration(const ContactFace& f, const ContactPoint& q, double clearance, const NodeDisplacement& u) {
    Eigen::Vector3d du = Eigen::Vector3d::Zero();
    for (size_t a = 0; a < f.core_nodes.size(); ++a) du += q.N[a] * (u(f.core_nodes[a]) - u(f.chuck_nodes[a]));
    return -clearance - q.normal().dot(du);
}

CouplingElement contact_coupling(const ContactFace& f, const std::function<Eigen::Matrix3d(size_t q)>& D) {
    const int n = static_cast<int>(f.core_nodes.size());
    CouplingElement e;
    e.nodes = f.core_nodes;
    e.nodes.insert(e.nodes.end(), f.chuck_nodes.begin(), f.chuck_nodes.end());
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    for (size_t q = 0; q < f.points.size(); ++q) {
        const ContactPoint& p = f.points[q];
        const Eigen::Matrix3d Dq = D(q);
        if (Dq.isZero(0)) continue;
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) K.block<3, 3>(3 * a, 3 * b) += p.area_weight * p.N[a] * p.N[b] * Dq;
    }
    e.terms.push_back({OneSidedContact::kTerm, spring_between(K)});
    return e;
}

Eigen::VectorXd contact_load(const ContactFace& f, const std::function<double(size_t q)>& t) {
    const int n = static_cast<int>(f.core_nodes.size());
    Eigen::VectorXd load = Eigen::VectorXd::Zero(6 * n);
    for (size_t q = 0; q < f.points.size(); ++q) {
        const ContactPoint& p = f.points[q];
        const double tq = t(q);
        if (tq == 0) continue;
        const Eigen::Vector3d force = tq * p.area_weight * p.normal();
        for (int a = 0; a < n; ++a) {
            load.segment<3>(3 * a) += p.N[a] * force;
            load.segment<3>(3 * (n + a)) -= p.N[a] * force;
        }
    }
    return load;
}

std::vector<CouplingElement> linearised_contact(const std::vector<ContactFace>& faces,
                                                const std::vector<ContactPointState>& state,
                                                const SupportEffects& effects) {
    std::vector<CouplingElement> out;
    size_t k = 0;
    for (const ContactFace& f : faces) {
        const OneSidedContact& contact = *effects.chucks.at(f.chuck).one_sided;
        const size_t first = k;
        out.push_back(contact_coupling(f, [&](size_t q) -> Eigen::Matrix3d {
            const ContactPointState& s = state.at(first + q);
            if (!s.closed()) return Eigen::Matrix3d::Zero();
            const Eigen::Vector3d& x = f.points[q].x;
            return contact.linearised(s.p).per_area(std::atan2(x[1], x[0]));
        }));
        k += f.points.size();
    }
    COREMODAL_ASSERT(k == state.size());
    return out;
}

}  // namespace coremodal
