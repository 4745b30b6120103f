// Spherical shell: the liquid between an inner sphere of radius Ri = 0.35 and the outer sphere of radius 1 (Kore's own
// test case, the spin-over mode with both walls no-slip: bench/kore_peer.sh; docs/benchmarks.md, "Kore"). Meridian
// half-section in the (x = r, y = z) plane: two half circles (each as two quarter arcs) joined by the two pieces of
// the axis between them. The mesh size and order come from cavity-modes' options.
Ri = 0.35;
Ro = 1.0;
lc = 0.1;

Point(1) = {0, 0, 0, lc};      // centre
Point(2) = {0, -Ro, 0, lc};    // outer south pole
Point(3) = {Ro, 0, 0, lc};     // outer equator
Point(4) = {0, Ro, 0, lc};     // outer north pole
Point(5) = {0, Ri, 0, lc};     // inner north pole
Point(6) = {Ri, 0, 0, lc};     // inner equator
Point(7) = {0, -Ri, 0, lc};    // inner south pole

Circle(1) = {2, 1, 3};  // outer sphere, lower quarter
Circle(2) = {3, 1, 4};  // outer sphere, upper quarter
Line(3) = {4, 5};       // axis, north
Circle(4) = {5, 1, 6};  // inner sphere, upper quarter
Circle(5) = {6, 1, 7};  // inner sphere, lower quarter
Line(6) = {7, 2};       // axis, south

Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};

Physical Surface("fluid") = {1};
Physical Curve("wall") = {1, 2, 4, 5};
Physical Curve("axis") = {3, 6};
