// The oblate spheroid a = b = 1, c = 0.5 (axis z, centre at the origin) as a user's 3-D cavity file: with wall
// layers (--wall-layer) its viscous spin-over mode must be the meridian solver's and the built-in ellipsoid's
// (docs/volume.md §7, "Wall layers").
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Dilate {{0, 0, 0}, {1, 1, 0.5}} { Volume{1}; }
Physical Volume("fluid") = {1};
Physical Surface("wall") = {1};
