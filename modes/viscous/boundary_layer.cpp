#include "boundary_layer.hpp"

#include <cmath>
#include <numbers>

namespace rc::modes {
namespace {


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
    sum += 0.5 * (qp * Wp + qm * Wm) * 2.0 * std::numbers::pi * w.r * w.weight;  // dS = 2π r dl
  }
  return I * sum / norm2;
}

std::complex<double> boundary_layer_correction(double lambda0, const std::vector<SurfacePoint>& wall,
                                               const VolumeModeVelocity& velocity, double norm2) {
  const std::complex<double> I(0, 1);
  std::complex<double> sum = 0;
  for (const auto& p : wall) {
    const auto& n = p.normal;
    // e1: the unit vector along the coordinate axis least aligned with n, made tangent; e2 = n × e1 (e1 × e2 = n).
    std::array<double, 3> e1{0, 0, 0};
    const int k = std::abs(n[0]) <= std::abs(n[1]) && std::abs(n[0]) <= std::abs(n[2]) ? 0 : std::abs(n[1]) <= std::abs(n[2]) ? 1 : 2;
    e1[k] = 1;
    const double along = e1[k] * n[k];
    for (int d = 0; d < 3; ++d) e1[d] -= along * n[d];
    const double l = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (double& v : e1) v /= l;
    const std::array<double, 3> e2 = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
    const auto V = velocity(p.x);
    std::complex<double> U1 = 0, U2 = 0;
    for (int d = 0; d < 3; ++d) { U1 += V[d] * e1[d]; U2 += V[d] * e2[d]; }
    const double c = n[2];
    const std::complex<double> qp = std::sqrt(I * (lambda0 + 2 * c)), qm = std::sqrt(I * (lambda0 - 2 * c));
    sum += 0.5 * (qp * std::norm(U1 + I * U2) + qm * std::norm(U1 - I * U2)) * p.weight;
  }
  return I * sum / norm2;
}

std::vector<SurfacePoint> ellipsoid_surface(double a, double b, double c, int panels) {
  std::vector<SurfacePoint> wall;
  for (int i = 0; i < panels; ++i)
    for (std::size_t gi = 0; gi < kX.size(); ++gi) {
      const double t = std::numbers::pi * (i + kX[gi]) / panels, wt = kW[gi] * std::numbers::pi / panels;
      for (int j = 0; j < 2 * panels; ++j)
        for (std::size_t gj = 0; gj < kX.size(); ++gj) {
          const double f = std::numbers::pi * (j + kX[gj]) / panels, wf = kW[gj] * std::numbers::pi / panels;
          const double st = std::sin(t), ct = std::cos(t), sf = std::sin(f), cf = std::cos(f);
          SurfacePoint p;
          p.x = {a * st * cf, b * st * sf, c * ct};
          // x_θ × x_φ = (b c sin²θ cos φ, a c sin²θ sin φ, a b sin θ cos θ): outward, |·| dθ dφ = dS.
          const double N[3] = {b * c * st * st * cf, a * c * st * st * sf, a * b * st * ct};
          const double area = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
          p.normal = {-N[0] / area, -N[1] / area, -N[2] / area};
          p.weight = area * wt * wf;
          wall.push_back(p);
        }
    }
  return wall;
}

std::vector<WallPoint> ellipse_wall(double a, double c, int panels) {
  std::vector<WallPoint> wall;
  for (int p = 0; p < panels; ++p)
    for (std::size_t g = 0; g < kX.size(); ++g) {
      const double t = -std::numbers::pi / 2 + std::numbers::pi * (p + kX[g]) / panels;  // r = a cos t, z = c sin t
      const double dr = -a * std::sin(t), dz = c * std::cos(t), speed = std::hypot(dr, dz);
      wall.push_back({a * std::cos(t), c * std::sin(t), dr / speed, dz / speed, kW[g] * speed * std::numbers::pi / panels});
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
