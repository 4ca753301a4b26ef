// From gmsh to coremodal's Mesh: the one place that reads gmsh's mesh data.
#pragma once

#include "mesh/mesh.hpp"

#include <string>

namespace coremodal {

// gmsh must be initialised once per process before any model is built or read.
// The session is quiet: coremodal prints its own progress.
class GmshSession {
public:
    GmshSession();
    ~GmshSession();
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;
};

// Converts the current gmsh model's mesh. Cells come from the physical volumes
// (each becomes a part, in order of group tag), node groups from the physical
// surfaces. Throws InputError (naming `source`) if the mesh has no physical
// volume, first-order or mixed cells, or cells of an unsupported type.
Mesh read_current_gmsh_mesh(const std::string& source);

// Opens a user .msh file and converts it. Throws InputError if the file is
// missing, unreadable or not a mesh gmsh can read.
Mesh read_msh_file(const std::string& path);

// Throws InputError naming the mesh and the missing groups, listing those present.
void require_groups(const Mesh& mesh, const std::vector<std::string>& parts,
                    const std::vector<std::string>& node_groups, const std::string& source,
                    const std::string& needed_by);

}  // namespace coremodal
