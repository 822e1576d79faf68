// A compact body for the real-time benchmarks (scripts/bench/fem-rate): the ellipsoid x^2/2^2 + y^2/1.2^2 +
// z^2/1^2 <= 1 cut by the planes x = -1.6 (clamped: -dirichlet x=-1.6) and x = 1.6 (the loaded end face).
// Made by scripts/make-compact-meshes (gmsh 4.8, Debian): -setnumber h 0.18 gives ellipsoid_5k.msh,
// -setnumber h 0.108 ellipsoid_20k.msh (first-order tetrahedra, MSH 4.1 ASCII).
SetFactory("OpenCASCADE");
DefineConstant[h = 0.26];
Sphere(1) = {0, 0, 0, 1};
Dilate {{0, 0, 0}, {2, 1.2, 1}} { Volume{1}; }
Box(2) = {-1.6, -2, -2, 3.2, 4, 4};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
Mesh.Algorithm3D = 1;
Mesh.Optimize = 1;
Mesh.MshFileVersion = 4.1;
Physical Volume("body") = {3};
