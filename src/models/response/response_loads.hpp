// The loads of [excitation] on a roll's beam network, per excitation order
// (effects/excitation.hpp states and derives each one). A load turning at
// k Omega is the complex network vector f(Omega) = constant + Omega^2
// per_spin_squared (Omega in rad/s): unbalance grows with Omega^2, the bow's
// and the ovality's stiffness loads do not.
#pragma once

#include "models/response/lateral_response.hpp"
#include "beam/beam_network.hpp"
#include "scene/response_spec.hpp"
#include "scene/scene.hpp"

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace coremodal {

struct OrderLoad {
    int order = 1;
    Eigen::VectorXcd constant, per_spin_squared;  // per network DOF
    std::vector<std::string> sources;             // the effects' names
    Eigen::VectorXcd at(double omega_spin) const { return constant + omega_spin * omega_spin * per_spin_squared; }
};

// Adds f(Omega) = constant + Omega^2 per_spin2 to the order's load (a new
// entry for a new order), with the effect's name among its sources.
void add_order_load(std::vector<OrderLoad>& orders, int order, const Eigen::VectorXcd& constant,
                    const Eigen::VectorXcd& per_spin2, const std::string& source);

// A point on the core (beam 0 of a roll's network): the three nodes of the
// element holding z and their shape functions there.
struct CorePoint {
    int nodes[3] = {0, 0, 0};
    double shape[3] = {0, 0, 0};
};
CorePoint core_point(const BeamNetwork& network, double z);

struct ResponseLoads {
    std::vector<OrderLoad> orders;  // ascending order; only orders with a load
    Eigen::VectorXd sag;            // static sag under gravity per network DOF (x-z plane), m; empty without gravity
    double ovality_split = 0;       // eps of effects/excitation.hpp (0 without ovality)
    std::vector<std::string> assumptions;
};

// first_bending_shape: the first bending mode at rest per network DOF
// (needed for bow_shape = "first_mode" only).
ResponseLoads build_response_loads(const Scene& scene, const ExcitationSpec& excitation, const BeamNetwork& network,
                                   const LateralResponse& lateral, const Eigen::VectorXd& first_bending_shape);

}  // namespace coremodal
