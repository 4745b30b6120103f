// The uniform-vorticity modes of an ellipsoid of ideal fluid spinning about an axis at any angle to its own (Poincaré
// 1910, "Sur la précession des corps déformables"; Hough 1895, "The oscillations of a rotating ellipsoidal shell
// containing fluid"; derivation: docs/volume.md §3). With semi-axes D = diag(a, b, c) and the spin axis Ω (unit,
// body frame), the fields V = D (ω × D⁻¹ r) are solenoidal and tangent to the wall, their vorticity is K ω with
// K = diag((b² + c²)/(bc), (a² + c²)/(ac), (a² + b²)/(ab)), and the curl of iλV + 2Ω × V = −∇P closes on them:
//   K ω̇ = −2 D [D⁻¹Ω]× ω,
// a 3 × 3 system with eigenvalues 0 (the steady geostrophic vortex ω ∥ D⁻¹Ω) and ±iλ (the spin-over mode). Every
// coupling field e_k × r projects into this space, so these three are the only modes that couple to rotation.
#pragma once

#include <Eigen/Core>

namespace rc::modes {

struct EllipsoidModes {
  double lambda = 0;              // the spin-over mode's frequency (> 0)
  Eigen::Matrix3cd H;             // its coupling tensor c cᴴ/‖V‖², c_k = ∫ (e_k × r)·V, in the spin frame
  Eigen::Matrix3cd field;         // its velocity V = field · r (spin frame, r from the centre), with ∫ |V|² = norm2
  double norm2 = 0;
  Eigen::Matrix3d geostrophic;    // the λ = 0 vortex's coupling tensor
  Eigen::Matrix3d inertia, zhukovsky;  // frozen fluid and Zhukovsky's inertia about the centre, spin frame
  double mass = 0;
};

// tilt: the ellipsoid turned about x by this angle (radians), as cavity-modes ellipsoid --tilt does (the c axis
// goes to (0, −sin tilt, cos tilt)).
EllipsoidModes ellipsoid_modes(double a, double b, double c, double tilt);

}  // namespace rc::modes
