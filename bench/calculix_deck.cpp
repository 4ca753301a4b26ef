// The CalculiX deck of a solid run (issue 19, bench/results/log.md "Against
// CalculiX"): coremodal's own mesh of a case as C3D20 cells, its cylindrically
// orthotropic materials, its rigid clamps and the same number of modes, so
// that `ccx` (Debian calculix-ccx) solves the very problem coremodal's solid
// level solves and the two can be timed side by side
// (bench/calculix_compare.py).
//
//   build/coremodal_calculix_deck CASE.toml OUT.inp [--modes N]
//
// Scenes with chucks are refused: their ties, spring layers and bearings
// have no one-line CalculiX equivalent here. What is written:
// - *NODE (13 significant digits: CalculiX reads at most 20 characters a
//   field), *ELEMENT TYPE=C3D20 per part (gmsh's hex20 edge order mapped to
//   CalculiX's), hex20 meshes only;
// - per part *MATERIAL with *ELASTIC, TYPE=ORTHO: the stiffness C in the
//   cylindrical frame (r, theta, z) = CalculiX's local (1, 2, 3) of an
//   *ORIENTATION SYSTEM=CYLINDRICAL about the z axis (D1111 = C_rr,rr, ...,
//   D1212 = C_rt,rt, D1313 = C_rz,rz, D2323 = C_tz,tz with coremodal's Voigt
//   order (rr, tt, zz, tz, rz, rt)), and *DENSITY;
// - *BOUNDARY: every node of a rigid clamp held in 1-3;
// - *FREQUENCY with the case's [analysis] modes.
#include "common/error.hpp"
#include "material/material.hpp"
#include "mesh/mesh.hpp"
#include "models/part_materials.hpp"
#include "models/solid/solid_level.hpp"
#include "scene/case_file.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <string>

using namespace coremodal;

namespace {

// CalculiX (Abaqus) C3D20 node k is gmsh hex20 node kFromGmsh[k]: the corners
// agree; CalculiX numbers the edges bottom face, top face, then vertical.
constexpr int kFromGmsh[20] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 16, 18, 19, 17, 10, 12, 14, 15};

void write_nodes(std::ostream& out, const Mesh& mesh) {
    out << "*NODE, NSET=NALL\n";
    char line[128];
    for (int n = 0; n < mesh.n_nodes(); ++n) {
        std::snprintf(line, sizeof line, "%d, %.13g, %.13g, %.13g\n", n + 1, mesh.nodes[n][0], mesh.nodes[n][1],
                      mesh.nodes[n][2]);
        out << line;
    }
}

void write_cells(std::ostream& out, const Mesh& mesh) {
    for (size_t p = 0; p < mesh.part_names.size(); ++p) {
        out << "*ELEMENT, TYPE=C3D20, ELSET=E_" << mesh.part_names[p] << "\n";
        for (int c = 0; c < mesh.n_cells(); ++c) {
            if (mesh.cell_part[c] != static_cast<int>(p)) continue;
            out << c + 1;
            for (int k = 0; k < 20; ++k) out << (k == 15 ? ",\n" : ", ") << mesh.cell(c)[kFromGmsh[k]] + 1;
            out << "\n";
        }
    }
}

void write_materials(std::ostream& out, const Mesh& mesh, const std::vector<PartMaterial>& materials) {
    out << "*ORIENTATION, NAME=CYL, SYSTEM=CYLINDRICAL\n0, 0, 0, 0, 0, 1\n";
    char line[512];
    for (size_t p = 0; p < mesh.part_names.size(); ++p) {
        const Matrix6& C = materials[p].C_cylindrical;
        const std::string& name = mesh.part_names[p];
        out << "*MATERIAL, NAME=M_" << name << "\n*ELASTIC, TYPE=ORTHO\n";
        std::snprintf(line, sizeof line, "%.13g, %.13g, %.13g, %.13g, %.13g, %.13g, %.13g, %.13g\n%.13g, 0\n",
                      C(0, 0), C(0, 1), C(1, 1), C(0, 2), C(1, 2), C(2, 2), C(5, 5), C(4, 4), C(3, 3));
        out << line << "*DENSITY\n" << materials[p].density << "\n";
        out << "*SOLID SECTION, ELSET=E_" << name << ", MATERIAL=M_" << name << ", ORIENTATION=CYL\n";
    }
}

void write_clamps(std::ostream& out, const Scene& scene, const Mesh& mesh) {
    std::set<int> held;
    for (const ClampSpec& c : scene.supports.clamps)
        for (int n : mesh.node_groups.at("clamp_" + c.name)) held.insert(n);
    if (held.empty()) return;
    out << "*NSET, NSET=CLAMPED\n";
    int k = 0;
    for (int n : held) out << n + 1 << (++k % 16 == 0 ? ",\n" : ", ");
    out << "\n*BOUNDARY\nCLAMPED, 1, 3\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: coremodal_calculix_deck CASE.toml OUT.inp [--modes N]\n";
        return 2;
    }
    try {
        Scene scene = parse_case_file(argv[1]);
        if (argc == 5 && std::string(argv[3]) == "--modes") scene.analysis.n_modes = std::atoi(argv[4]);
        if (!scene.supports.chucks.empty()) throw InputError(scene.source_file + ": chucks have no CalculiX deck here");
        const Mesh mesh = make_solid_mesh(scene);
        if (mesh.cell_type != CellType::hex20) throw InputError("only hex20 meshes are written");
        const std::vector<PartMaterial> materials = part_materials(scene, mesh.part_names, scene.source_file);
        std::ofstream out(argv[2]);
        out << "** " << scene.name << ": coremodal's solid mesh, " << mesh.n_nodes() << " nodes, " << mesh.n_cells()
            << " C3D20 cells (bench/calculix_deck.cpp)\n";
        write_nodes(out, mesh);
        write_cells(out, mesh);
        write_materials(out, mesh, materials);
        write_clamps(out, scene, mesh);
        out << "*STEP\n*FREQUENCY\n" << scene.analysis.n_modes << "\n*END STEP\n";
        if (!out) throw InputError(std::string(argv[2]) + ": could not write");
        std::cout << mesh.n_nodes() << " nodes, " << mesh.n_cells() << " cells\n";
    } catch (const std::exception& e) {
        std::cerr << "coremodal_calculix_deck: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
