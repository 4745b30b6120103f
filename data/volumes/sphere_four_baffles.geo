// A spherical tank of radius 1 with four radial anti-slosh baffles: plates 0.04 thick in the planes x = 0 and y = 0,
// reaching in from the wall to 0.7 from the spin axis (z), over the whole height. OpenCASCADE: the sphere less four
// boxes; every surface of the fluid is wall. docs/volume.md §6 says what its table measures so far.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
t = 0.04;   // baffle thickness
ri = 0.7;   // the baffles' inner edge, from the axis
Box(2) = {ri, -t/2, -1.1, 1.5 - ri, t, 2.2};
Box(3) = {-1.5, -t/2, -1.1, 1.5 - ri, t, 2.2};
Box(4) = {-t/2, ri, -1.1, t, 1.5 - ri, 2.2};
Box(5) = {-t/2, -1.5, -1.1, t, 1.5 - ri, 2.2};
BooleanDifference(10) = { Volume{1}; Delete; }{ Volume{2, 3, 4, 5}; Delete; };
Physical Volume("fluid") = {10};
Physical Surface("wall") = Boundary{ Volume{10}; };
