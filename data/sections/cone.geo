// The built-in cone (cavity-modes cone --radius 1 --height 1.5) as a section file: apex at the origin, the lid at
// z = H. Meshed through the section path (gmsh's fields, not the built-in cone's CAD wall layers), it is an
// independent discretisation of the same cavity (tests/modes/test_viscous_cone.cpp).
// Meridian half-section in the (x = r, y = z) plane; the mesh size and order come from cavity-modes' options.
R = 1.0;
H = 1.5;
lc = 0.1;

Point(1) = {0, 0, 0, lc};  // apex
Point(2) = {R, H, 0, lc};  // rim
Point(3) = {0, H, 0, lc};  // centre of the lid

Line(1) = {1, 2};  // slant
Line(2) = {2, 3};  // lid
Line(3) = {3, 1};  // the symmetry axis r = 0

Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

Physical Surface("fluid") = {1};
Physical Curve("wall") = {1, 2};
Physical Curve("axis") = {3};
