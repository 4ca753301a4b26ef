// gmsh -> Mesh: the shipped user meshes (meshes/*.msh), the generated tube
// model, and every way a mesh file can be refused; then a whole solve on the
// unstructured tet10 user mesh against the generated hex20 mesh.
#include "mesh/gmsh_mesh.hpp"

#include "common/error.hpp"
#include "element/element.hpp"
#include "geometry/tube_model.hpp"
#include "geometry/tube_section.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>
#include <gmsh.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace coremodal;
using namespace coremodal::testing;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

// The shipped examples: a 76x15 mm core, 1.0 m long (meshes/README.md).
constexpr double kRi = 0.038, kRo = 0.053, kLength = 1.0, kClamp = 0.070;

std::string shipped(const std::string& name) { return std::string(COREMODAL_SOURCE_DIR) + "/meshes/" + name; }

struct TempDir {
    fs::path path;
    TempDir() {
        static int counter = 0;
        path = fs::temp_directory_path() /
               ("coremodal_test_gmsh_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

double mesh_volume(const Mesh& mesh) {
    double v = 0;
    CellCoords x(mesh.nodes_per_cell(), 3);
    for (int c = 0; c < mesh.n_cells(); ++c) {
        for (int a = 0; a < mesh.nodes_per_cell(); ++a)
            for (int k = 0; k < 3; ++k) x(a, k) = mesh.nodes[mesh.cell(c)[a]][k];
        v += element_volume(mesh.cell_type, x);
    }
    return v;
}

double radius(const std::array<double, 3>& x) { return std::hypot(x[0], x[1]); }

// Area inside n quadratic arcs through the points of a circle of radius r at
// angles 0, a, 2a, ... (a = pi / n, the arcs' half-angle): each sector is the
// triangle to the chord, r^2 sin a cos a, plus the parabolic segment, 2/3 x
// chord x sagitta = 4/3 r^2 sin a (1 - cos a). This is the exact area a
// quadratic cell encloses when its edge midside node lies on the circle at
// the middle angle; it falls short of pi r^2 by a^4 / 30 relatively.
double quadratic_polygon_area(double r, int n) {
    const double a = M_PI / n;
    return n * r * r * std::sin(a) * (std::cos(a) + 4.0 / 3.0 * (1 - std::cos(a)));
}

// Nodes of the group that are not at r = r0 or not inside [z0, z1] (1 um).
int nodes_off(const Mesh& mesh, const std::string& group, double r0, double z0, double z1) {
    int off = 0;
    for (int n : mesh.node_groups.at(group)) {
        const auto& x = mesh.nodes[n];
        if (std::abs(radius(x) - r0) > 1e-9 || x[2] < z0 - 1e-9 || x[2] > z1 + 1e-9) ++off;
    }
    return off;
}

}  // namespace

TEST_CASE("The shipped hex20 user mesh reads as 20-node hexahedra with the core and clamp groups",
          "[mesh][gmsh]") {
    GmshSession gmsh;
    const Mesh mesh = read_msh_file(shipped("tube-76x15-clamped.msh"));
    CHECK(mesh.cell_type == CellType::hex20);
    CHECK(mesh.part_names == std::vector<std::string>{"core"});
    // 2 through the wall x 16 around x 24 along (meshes/tube-76x15-clamped.geo).
    CHECK(mesh.n_cells() == 2 * 16 * 24);
    CHECK(std::all_of(mesh.cell_part.begin(), mesh.cell_part.end(), [](int p) { return p == 0; }));
    for (const char* g : {"core_inner", "core_outer", "clamp_left", "clamp_right"}) {
        INFO(g);
        REQUIRE(mesh.node_groups.count(g) == 1);
        CHECK(!mesh.node_groups.at(g).empty());
    }

    SECTION("its node groups lie on the surfaces they name") {
        CHECK(nodes_off(mesh, "core_inner", kRi, 0, kLength) == 0);
        CHECK(nodes_off(mesh, "core_outer", kRo, 0, kLength) == 0);
        CHECK(nodes_off(mesh, "clamp_left", kRi, 0, kClamp) == 0);
        CHECK(nodes_off(mesh, "clamp_right", kRi, kLength - kClamp, kLength) == 0);
        // A clamp zone of 2 elements along: 5 node rings (3 corner, 2 midside
        // levels), 32 nodes per corner ring (16 corners + 16 midsides), 16 per
        // midside ring.
        CHECK(mesh.node_groups.at("clamp_left").size() == 3 * 32 + 2 * 16);
        CHECK(mesh.node_groups.at("clamp_right").size() == 3 * 32 + 2 * 16);
    }

    SECTION("its volume is the annulus bounded by quadratic arcs, to rounding") {
        // The midside nodes lie on the cylinders at mid-angle and the axial
        // edges are straight, so the cells fill exactly the annulus between
        // two 16-sided quadratic polygons (3x3x3 Gauss integrates det J, of
        // degree 5 per direction, exactly). What remains is the 16-digit
        // coordinates of the .msh file: 1e-12 relative is generous.
        const double exact = (quadratic_polygon_area(kRo, 16) - quadratic_polygon_area(kRi, 16)) * kLength;
        CHECK(mesh_volume(mesh) == Approx(exact).epsilon(1e-12));
        // ... which is the true annulus less a^4/30, a = pi/16 (5e-5).
        const double annulus = M_PI * (kRo * kRo - kRi * kRi) * kLength;
        CHECK(mesh_volume(mesh) == Approx(annulus * (1 - std::pow(M_PI / 16, 4) / 30)).epsilon(1e-6));
    }

    SECTION("every node belongs to a cell (the seam is merged)") {
        // An unmerged seam leaves duplicate nodes: 2 x 3 x 25 corners + midsides.
        // The structured count is 3 x 16 x 25 corners + 2 x 16 x 25 radial,
        // 3 x 16 x 25 circumferential and 3 x 16 x 24 axial midside nodes.
        CHECK(mesh.n_nodes() == 3 * 16 * 25 + 2 * 16 * 25 + 3 * 16 * 25 + 3 * 16 * 24);
    }
}

TEST_CASE("The shipped tet10 user mesh reads as 10-node tetrahedra filling the annulus", "[mesh][gmsh]") {
    GmshSession gmsh;
    const Mesh mesh = read_msh_file(shipped("tube-76x15-tet10.msh"));
    CHECK(mesh.cell_type == CellType::tet10);
    CHECK(mesh.part_names == std::vector<std::string>{"core"});
    CHECK(3 * mesh.n_nodes() < 40000);
    REQUIRE(mesh.node_groups.count("core_inner") == 1);
    REQUIRE(mesh.node_groups.count("core_outer") == 1);
    CHECK(mesh.node_groups.count("clamp_left") == 0);
    CHECK(nodes_off(mesh, "core_inner", kRi, 0, kLength) == 0);
    CHECK(nodes_off(mesh, "core_outer", kRo, 0, kLength) == 0);

    // Quadratic triangles on a cylinder of radius r cut off about a^4/30 of
    // the disc area, a = h / (2 r) the half-angle an edge of length h
    // subtends. The outer cylinder loses volume, the inner one gains it (the
    // hole shrinks): net (ri^2 d_i - ro^2 d_o) / (ro^2 - ri^2). With edges of
    // MeshSizeMax = 26 mm that is 2.4e-4 (measured: 1.2e-4, edges ~22 mm);
    // flat ends and straight interior faces are exact. 5e-4 leaves room for
    // the mesher's longer edges.
    const double annulus = M_PI * (kRo * kRo - kRi * kRi) * kLength;
    CHECK(mesh_volume(mesh) == Approx(annulus).epsilon(5e-4));
}

TEST_CASE("The generated tube model carries the physical groups and clamps on the inner surface",
          "[mesh][gmsh]") {
    Scene scene = clamp_both_ends(steel_tube(0.106, 0.076, 0.5, 1, 8, 6), 0.05);
    scene.supports.clamps[0] = {"left", 0.02, 0.07};  // a zone away from the end
    GmshSession gmsh;
    build_tube_model(make_tube_section(scene), scene.supports.clamps, "hex20");
    const Mesh mesh = read_current_gmsh_mesh("generated mesh");
    CHECK(mesh.cell_type == CellType::hex20);
    CHECK(mesh.part_names == std::vector<std::string>{"core"});
    for (const char* g : {"core_inner", "core_outer", "clamp_left", "clamp_right"}) {
        INFO(g);
        REQUIRE(mesh.node_groups.count(g) == 1);
        CHECK(!mesh.node_groups.at(g).empty());
    }
    CHECK(nodes_off(mesh, "clamp_left", 0.038, 0.02, 0.07) == 0);
    CHECK(nodes_off(mesh, "clamp_right", 0.038, 0.45, 0.5) == 0);
    CHECK(nodes_off(mesh, "core_inner", 0.038, 0, 0.5) == 0);
    CHECK(nodes_off(mesh, "core_outer", 0.053, 0, 0.5) == 0);

    // The clamp groups hold every inner-surface node of their zone, the edges included.
    int inner_in_left_zone = 0;
    for (int n : mesh.node_groups.at("core_inner"))
        if (mesh.nodes[n][2] >= 0.02 - 1e-9 && mesh.nodes[n][2] <= 0.07 + 1e-9) ++inner_in_left_zone;
    CHECK(int(mesh.node_groups.at("clamp_left").size()) == inner_in_left_zone);
    CHECK(mesh_volume(mesh) ==
          Approx((quadratic_polygon_area(0.053, 8) - quadratic_polygon_area(0.038, 8)) * 0.5).epsilon(1e-12));
}

TEST_CASE("A mesh of first-order cells is refused, naming the cell types needed", "[mesh][gmsh]") {
    TempDir dir;
    {
        std::ofstream geo(dir.file("linear.geo"));
        geo << "SetFactory(\"OpenCASCADE\");\n"
               "Box(1) = {0, 0, 0, 0.1, 0.1, 0.1};\n"
               "Physical Volume(\"core\") = {1};\n"
               "Mesh.MeshSizeMax = 0.05;\n"
               "Mesh.ElementOrder = 1;\n";
    }
    GmshSession gmsh;
    gmsh::open(dir.file("linear.geo"));
    gmsh::model::mesh::generate(3);
    gmsh::write(dir.file("linear.msh"));
    const std::string path = dir.file("linear.msh");
    REQUIRE_THROWS_AS(read_msh_file(path), InputError);
    REQUIRE_THROWS_WITH(read_msh_file(path), Contains(path) && Contains("Tetrahedron 4") &&
                                                 Contains("20- or 27-node hexahedra or 10-node tetrahedra") &&
                                                 Contains("Mesh.ElementOrder = 2"));
}

TEST_CASE("A missing or unreadable mesh file is an input error naming the file", "[mesh][gmsh]") {
    TempDir dir;
    GmshSession gmsh;

    SECTION("a file that does not exist") {
        const std::string path = dir.file("nowhere.msh");
        REQUIRE_THROWS_AS(read_msh_file(path), InputError);
        REQUIRE_THROWS_WITH(read_msh_file(path), Contains(path) && Contains("does not exist"));
    }

    SECTION("a file that is not a mesh") {
        const std::string path = dir.file("garbage.msh");
        std::ofstream(path) << "this is not a mesh\n1 2 3\n$Nodes\nnonsense\n";
        REQUIRE_THROWS_AS(read_msh_file(path), InputError);
        // gmsh's API throws its parser's message as a std::string the first
        // time; opened again, it leaves an empty model. Both name the file.
        REQUIRE_THROWS_WITH(read_msh_file(path), Contains(path) && Contains("mesh"));
    }

    SECTION("an empty file") {
        const std::string path = dir.file("empty.msh");
        std::ofstream{path};
        // gmsh opens it without complaint and leaves an empty model.
        REQUIRE_THROWS_AS(read_msh_file(path), InputError);
        REQUIRE_THROWS_WITH(read_msh_file(path), Contains(path) && Contains("no mesh"));
    }
}

TEST_CASE("require_groups names the missing group and lists those present", "[mesh]") {
    Mesh mesh;
    mesh.part_names = {"core"};
    mesh.node_groups["core_inner"] = {};
    mesh.node_groups["clamp_left"] = {};

    SECTION("a missing physical surface") {
        REQUIRE_THROWS_AS(require_groups(mesh, {"core"}, {"clamp_left", "clamp_right"}, "x.msh", "the clamps"),
                          InputError);
        REQUIRE_THROWS_WITH(require_groups(mesh, {"core"}, {"clamp_left", "clamp_right"}, "x.msh", "the clamps"),
                            Contains("x.msh") && Contains("'clamp_right'") && Contains("the clamps") &&
                                Contains("'clamp_left', 'core_inner'"));
    }

    SECTION("a missing physical volume") {
        REQUIRE_THROWS_WITH(require_groups(mesh, {"core", "rest_paper"}, {}, "x.msh", "[rest_paper]"),
                            Contains("x.msh") && Contains("'rest_paper'") && Contains("physical volumes found: 'core'"));
    }

    SECTION("nothing missing") { CHECK_NOTHROW(require_groups(mesh, {"core"}, {"clamp_left"}, "x.msh", "x")); }
}

TEST_CASE("The free-free tet10 user mesh bends like the generated hex20 mesh of the same tube",
          "[long][mesh][gmsh][solve]") {
    // Steel: the comparison is between meshes, the material only sets the scale.
    Scene generated = steel_tube(0.106, 0.076, kLength, 2, 16, 24, 8);  // 6 rigid + a bending pair
    Scene user = generated;
    user.mesh.file = shipped("tube-76x15-tet10.msh");
    const RunReport hex = solve_quietly(generated);
    const RunReport tet = solve_quietly(user);
    REQUIRE(tet.model.element == "tet10");
    CHECK(tet.modes.verification.complete);

    int rigid = 0;
    for (const auto& m : tet.modes.modes) rigid += m.label.type == "rigid";
    CHECK(rigid == 6);
    CHECK(tet.modes.modes.at(6).label.type != "rigid");

    // Both meshes resolve the first bending mode (two half-waves over 1 m:
    // 24 quadratic hexahedra, or tetrahedra of ~22 mm, along) far better than
    // 1%; what differs is the section (16 quadratic arcs against ~22 mm curved
    // triangles: area and inertia differ by ~1e-4) and the tetrahedra's
    // stiffer shear with one cell through the wall. Measured: 1e-4 apart.
    const double f_hex = nth_of_type(hex, "bending").frequency_hz;
    const double f_tet = nth_of_type(tet, "bending").frequency_hz;
    INFO("hex20 " << f_hex << " Hz, tet10 " << f_tet << " Hz");
    CHECK(f_tet == Approx(f_hex).epsilon(0.01));
}
