// How far a stable undamped chain is from losing stability: the closest approach of two real roots that can meet.
//
// Without dissipation every root of a stable chain is real (Kononov's necessary condition), and the chain loses
// stability only where two real roots meet and leave the axis as a complex pair. Roots of the same Krein signature
// pass through each other without leaving it; only roots of opposite signature can meet so (Krein's theorem; for
// the chain the indefinite-metric argument of Batyr 2010, "Small motions and normal oscillations of a system of
// three articulated bodies with cavities filled with an ideal incompressible fluid"). For real σ the matrix Φ(σ) of
// Kononov (22) is real symmetric (characteristic.hpp), and the signature of a simple real root σ with Φ(σ)v = 0 is
//   sign vᵀ Φ'(σ) v,
// the slope with which the eigenvalue of Φ through zero crosses it. The gap is the smallest distance between two
// roots adjacent on the real axis with opposite signatures: what the roots must still travel, together, before the
// verdict can change. It is 0 at a collision and undefined for an unstable or dissipative chain.
#pragma once

#include "chain_model.hpp"

#include "eigen_dense.hpp"
#include <limits>

namespace rc::rom {

struct KreinGap {
  bool defined = false;  // an undamped chain with every root real and two of opposite signature
  double gap = std::numeric_limits<double>::quiet_NaN();    // rad/s
  double left = std::numeric_limits<double>::quiet_NaN();   // the two roots (rad/s), left < right
  double right = std::numeric_limits<double>::quiet_NaN();
};

// `sigma`: every root of the chain; `tolerance`: |Im σ| (and |σ| at zero) within which a root counts as real (zero).
int krein_signature(const ChainModel& m, double sigma);  // +1, -1, or 0 where it cannot be read
KreinGap krein_gap(const ChainModel& m, const Eigen::VectorXcd& sigma, double tolerance);

}  // namespace rc::rom
