#include "output/mode_display.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coremodal {

double suggested_warp_scale(const Mesh& mesh, const std::vector<double>& shape, const std::string& type) {
    double largest = 0;
    for (size_t a = 0; a + 2 < shape.size(); a += 3)
        largest = std::max(largest, std::hypot(shape[a], shape[a + 1], shape[a + 2]));
    if (largest == 0 || mesh.nodes.empty()) return 0;

    std::array<double, 3> low = mesh.nodes.front(), high = mesh.nodes.front();
    for (const auto& x : mesh.nodes)
        for (int c = 0; c < 3; ++c) {
            low[c] = std::min(low[c], x[c]);
            high[c] = std::max(high[c], x[c]);
        }
    double longest = 0, shortest = std::numeric_limits<double>::infinity();
    for (int c = 0; c < 3; ++c) {
        const double extent = high[c] - low[c];
        if (extent <= 0) continue;
        longest = std::max(longest, extent);
        shortest = std::min(shortest, extent);
    }
    if (longest == 0) return 0;  // a single point: nothing to compare with
    const bool sections_stay_round = type == "bending" || type == "axial";
    const double drawn = sections_stay_round ? kWarpLengthFraction * longest
                                             : std::min(kWarpLengthFraction * longest, kWarpDiameterFraction * shortest);
    return drawn / largest;
}

CylindricalShape cylindrical_components(const Mesh& mesh, const std::vector<double>& shape) {
    CylindricalShape out;
    const size_t n = std::min(mesh.nodes.size(), shape.size() / 3);
    out.u_r.resize(n);
    out.u_theta.resize(n);
    out.u_z.resize(n);
    for (size_t a = 0; a < n; ++a) {
        const double x = mesh.nodes[a][0], y = mesh.nodes[a][1];
        const double r = std::hypot(x, y);
        const double cos_t = r > 0 ? x / r : 1.0, sin_t = r > 0 ? y / r : 0.0;
        const double ux = shape[3 * a], uy = shape[3 * a + 1];
        out.u_r[a] = ux * cos_t + uy * sin_t;
        out.u_theta[a] = -ux * sin_t + uy * cos_t;
        out.u_z[a] = shape[3 * a + 2];
    }
    return out;
}

}  // namespace coremodal
