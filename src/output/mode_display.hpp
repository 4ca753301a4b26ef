// What a viewer needs beside a mode shape to show it well: the shape in
// cylindrical components (u_r, u_theta, u_z) and a suggested exaggeration.
// Written into modes.h5 and modes.xdmf (ParaView), and computed the same way
// by the python package (coremodal.display), which tests that both agree.
#pragma once

#include "mesh/mesh.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The suggested warp makes the largest displacement this fraction of the
// model's largest extent (for a roll: its length), so that a bending
// deflection is clearly visible...
inline constexpr double kWarpLengthFraction = 0.10;
// ...but, for every mode that is not a bending or axial mode, at most this
// fraction of its smallest extent (the outer diameter): a shell mode
// (ovalling, breathing) warped to 10 % of the length would move the wall by
// more than the radius and turn the tube inside out, and a torsion mode would
// turn by radians. Bending and axial modes move whole sections, which stay
// round at any scale.
inline constexpr double kWarpDiameterFraction = 0.25;

// Scale factor for ParaView's Warp By Vector for `shape` (n_nodes x 3,
// node-major) on `mesh`, by the two fractions above, given the mode's `type`
// (the classifier's word: "bending", "axial", "ovalling", ...); 0 for a zero
// shape. Extents are those of the node box in x, y and z; an axis with no
// extent (a flat model) is left out of the smallest extent.
double suggested_warp_scale(const Mesh& mesh, const std::vector<double>& shape, const std::string& type);

// A shape in cylindrical components about the z axis (x = y = 0, the
// program's roll axis): one value per node each. A node on the axis takes
// theta = 0, so there u_r = u_x and u_theta = u_y.
struct CylindricalShape {
    std::vector<double> u_r, u_theta, u_z;
};
CylindricalShape cylindrical_components(const Mesh& mesh, const std::vector<double>& shape);

}  // namespace coremodal
