#include "scene/free_span.hpp"

namespace coremodal {

Scene free_span_scene(const Scene& scene, int n_modes) {
    double li = 0;
    for (const ChuckSpec& c : scene.supports.chucks) li += c.li();
    Scene free = scene;
    free.core.length = scene.core.length - li;
    free.supports = {};
    free.web.reset();  // k compares the roll in its stand with the same roll free: nothing holds it
    free.analysis = {};
    free.analysis.n_modes = n_modes;
    free.mesh.along_per_segment.clear();
    return free;
}

}  // namespace coremodal
