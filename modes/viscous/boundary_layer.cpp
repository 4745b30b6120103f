#include "boundary_layer.hpp"

#include <cmath>
#include <numbers>

namespace rc::modes {
namespace {

constexpr double kPi = std::numbers::pi;

// 8-point Gauss–Legendre on [0, 1]: the integrand has only |x|^{1/2} kinks (critical latitudes, where
// λ0 ± 2c = 0), so many short panels beat a high order.
constexpr std::array<double, 8> kX = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355,
                                      0.4082826787521751, 0.5917173212478249, 0.7627662049581645,
                                      0.8983332387068134, 0.9801449282487681};
constexpr std::array<double, 8> kW = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436,
                                      0.1813418916891810, 0.1813418916891810, 0.1568533229389436,
                                      0.1111905172266872, 0.0506142681451881};

// A straight segment from (r0, z0) to (r1, z1).
void add_segment(std::vector<WallPoint>& wall, double r0, double z0, double r1, double z1, int panels) {
  const double length = std::hypot(r1 - r0, z1 - z0);
  for (int p = 0; p < panels; ++p)
    for (std::size_t g = 0; g < kX.size(); ++g) {
      const double t = (p + kX[g]) / panels;
      wall.push_back({r0 + t * (r1 - r0), z0 + t * (z1 - z0), (r1 - r0) / length, (z1 - z0) / length,
                      kW[g] * length / panels});
    }
}

}  // namespace

std::complex<double> boundary_layer_correction(double lambda0, const std::vector<WallPoint>& wall,
                                               const ModeVelocity& velocity, double norm2) {
  const std::complex<double> I(0, 1);
  std::complex<double> sum = 0;
  for (const auto& w : wall) {
    const auto V = velocity(w.r, w.z);
    const std::complex<double> Us = V[0] * w.sr + V[2] * w.sz, Uphi = V[1];
    const double c = w.sr;  // ẑ·(s × e_φ) with s × e_φ = (−s_z, 0, s_r)
    const std::complex<double> qp = std::sqrt(I * (lambda0 + 2 * c)), qm = std::sqrt(I * (lambda0 - 2 * c));
    const double Wp = std::norm(Us + I * Uphi), Wm = std::norm(Us - I * Uphi);
    sum += 0.5 * (qp * Wp + qm * Wm) * 2.0 * kPi * w.r * w.weight;  // dS = 2π r dl
  }
  return I * sum / norm2;
}

std::vector<WallPoint> ellipse_wall(double a, double c, int panels) {
  std::vector<WallPoint> wall;
  for (int p = 0; p < panels; ++p)
    for (std::size_t g = 0; g < kX.size(); ++g) {
      const double t = -kPi / 2 + kPi * (p + kX[g]) / panels;  // r = a cos t, z = c sin t
      const double dr = -a * std::sin(t), dz = c * std::cos(t), speed = std::hypot(dr, dz);
      wall.push_back({a * std::cos(t), c * std::sin(t), dr / speed, dz / speed, kW[g] * speed * kPi / panels});
    }
  return wall;
}

std::vector<WallPoint> cylinder_wall(double radius, double height, int panels_per_side) {
  std::vector<WallPoint> wall;
  const double h = height / 2;
  add_segment(wall, 0, -h, radius, -h, panels_per_side);
  add_segment(wall, radius, -h, radius, h, panels_per_side);
  add_segment(wall, radius, h, 0, h, panels_per_side);
  return wall;
}

}  // namespace rc::modes
