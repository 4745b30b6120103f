#include "free_surface_coupling.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::modes {

FreeSurfaceCoupling free_surface_coupling(double lambda, const FreeSurfaceFormValues& v) {
  constexpr double pi = std::numbers::pi;
  const double l = lambda, D = 4 - l * l;
  const double centroid = pi * ((l * l + 2 * l) * v.f1p + D * v.f2p + l * D * v.f3p);
  const double offset = pi * ((l * l + 2 * l) * v.g1p + l * D * v.e1p);
  const double t1 = l * l * (l * l + 4) * v.kh, t2 = 4 * l * l * l * v.gc, t3 = D * D * v.kz, t4 = l * l * D * D * v.ss;
  const double norm2 = 2 * pi * (t1 + t2 + t3 + t4);
  if (!std::isfinite(norm2) || !std::isfinite(centroid) || !std::isfinite(offset))
    throw std::runtime_error("free-surface mode with non-finite energy");
  FreeSurfaceCoupling c;
  if (norm2 <= 1e-14 * 2 * pi * (t1 + std::abs(t2) + t3 + t4)) return c;
  c.a = centroid / std::sqrt(norm2);
  c.t = offset / std::sqrt(norm2);
  c.E = 2 * c.a * c.a;
  c.norm = std::sqrt(norm2);
  return c;
}

}  // namespace rc::modes
