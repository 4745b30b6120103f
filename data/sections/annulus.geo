// Annular cylinder: the liquid between a coaxial rod of radius Ri and a cylinder of radius Ro, height H, centre at
// the origin (a projectile's payload around its burster tube). Meridian half-section in the (x = r, y = z) plane;
// the section nowhere touches r = 0, so it has no "axis" group: its wall is its whole boundary. The m = 1 modes are
// separable (Bessel J1 and Y1): docs/physics.md, "Annular cylinder". The mesh size and order come from cavity-modes'
// options (lc below only matters when gmsh meshes this file on its own).
Ri = 0.3;
Ro = 1.0;
H = 2.0;
lc = 0.1;

Point(1) = {Ri, -H/2, 0, lc};
Point(2) = {Ro, -H/2, 0, lc};
Point(3) = {Ro, H/2, 0, lc};
Point(4) = {Ri, H/2, 0, lc};

Line(1) = {1, 2};  // bottom
Line(2) = {2, 3};  // outer wall
Line(3) = {3, 4};  // top
Line(4) = {4, 1};  // the rod

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Physical Surface("fluid") = {1};
Physical Curve("wall") = {1, 2, 3, 4};
