// The partially filled cylinder under rapid spin (docs/physics.md §2, "Partially filled cylinder"; Stewartson 1959,
// "On the stability of a spinning top containing liquid"): the liquid fills b < r < a, |z| < h of a cylinder of
// radius a and height 2h, its free surface the coaxial cylinder r = b on which the rigid rotation's pressure is
// constant (gravity neglected against the centrifugal acceleration). The m = 1 inertial modes, ω0 = 1:
// p = F(ξ r/a) sin(k z), k = (2n+1)π/(2h), with
//   |λ| < 2 (κ² > 1):  ξ² = (ka)²(κ² − 1),  F = J1 + c Y1;
//   |λ| > 2 (κ² < 1):  ζ² = (ka)²(1 − κ²),  F = I1 + c K1 (modes that exist only with a free surface);
// the wall's u_r = 0 at r = a:                        r p_r + κ p = 0,
// the free surface's kinematic and dynamic conditions: r p_r + (κ − D) p = 0 at r = b,  D = 4 − λ².
// Nothing here touches the FE solvers.
#pragma once

#include <vector>

namespace rc::modes::exact {

// The free surface's radius for a liquid volume fraction `fill` of the cylinder of radius a: b = a √(1 − fill).
// Throws std::invalid_argument unless 0 < fill <= 1.
double partial_fill_surface_radius(double a, double fill);

struct PartialFillMode {
  double lambda = 0, kappa = 0;
  int axial = 0;         // n: k = (2n+1)π/(2h)
  int radial = 0;        // j: 1-based rank of the root in ξ for this n and sign of κ (|λ| < 2; j = 1 is nearest
                         //    |λ| = 2), or 0 for a mode with |λ| > 2
};

// Every mode with n < max_axial and ξ < max_xi (all those with |λ| > 2), for 0 < fill < 1. Sorted by n, then by
// sign of λ (positive first), then by j.
std::vector<PartialFillMode> partially_filled_cylinder_modes(double a, double height, double fill, int max_axial = 4,
                                                             double max_xi = 40.0);

}  // namespace rc::modes::exact
