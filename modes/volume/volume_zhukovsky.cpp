#include "volume_zhukovsky.hpp"

#include <vector>

namespace rc::modes {

Tensor3 zhukovsky_tensor(const VolumeVelocity& V, const StiffnessSolver& M) {
  std::vector<std::vector<double>> g(3), psi(3);
  for (int k = 0; k < 3; ++k) {
    std::vector<double> both;
    V.divergence(V.rotation_field(k), both);  // the real field: its imaginary half is zero
    g[k].assign(both.begin(), both.begin() + both.size() / 2);
    M.solve(g[k], psi[k]);
  }
  Tensor3 J{};
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k)
      for (std::size_t i = 0; i < g[j].size(); ++i) J[j][k] += g[j][i] * psi[k][i];
  return J;
}

}  // namespace rc::modes
