// modes.h5: the complete results of a run (mesh, case, modes, shapes) in one
// HDF5 file, read by the python package (python/coremodal) and, through
// modes.xdmf, by ParaView. The layout is documented in docs/results.md
// ("modes.h5 and modes.xdmf"); change it only together with
// modes_h5_schema_version and the python reader.
#pragma once

#include "mesh/mesh.hpp"
#include "modes/mode_set.hpp"

#include <string>
#include <vector>

namespace coremodal {

// Version of the file layout. Readers reject files with a newer version.
inline constexpr int modes_h5_schema_version = 1;

// Dataset holding the shape of mode number `number` (1-based position in the
// mode list): "/modes/shapes/mode_0001".
std::string modes_h5_shape_dataset(int number);

// Writes modes.h5 with the serial HDF5 API; call on one rank only (the rank
// holding the mode shapes). `case_json` is the resolved case as a JSON object,
// stored verbatim; `case_name` becomes the case_name root attribute. Each mode's shape must hold 3 * mesh.n_nodes()
// values. Overwrites an existing file. Throws std::runtime_error naming the
// path on any HDF5 failure or inconsistent input.
void write_modes_h5(const std::string& path, const Mesh& mesh, const std::vector<Mode>& modes,
                    const std::string& case_name, const std::string& case_json,
                    const std::string& program_version);

}  // namespace coremodal
