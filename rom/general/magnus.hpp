// The sixth-order Magnus exponent of one step (Blanes, Casas and Ros, "Improved high order integrators based on the
// Magnus expansion", BIT 40, 2000) for y' = A(t) y: from A_i = h A(t + c_i h) at the Gauss points c = ½ ∓ √15/10, ½,
//   α1 = A2, α2 = √15/3 (A3 − A1), α3 = 10/3 (A3 − 2A2 + A1),  C1 = [α1, α2],  C2 = −[α1, 2α3 + C1]/60,
//   Ω = α1 + α3/12 + [−20α1 − α3 + C1, α2 + C2]/240,
// and the step is exp(Ω) (error O(h⁷) a step). Real for the chain's own motion (floquet.cpp), complex for its steady
// response to a harmonic moment (periodic_response.cpp).
#pragma once

#include <cmath>

namespace rc::rom {

// The Gauss points' offsets within the step, as fractions of h.
inline constexpr double kMagnusNodes[3] = {0.5 - 0.3872983346207417, 0.5, 0.5 + 0.3872983346207417};  // √15/10

template <class Matrix>
Matrix magnus_exponent(const Matrix& A1, const Matrix& A2, const Matrix& A3) {
  const auto commutator = [](const Matrix& a, const Matrix& b) -> Matrix { return a * b - b * a; };
  const Matrix a1 = A2, a2 = std::sqrt(15.0) / 3 * (A3 - A1), a3 = 10.0 / 3 * (A3 - 2 * A2 + A1);
  const Matrix C1 = commutator(a1, a2);
  const Matrix C2 = -commutator(a1, 2 * a3 + C1) / 60;
  return a1 + a3 / 12 + commutator(-20 * a1 - a3 + C1, a2 + C2) / 240;
}

}  // namespace rc::rom
