// A user mesh for coremodal: a 76x15 mm paperboard core tube, 1.0 m long,
// clamped on its inner surface over the first and last 70 mm.
//
//   gmsh -3 meshes/tube-76x15-clamped.geo -o meshes/tube-76x15-clamped.msh
//
// Used by cases/04-user-mesh-76x15.toml. coremodal reads the mesh in metres
// with the tube axis along z from z = 0 (left end) to z = L (right end), and
// finds the parts and surfaces by their physical-group names (meshes/README.md):
//   Physical Volume  "core"                       the cells of the core
//   Physical Surface "core_inner", "core_outer"   the inner and outer cylinders
//   Physical Surface "clamp_left", "clamp_right"  inner surface inside each clamp
// Every node of a clamp group is fixed (all three displacements).
//
// How it is built: the r-z section of the wall (a rectangle from ri to ro,
// split at the clamp edges) is meshed with structured quadrangles and revolved
// about the z axis in four quarter turns (the built-in kernel revolves by less
// than pi per extrusion), then the seam is merged. The result is a structured
// mesh of hexahedra; Mesh.ElementOrder = 2 with SecondOrderIncomplete = 1 makes
// them 20-node serendipity hexahedra, the midside nodes placed on the true
// cylinders.

// ---- Dimensions (metres) ---------------------------------------------------
ri = 0.076 / 2;    // inner radius (76 mm inner diameter)
ro = ri + 0.015;   // outer radius (15 mm wall, 106 mm outer diameter)
L  = 1.0;          // core length
Lc = 0.070;        // clamp length at each end (chuck supporting length)

// ---- Mesh density ----------------------------------------------------------
// Coarse on purpose (a small example, about 13 000 DOFs): 2 elements through the
// wall, 16 around, 2 + 20 + 2 along. Use at least 2-3 quadratic elements
// through the wall (docs/case-files.md); refine `around` and `along_free` for
// accuracy.
through_wall = 2;
around       = 16;     // multiple of 4: one quarter turn gets around / 4
along_clamp  = 2;      // elements along each clamp zone
along_free   = 20;     // elements along the free span between the clamps

// ---- The r-z section, in the plane y = 0 (x = r) ---------------------------
// Points at the two radii and the four axial breakpoints 0, Lc, L - Lc, L.
zs[] = {0, Lc, L - Lc, L};
nz[] = {along_clamp, along_free, along_clamp};
For j In {0 : 3}
  p_in[j]  = newp; Point(p_in[j])  = {ri, 0, zs[j]};
  p_out[j] = newp; Point(p_out[j]) = {ro, 0, zs[j]};
  radial[j] = newl; Line(radial[j]) = {p_in[j], p_out[j]};
  Transfinite Curve{radial[j]} = through_wall + 1;
EndFor
For j In {0 : 2}
  inner[j] = newl; Line(inner[j]) = {p_in[j], p_in[j + 1]};
  outer[j] = newl; Line(outer[j]) = {p_out[j], p_out[j + 1]};
  Transfinite Curve{inner[j], outer[j]} = nz[j] + 1;
  // The loop's order fixes the order of the lateral faces the revolution
  // returns: [2 + 0] from radial[j], [2 + 1] outer, [2 + 2] radial[j+1], [2 + 3] inner.
  loop = newll; Curve Loop(loop) = {radial[j], outer[j], -radial[j + 1], -inner[j]};
  section[j] = news; Plane Surface(section[j]) = {loop};
  Transfinite Surface{section[j]};
  Recombine Surface{section[j]};
EndFor

// ---- Revolve: four quarter turns per axial segment -------------------------
// ex[] = Extrude{...}{Surface{s}; ...} returns {top face, volume, lateral faces}.
volumes[] = {};
inner_faces[] = {};   // per segment j: inner_faces of segment j collected below
outer_faces[] = {};
clamp_left_faces[] = {};
clamp_right_faces[] = {};
For j In {0 : 2}
  face = section[j];
  For q In {1 : 4}
    ex[] = Extrude { {0, 0, 1}, {0, 0, 0}, Pi / 2 } {
      Surface{face}; Layers{around / 4}; Recombine;
    };
    face = ex[0];
    volumes[] += ex[1];
    outer_faces[] += ex[3];
    inner_faces[] += ex[5];
    If (j == 0)
      clamp_left_faces[] += ex[5];
    EndIf
    If (j == 2)
      clamp_right_faces[] += ex[5];
    EndIf
  EndFor
EndFor

// The last quarter ends on the starting section: merge the coincident points,
// curves and faces so that the mesh is conforming across the seam.
Coherence;

// ---- Physical groups: the names coremodal looks for -------------------------
Physical Volume("core") = {volumes[]};
Physical Surface("core_inner") = {inner_faces[]};
Physical Surface("core_outer") = {outer_faces[]};
Physical Surface("clamp_left") = {clamp_left_faces[]};
Physical Surface("clamp_right") = {clamp_right_faces[]};

// ---- Quadratic cells --------------------------------------------------------
Mesh.ElementOrder = 2;            // coremodal needs quadratic cells
Mesh.SecondOrderIncomplete = 1;   // 20-node serendipity hexahedra (0: 27-node)
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;                  // ASCII, readable and diff-able
