// The mesh error of a confirmed root's growth rate (docs/rom.md, "Mesh error of confirmed roots"). A root of (22)
// with the tanks' own R is measured on levels of one mesh family — level 0 the table's mesh, each next level with
// every element size halved (cavity-modes response --mesh-level) — and the differences between levels estimate how
// far the finest level's growth rate is from the mesh-converged one.
#pragma once

#include <complex>
#include <string>
#include <vector>

namespace rc::rom {

struct MeshErrorEstimate {
  std::complex<double> sigma;  // the root on the finest level
  double growth = 0;           // -Im sigma (1/s): > 0 grows, < 0 decays
  double error = 0;            // the estimated error of `growth` (1/s)
  double order = 0;            // observed order of convergence in the element size; 0: not measured (two levels)
  double extrapolated = 0;     // Richardson's growth rate where `order` was measured and sane, else `growth`
  bool asymptotic = false;     // three levels or more whose differences fall at a sane order
  bool converged = false;      // error <= tolerance |growth| + floor
  bool sign_settled = false;   // |growth| > error: the sign of the growth does not depend on the mesh
  double relative() const;     // error / |growth|
};

// `levels`: the root's sigma on levels 0 (the coarsest) .. L (the finest), L >= 1. With g_l = -Im sigma_l and
// d_l = g_l - g_{l-1}:
//   two levels:   error = |d_L|: the finest level's own error if the rate converges at first order, an
//                 over-estimate at any higher order;
//   three or more: the observed order p = log2(|d_{L-1}| / |d_L|); where p >= 0.5 (the difference falls by 1.41 or
//                 more per halving), Roache's grid convergence index: error = 1.25 |d_L| / (2^p - 1), and Richardson's
//                 extrapolation g_L + d_L / (2^p - 1) (Roache 1994, "Perspective: a method for uniform reporting of
//                 grid refinement studies"); otherwise the differences do not fall as a converging sequence's do:
//                 error = max(|d_L|, |d_{L-1}|) and `asymptotic` false.
// `tolerance` is relative to |growth|; `floor` (1/s) an absolute allowance for rates at rounding level.
// `halving` false (levels that raise the order instead): no order is taken, the error is max(|d_L|, |d_{L-1}|) — the
// finest difference alone where two levels (p-refinement converges faster than any power of h once resolved).
// `ratio`: each level's element size over the next one's (2 for halving); the formulas above with 2 replaced by it,
// so that two levels give |d_L| / (ratio − 1), the error at first order in h (1.5: 2 |d_L|).
MeshErrorEstimate mesh_error(const std::vector<std::complex<double>>& levels, double tolerance, double floor,
                             bool halving = true, double ratio = 2.0);

// "decay 2.970e-4 ± 3.1e-6 1/s (1.0 %)": the rate with its error, as the verdict prints it.
std::string rate_with_error(const MeshErrorEstimate& e);

}  // namespace rc::rom
