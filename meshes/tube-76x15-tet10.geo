// A user mesh for coremodal made the way a CAD model usually is: the same
// 76x15 mm core tube, 1.0 m long, as in tube-76x15-clamped.geo, but built from
// OpenCASCADE solids and filled with unstructured 10-node tetrahedra. No clamp
// groups: use it with a free-free case ([supports] type = "free", the default).
//
//   gmsh -3 meshes/tube-76x15-tet10.geo -o meshes/tube-76x15-tet10.msh
//
// coremodal reads the mesh in metres, tube axis along z from z = 0 to z = L,
// and finds the parts and surfaces by their physical-group names
// (meshes/README.md): volume "core"; surfaces "core_inner", "core_outer".

SetFactory("OpenCASCADE");

// ---- Dimensions (metres) ---------------------------------------------------
ri = 0.076 / 2;    // inner radius (76 mm inner diameter)
ro = ri + 0.015;   // outer radius (15 mm wall, 106 mm outer diameter)
L  = 1.0;          // core length
eps = 1e-6;        // tolerance for selecting faces by their bounding boxes

// ---- Solid: outer cylinder minus inner cylinder ----------------------------
Cylinder(1) = {0, 0, 0, 0, 0, L, ro};
Cylinder(2) = {0, 0, 0, 0, 0, L, ri};
tube[] = BooleanDifference { Volume{1}; Delete; } { Volume{2}; Delete; };

// ---- Faces by position -----------------------------------------------------
// The inner cylinder is the only face inside the box of radius ri; the two end
// annuli are flat at z = 0 and z = L; the outer cylinder is what remains.
inner[] = Surface In BoundingBox {-ri - eps, -ri - eps, -eps, ri + eps, ri + eps, L + eps};
ends[]  = Surface In BoundingBox {-ro - eps, -ro - eps, -eps, ro + eps, ro + eps, eps};
ends[] += Surface In BoundingBox {-ro - eps, -ro - eps, L - eps, ro + eps, ro + eps, L + eps};
outer[] = Surface In BoundingBox {-ro - eps, -ro - eps, -eps, ro + eps, ro + eps, L + eps};
outer[] -= inner[];
outer[] -= ends[];

Physical Volume("core") = {tube[]};
Physical Surface("core_inner") = {inner[]};
Physical Surface("core_outer") = {outer[]};

// ---- Mesh -------------------------------------------------------------------
// Unstructured tetrahedra of 18-26 mm (one through the 15 mm wall):
// quadratic tetrahedra bend well even that coarse, and the example stays small
// (6417 nodes, 19 251 DOFs). For ovalling and through-wall shear modes, refine.
Mesh.MeshSizeMin = 0.018;
Mesh.MeshSizeMax = 0.026;
Mesh.ElementOrder = 2;            // coremodal needs quadratic cells: 10-node tetrahedra
Mesh.HighOrderOptimize = 0;       // midside nodes on the true cylinders, no untangling needed
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;
Mesh.RandomSeed = 1;              // reproducible meshing
