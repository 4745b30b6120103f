#include "field_gradient.hpp"

#include <algorithm>
#include <cmath>

namespace rc::rom {

std::string gradient_asymmetry(const FieldSpec& field) {
  const auto& G = field.gradient;  // row-major
  double scale = 0;
  for (const double g : G) scale = std::max(scale, std::abs(g));
  const double tol = 1e-12 * scale;
  if (std::abs(G[1]) > tol || std::abs(G[2]) > tol || std::abs(G[5]) > tol)
    return "has off-diagonal entries (xy, xz, yz)";
  if (std::abs(G[0] - G[4]) > tol) return "has xx != yy";
  return {};
}

void add_gradient_stiffness(const Scene& scene, ChainModel& cm) {
  if (!scene.field || !scene.field->has_gradient()) return;
  const double g_t = scene.field->gradient[0], g_z = scene.field->gradient[8];
  const int n = cm.n;
  double S = 0;  // S_k: O_k's height above O_1 with every axis vertical
  for (int k = 0; k < n; ++k) {
    const BodyModel& b = cm.bodies[static_cast<std::size_t>(k)];
    const double mc = b.m * b.c;
    cm.K(k, k) += mc * g_z * S + (b.A - b.C) * (g_z - g_t);
    for (int j = 0; j < k; ++j) {
      const double s_j = scene.bodies[static_cast<std::size_t>(j)].next_joint;
      cm.K(j, j) += (b.m * S + mc) * g_z * s_j;
      cm.K(j, k) -= mc * g_t * s_j;
      cm.K(k, j) -= mc * g_t * s_j;
      for (int i = 0; i < k; ++i) cm.K(i, j) -= b.m * g_t * scene.bodies[static_cast<std::size_t>(i)].next_joint * s_j;
    }
    S += scene.bodies[static_cast<std::size_t>(k)].next_joint;
  }
}

}  // namespace rc::rom
