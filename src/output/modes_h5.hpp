// modes.h5: the complete results of a run (mesh, case, modes, shapes) in one
// HDF5 file, read by the python package (python/coremodal) and, through
// modes.xdmf, by ParaView. The layout is documented in docs/reference/results.md
// ("modes.h5 and modes.xdmf"); change it only together with
// modes_h5_schema_version and the python reader.
#pragma once

#include "mesh/mesh.hpp"
#include "modes/mode_set.hpp"

#include <string>
#include <vector>

namespace coremodal {

// Version of the file layout. Readers reject files with a newer version.
// Adding datasets keeps the version (docs/reference/results.md, "Compatibility"): the
// cylindrical components and warp scales came without a change.
inline constexpr int modes_h5_schema_version = 1;

// gzip level of the compressed datasets: level 4 makes case 07's file
// about a third of its raw size (29.5 -> 10 MB of the
// same data) at a small fraction of the run's time; levels 6-9 gain little more.
inline constexpr int kModesH5DeflateLevel = 4;

// Dataset holding the shape of mode number `number` (1-based position in the
// mode list): "/modes/shapes/mode_0001".
std::string modes_h5_shape_dataset(int number);

// The cylindrical components of mode `number` for ParaView (float32, one
// value per node): component "u_r", "u_theta" or "u_z" -> "/modes/u_r/mode_0001".
std::string modes_h5_component_dataset(const std::string& component, int number);

// True when this HDF5 library can write gzip (deflate) and shuffle filters;
// without them write_modes_h5 writes every dataset uncompressed.
bool modes_h5_compression_available();

// Writes modes.h5 with the serial HDF5 API; call on one rank only (the rank
// holding the mode shapes). Numeric datasets of more than a few thousand
// values are chunked and gzip-compressed (shuffle + deflate) where the library
// can; readers (h5py, ParaView) decompress them transparently. `case_json` is the resolved case as a JSON object,
// stored verbatim; `case_name` becomes the case_name root attribute. Each mode's shape must hold 3 * mesh.n_nodes()
// values. Overwrites an existing file. Throws std::runtime_error naming the
// path on any HDF5 failure or inconsistent input.
void write_modes_h5(const std::string& path, const Mesh& mesh, const std::vector<Mode>& modes,
                    const std::string& case_name, const std::string& case_json,
                    const std::string& program_version);

}  // namespace coremodal
