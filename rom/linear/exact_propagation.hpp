// Exact propagation of the linear constant-coefficient system y' = B y (first_order_system.hpp)
// through its eigen-decomposition B = V diag(mu) V^{-1}:
//   y(t) = V diag(e^{mu t}) c,   c = V^{-1} y(0),
// evaluated at each output time from scratch (no error accumulates from step to step). Many output
// times are evaluated a block of columns at a time, Y = V [e^{mu t_j} c]_j, one matrix product per
// block, with e^{mu j h} = e^{mu q K h} e^{mu r h} (j = qK + r) from two tables of exponentials.
//
// Real form. Without friction, -iB conjugated by T = diag(-i I_n, I, I) (rows of the s*u block
// times -i, its columns times i) is a real matrix A (spectrum.cpp uses the same fact). When all its
// eigenvalues sigma are real (an undamped stable chain) its eigenvectors W are real too, and
//   T y(t) = W diag(e^{i sigma t}) W^{-1} T y(0):
// the product per block is then real x complex, half the work of complex x complex.
#pragma once

#include "first_order_system.hpp"

#include "eigen_dense.hpp"

#include <functional>

namespace rc::rom {

// Above this 2-norm condition number of the eigenvector matrix the decomposition is not used
// (defective or nearly defective spectrum, e.g. omega = 0 and g = 0): propagate() steps with
// exp(B h) instead.
inline constexpr double kMaxEigvecCondition = 1e8;

struct ModalForm {
  int n = 0;               // size of the s*u block (the rows T multiplies by -i in the real form)
  bool real = false;       // real form: W, sigma (below) in place of V, mu
  Eigen::MatrixXd W;       // real form: real eigenvectors of A = T(-iB)T^{-1}
  Eigen::VectorXd sigma;   // real form: its real eigenvalues (roots sigma)
  Eigen::MatrixXcd V;      // complex form: eigenvectors of B
  Eigen::VectorXcd mu;     // complex form: eigenvalues of B (mu = i sigma)
  double condition = 0;    // cond_2 of W or V
  bool usable = false;     // the eigen-solver converged and condition < kMaxEigvecCondition
  bool undamped_real = false;  // no friction and all roots real within the verdict's tolerance
};

// Eigen-decomposition of the first-order matrix. `undamped`: the model has no friction (the real
// form is tried first); `real_tolerance`: the relative tolerance of spectrum.hpp's verdict.
ModalForm modal_form(const FirstOrderSystem& f, bool undamped, double real_tolerance);

// Complex form only: sets Re mu = 0 (roots exactly real), so that |e^{mu t}| = 1 and no energy can
// drift; for undamped stable systems, whose roots are real up to rounding. (The real form's roots
// are real by construction.)
void snap_to_imaginary_axis(ModalForm& f);

// y(t) for one t.
Eigen::VectorXcd modal_state_at(const ModalForm& f, const Eigen::VectorXcd& y0, double t);

// y(j h) for j = 0..steps, handed to `sink` block by block: sink(j0, re, im) with column i of
// re + i*im the state at (j0 + i) h (real and imaginary parts apart: the real form computes them
// apart, and what the caller derives from them — energies, copies — is real arithmetic too).
// Blocks are shared among `threads` threads (0: all cores); sink is then called concurrently for
// different blocks and must only write what belongs to its own columns.
using StateBlockSink =
    std::function<void(long, const Eigen::Ref<const Eigen::MatrixXd>&, const Eigen::Ref<const Eigen::MatrixXd>&)>;
void modal_states(const ModalForm& f, const Eigen::VectorXcd& y0, double h, long steps,
                  const StateBlockSink& sink, int threads = 0);

}  // namespace rc::rom
