#include "modes/rotating_mode.hpp"

#include <complex>

namespace coremodal {

const char* whirl_name(Whirl w) {
    switch (w) {
        case Whirl::forward: return "FW";
        case Whirl::backward: return "BW";
        case Whirl::none: return "";
    }
    return "";
}

double complex_mac(const Eigen::VectorXcd& x, const Eigen::VectorXcd& y) {
    const double xx = x.squaredNorm(), yy = y.squaredNorm();
    if (xx == 0 || yy == 0) return 0;
    return std::norm(x.dot(y)) / (xx * yy);
}

}  // namespace coremodal
