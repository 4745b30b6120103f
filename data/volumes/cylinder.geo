// The circular cylinder of radius 1 and height 2 (axis z, centre at the origin) as a 3-D cavity: its 3-D table must
// give the axisymmetric table's m = 1 modes (docs/volume.md §3).
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, -1, 0, 0, 2, 1};
Physical Volume("fluid") = {1};
Physical Surface("wall") = {1, 2, 3};
