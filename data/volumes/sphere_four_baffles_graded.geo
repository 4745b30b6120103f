// The tank with four radial baffles (sphere_four_baffles.geo) with its mesh graded towards the baffles' inner edges:
// there the liquid turns 270 degrees round a plate's end, and the Zhukovsky flow (the liquid's response to the body's
// rotation) is singular, its velocity growing as d^(-1/3) with the distance d from the edge. docs/volume.md §6
// measures what the grading buys. The command's --mesh-size caps the size everywhere; --wall-size would replace this
// grading with its own (a grading towards every wall).
Include "sphere_four_baffles.geo";
edge_size = 0.04;   // element size at the edges
edge_reach = 0.5;   // distance from the edges over which the elements grow to the interior size
eps = 1e-3;
// Each plate's inner end (the face at ri from the axis): its two vertical edges and the short arcs on the sphere.
e() = Curve In BoundingBox{ri - eps, -t/2 - eps, -1.1, ri + eps, t/2 + eps, 1.1};
e() += Curve In BoundingBox{-ri - eps, -t/2 - eps, -1.1, -ri + eps, t/2 + eps, 1.1};
e() += Curve In BoundingBox{-t/2 - eps, ri - eps, -1.1, t/2 + eps, ri + eps, 1.1};
e() += Curve In BoundingBox{-t/2 - eps, -ri - eps, -1.1, t/2 + eps, -ri + eps, 1.1};
Field[1] = Distance;
Field[1].CurvesList = {e()};
Field[1].NumPointsPerCurve = 200;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = edge_size;
Field[2].SizeMax = 10;
Field[2].DistMin = edge_size;
Field[2].DistMax = edge_reach;
Background Field = 2;
