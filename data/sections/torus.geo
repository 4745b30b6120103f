// Torus: the liquid in a tube of circular cross-section, radius a = 0.4, whose centre line is the circle of radius
// R = 1 about the spin axis (a ring tank around an engine). Meridian half-section in the (x = r, y = z) plane: the
// disc of radius a centred at (R, 0). It nowhere touches r = 0, so it has no "axis" group: its wall is its whole
// boundary. No closed form for its modes; its frozen-fluid integrals are exact (volume 2π²Ra², A_f = m(R²/2 + 5a²/8),
// C_f = m(R² + 3a²/4)) and its sum rule Σ E = A_f − J_zh holds to the curved wall's geometric error (docs/geometry.md,
// "Ring-shaped sections"). Mesh size and order come from cavity-modes' options.
R = 1.0;
a = 0.4;
lc = 0.1;

Point(1) = {R, 0, 0, lc};      // centre
Point(2) = {R + a, 0, 0, lc};
Point(3) = {R, a, 0, lc};
Point(4) = {R - a, 0, 0, lc};
Point(5) = {R, -a, 0, lc};

Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Physical Surface("fluid") = {1};
Physical Curve("wall") = {1, 2, 3, 4};
