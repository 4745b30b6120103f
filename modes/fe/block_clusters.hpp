// The clusters of a block Gauss rule whose start block is N complex fields in real form (the fields, then each times
// i): a node's complex coupling to field j is c_j = ⟨f_j, z⟩ + i⟨i f_j, z⟩, and Ritz values within `width` ·
// max(|λ|, 0.1) of each other are one cluster (one exact mode split among discrete copies). Each complex mode is two
// real Ritz vectors z and iz with couplings c and ic, so a cluster's weight is H = ½ Σ c cᴴ, its λ the trace-weighted
// mean, its spread the trace-weighted deviation. Shared by the 3-D survey (N = 3 rotations) and the free-surface one
// (N = 5: rotations and the offsets along the spin axis).
#pragma once

#include "block_lanczos.hpp"
#include "lanczos.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace rc::modes {

// Mode: lambda, H (N × N complex), residual, members, spread.
template <class Mode, int N>
std::vector<Mode> block_clusters(std::vector<BlockGaussNode> rule, double width) {
  using Coupling = Eigen::Matrix<std::complex<double>, N, 1>;
  std::sort(rule.begin(), rule.end(), [](const auto& a, const auto& b) { return a.lambda < b.lambda; });
  std::vector<Mode> out;
  std::vector<double> sum_l, sum_l2, sum_w;
  for (const auto& n : rule) {
    Coupling c;
    for (int j = 0; j < N; ++j) c(j) = {n.weight(j), n.weight(N + j)};
    const auto H = (0.5 * c * c.adjoint()).eval();
    const double w = H.trace().real();
    if (out.empty() || !within_width(n.lambda, out.back().lambda, width)) {
      out.push_back({});
      out.back().lambda = n.lambda;
      sum_l.push_back(0); sum_l2.push_back(0); sum_w.push_back(0);
    }
    Mode& m = out.back();
    m.H += H;
    m.residual = std::max(m.residual, n.residual);
    ++m.members;
    sum_w.back() += w; sum_l.back() += w * n.lambda; sum_l2.back() += w * n.lambda * n.lambda;
    if (sum_w.back() > 0) m.lambda = sum_l.back() / sum_w.back();
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].members = (out[i].members + 1) / 2;  // real Ritz values come in pairs
    if (sum_w[i] > 0) out[i].spread = std::sqrt(std::max(0.0, sum_l2[i] / sum_w[i] - out[i].lambda * out[i].lambda));
  }
  return out;
}

}  // namespace rc::modes
