// A rational function fitted to samples of the fluid's response R(s) on the real axis: the AAA algorithm
// (Nakatsukasa, Sète and Trefethen, "The AAA algorithm for rational approximation", SIAM J. Sci. Comput. 40,
// 2018) picks the support points and barycentric weights; its poles are then kept where a passive fluid allows
// them (Im p > 0: every damped mode e^{ipt} decays) and the residues refitted by linear least squares, so that
//   R(s) ≈ Σ_j r_j / (s − p_j)
// has exactly the form of a modal sum (docs/viscous.md, "Response fit"): each (p_j, r_j) enters the chain model
// as a damped mode with frequency p_j and coupling r_j. Pure Eigen; no PETSc.
#pragma once

#include <Eigen/Core>

#include <complex>
#include <vector>

namespace rc::modes {

struct RationalFit {
  std::vector<std::complex<double>> poles, residues;  // R(s) ≈ Σ residues[j] / (s − poles[j])
  int aaa_degree = 0;        // support points AAA used (its type is (degree − 1, degree − 1))
  int dropped_poles = 0;     // AAA poles left out: in the closed lower half plane or with negligible residue
  double fit_error = 0;      // max |R − fit| / max |R| over the fitted samples
  std::complex<double> operator()(std::complex<double> s) const;
};

// AAA on (z, f) to relative tolerance `tolerance` (at most `max_degree` support points), then the pole filter
// and the least-squares residues on all samples. Throws std::invalid_argument on fewer than 4 samples, unequal
// lengths or non-finite values, std::runtime_error if no pole survives the filter.
RationalFit fit_response(const std::vector<double>& z, const std::vector<std::complex<double>>& f,
                         double tolerance = 1e-10, int max_degree = 120);

}  // namespace rc::modes
