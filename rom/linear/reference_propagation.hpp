// Extended-precision reference of `chain-rom bench`: the state y(t) of the first-order system
// (first_order_system.hpp) assembled and propagated in long double (x86-64: 64-bit mantissa,
// epsilon 1.1e-19, against 2.2e-16 for double), twice and independently:
//   by the eigen-decomposition, y(t) = V e^{mu t} V^{-1} y(0) (what `exact` does in double), and
//   by the matrix exponential, y(t) = exp(B t) y(0) (Pade approximant + scaling and squaring).
// Their difference bounds the reference's own error; it is reported with the state. Both work on the
// balanced matrix (balancing.hpp): without it the long double eigen-decomposition of the default
// scene was off by 1.6e-14 at t = 5 s (against a 113-bit computation), with it by 1e-15.
// The model's inputs (M_eff, K, D, G, E, lambda, nu) are its double values: the reference is the exact
// solution of the same model, not of a model rebuilt in long double.
#pragma once

#include "chain_model.hpp"

#include "eigen_dense.hpp"

namespace rc::rom {

struct ReferenceState {
  Eigen::VectorXcd y;           // y(t) (eigen-decomposition, long double), rounded to double
  double method_difference = 0; // |y_eig - y_expm| / |y_eig|, both in long double
  double wall_seconds = 0;      // both computations
  int mantissa_bits = 0;        // of long double on this machine
};

// y0 and the result are balanced states for the scale s of build_first_order(m).
ReferenceState reference_state(const ChainModel& m, double s, const Eigen::VectorXcd& y0, double t);

// The same for a matrix assembled in double (the general chain's, general_system.hpp): B's entries are taken as
// exact, so the reference is the exact solution of that matrix, its assembly's rounding not included.
ReferenceState reference_state(const Eigen::MatrixXcd& B, const Eigen::VectorXcd& y0, double t);

}  // namespace rc::rom
