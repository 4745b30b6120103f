// A Lanczos process for a self-adjoint operator in a weighted inner product, and the Gauss quadrature
// rule of the start vector's spectral measure that it builds (Golub–Welsch). Used by the spectral
// surveys: on A = P_H S (spectral_survey.hpp) and on the shift-inverted (A − σ)⁻¹ (shift_invert_survey.hpp).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace rc::modes {

struct GaussNode {
  double lambda = 0;  // node of the Gauss rule
  double E = 0;       // its weight (sums to the measure's mass over all nodes)
  double residual = 0;  // Ritz residual ‖Op y − λ y‖ of the node's Ritz vector (β_k · |last component|)
};

// The λ scale of every window and cluster width in cavity-modes: max(|λ|, 0.1) (docs/modes.md, "Clusters").
inline double lambda_scale(double lambda) { return std::max(std::abs(lambda), 0.1); }
// True when λ = a lies within width · lambda_scale(b) of b.
inline bool within_width(double a, double b, double width) { return std::abs(a - b) <= width * lambda_scale(b); }

class LanczosProcess {
 public:
  using Apply = std::function<void(const Eigen::VectorXd& in, Eigen::VectorXd& out)>;

  // weights: the inner product ⟨u, v⟩ = Σ weights ∘ u ∘ v; start must be non-zero; at most max_steps steps.
  LanczosProcess(const Eigen::VectorXd& weights, const Eigen::VectorXd& start, int max_steps);

  // One step with the operator; false when the Krylov space became invariant (the rule is then exact)
  // or max_steps is reached.
  bool step(const Apply& apply);
  int steps() const { return static_cast<int>(alpha_.size()); }
  bool exhausted() const { return exhausted_; }

  // The Gauss rule of the current tridiagonal matrix: nodes are its eigenvalues (ascending), weights
  // mass · (first component of each eigenvector)².
  std::vector<GaussNode> rule(double mass) const;

 private:
  Eigen::VectorXd weights_;
  Eigen::MatrixXd basis_;  // Lanczos vectors, one per column
  std::vector<double> alpha_, beta_;
  double norm0_ = 0, last_beta_ = 0;
  bool exhausted_ = false;
  Eigen::VectorXd v_, h_;
};

}  // namespace rc::modes
