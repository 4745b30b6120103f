// A rectangular tank 1.2 × 0.8 × 1.0 (x, y, z), its centre off the spin axis: a 3-D cavity with flat faces, on
// which straight-sided tetrahedra are exact (docs/volume.md §4: the tensor sum rule then holds to rounding).
SetFactory("OpenCASCADE");
Box(1) = {0.3, -0.4, -0.5, 1.2, 0.8, 1.0};
Physical Volume("fluid") = {1};
Physical Surface("wall") = {1, 2, 3, 4, 5, 6};
