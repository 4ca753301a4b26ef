#include "output/beam_shapes.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace coremodal {
namespace {

// The beam each node belongs to (the core for a node a bonded chuck shares).
std::vector<std::string> node_beams(const BeamNetwork& net) {
    std::vector<std::string> name(net.n_nodes(), "frame");
    for (auto beam = net.beams.rbegin(); beam != net.beams.rend(); ++beam)
        for (int n : beam->nodes) name[n] = beam->name;
    return name;
}

}  // namespace

void write_beam_shapes_csv(const std::string& path, const BeamModelResult& beam) {
    std::ofstream f(path);
    f << "mode,node,beam,z_m,ux,uy,uz,rx,ry,rz\n";
    f.precision(10);
    const std::vector<std::string> beams = node_beams(beam.network);
    for (size_t i = 0; i < beam.modes.size(); ++i)
        for (int n = 0; n < beam.network.n_nodes(); ++n) {
            f << i + 1 << ',' << n << ',' << beams[n] << ',' << beam.network.node_z[n];
            for (int d = 0; d < beam_dof::per_node; ++d) f << ',' << beam.modes[i].shape(beam_dof::per_node * n + d);
            f << '\n';
        }
    f.close();  // checked: a full disk fails at close
    if (!f) throw std::runtime_error("cannot write " + path + " (" + std::strerror(errno) + ")");
}

}  // namespace coremodal
