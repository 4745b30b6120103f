// Capsule: a cylinder of radius R and length L closed by two hemispheres, centre at the origin.
// Meridian half-section in the (x = r, y = z) plane, r >= 0. rc_geometry needs the three
// physical groups at the end; the mesh size and order come from cavity-modes' options
// (lc below only matters when gmsh meshes this file on its own).
R = 1.0;
L = 2.0;
lc = 0.25;

Point(1) = {0, -L/2, 0, lc};      // centre of the lower hemisphere
Point(2) = {0, -L/2 - R, 0, lc};  // south pole
Point(3) = {R, -L/2, 0, lc};
Point(4) = {R, L/2, 0, lc};
Point(5) = {0, L/2, 0, lc};       // centre of the upper hemisphere
Point(6) = {0, L/2 + R, 0, lc};   // north pole

Circle(1) = {2, 1, 3};  // lower quarter circle (exact arc: high-order nodes lie on it)
Line(2) = {3, 4};       // cylindrical side
Circle(3) = {4, 5, 6};  // upper quarter circle
Line(4) = {6, 2};       // the symmetry axis r = 0

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Physical Surface("fluid") = {1};
Physical Curve("wall") = {1, 2, 3};
Physical Curve("axis") = {4};
