// The weak-viscosity limit by boundary-layer theory: the O(Ek^{1/2}) correction of an inertial mode's
// eigenvalue from its ideal wall velocity alone (Greenspan, "The Theory of Rotating Fluids", Cambridge
// University Press 1968, §2.8; docs/viscous.md, "Boundary-layer limit", derives this form). It is the
// independent check of the full viscous solver: no mesh, no Navier–Stokes, only the ideal mode.
//
// With e^{iλt}, ideal mode u0 (frequency λ0, ‖u0‖² = ∫|u0|² dV) and its wall velocity U = (U_s, U_φ) along the
// unit tangents s (meridian, fluid on its left) and e_φ, n = s × e_φ, c = ẑ·n:
//   λ = λ0 + λ1 Ek^{1/2} + O(Ek),   λ1 = (i / ‖u0‖²) ∮ ½ (q+ |U_s + iU_φ|² + q− |U_s − iU_φ|²) dS,
//   q± = (i (λ0 ± 2c))^{1/2} with Re q± ≥ 0  (the Ekman layer's two circular polarisations).
// Im λ1 > 0 is the decay rate per Ek^{1/2}; for the sphere's spin-over mode λ1 = 0.2585 + 2.6205 i.
#pragma once

#include <array>
#include <complex>
#include <functional>
#include <vector>

namespace rc::modes {

struct WallPoint {
  double r = 0, z = 0;    // position on the meridian wall
  double sr = 0, sz = 0;  // unit tangent, fluid on its left
  double weight = 0;      // quadrature weight of the arc length (dl)
};

// (V_r, V_φ, V_z) of an m = 1 mode at (r, z): the factor of e^{iφ}.
using ModeVelocity = std::function<std::array<std::complex<double>, 3>(double r, double z)>;

// λ1 of the formula above. norm2 = ‖u0‖² = 2π ∫∫ |V|² r dr dz.
std::complex<double> boundary_layer_correction(double lambda0, const std::vector<WallPoint>& wall,
                                               const ModeVelocity& velocity, double norm2);

// The same correction on a 3-D wall (a cavity without axial symmetry, docs/volume.md §7): at each wall point the
// inward normal n, any unit tangents e1, e2 with e1 × e2 = n (the meridian's s, e_φ), c = ẑ·n, and the polarisations
// U± = U·e1 ± i U·e2 of the wall velocity U; the same ∮ ½ (q+ |U+|² + q− |U−|²) dS.
struct SurfacePoint {
  std::array<double, 3> x{}, normal{};  // position, unit normal into the fluid
  double weight = 0;                    // quadrature weight of the area (dS)
};
using VolumeModeVelocity = std::function<std::array<std::complex<double>, 3>(const std::array<double, 3>& x)>;
std::complex<double> boundary_layer_correction(double lambda0, const std::vector<SurfacePoint>& wall,
                                               const VolumeModeVelocity& velocity, double norm2);

// The ellipsoid x²/a² + y²/b² + z²/c² = 1 (axes along x, y, z): composite 8-point Gauss rules in the polar angle θ
// (`panels` panels) and the azimuth φ (2 `panels`) of x = (a sin θ cos φ, b sin θ sin φ, c cos θ).
std::vector<SurfacePoint> ellipsoid_surface(double a, double b, double c, int panels);

// Composite 8-point Gauss–Legendre rules along the built-in walls (`panels` panels in all, or per side).
std::vector<WallPoint> ellipse_wall(double a, double c, int panels);          // south pole -> north pole
std::vector<WallPoint> cylinder_wall(double radius, double height, int panels_per_side);  // bottom, side, top

}  // namespace rc::modes
