// The nonlinear rigid body about a fixed point (rom/nonlinear/rigid_body.hpp), the first brick of the nonlinear chain:
// the Lagrange top at a large angle against its closed form (turning points of the nutation from the cubic in
// cos θ), the conserved energy and vertical angular momentum, the order of the Lie-group integrator, and the free
// asymmetric body's angular momentum vector.
#include "rigid_body.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace rc::rom;

namespace {

struct TopRun {
  double energy_drift = 0, Lz_drift = 0, u_min = 1, u_max = -1;
};

// Integrates to t_end with step h, tracking the conserved quantities and the extremes of cos θ = (R e3)_z.
TopRun integrate(const RigidBody& b, RigidState s, double h, double t_end) {
  TopRun r;
  const double E0 = energy(b, s), L0 = angular_momentum(b, s).z();
  const double scale_E = std::abs(E0) + 0.5 * s.omega.dot(b.inertia.cwiseProduct(s.omega));
  const double scale_L = angular_momentum(b, s).norm();
  const int steps = static_cast<int>(std::lround(t_end / h));
  for (int k = 0; k < steps; ++k) {
    s = rkmk4_step(b, s, h);
    r.energy_drift = std::max(r.energy_drift, std::abs(energy(b, s) - E0) / scale_E);
    r.Lz_drift = std::max(r.Lz_drift, std::abs(angular_momentum(b, s).z() - L0) / scale_L);
    const double u = (s.q * Eigen::Vector3d::UnitZ()).z();
    r.u_min = std::min(r.u_min, u);
    r.u_max = std::max(r.u_max, u);
  }
  return r;
}

// Roots in [−1, 1] of the Lagrange top's cubic f(u) = 2(E' − m g l u)(1 − u²)/A − ((L_z − L_3 u)/A)², by bisection
// on a fine scan (the turning points of cos θ).
std::vector<double> turning_points(double A, double Ep, double mgl, double Lz, double L3) {
  const auto f = [&](double u) { return 2 * (Ep - mgl * u) * (1 - u * u) / A - std::pow((Lz - L3 * u) / A, 2); };
  std::vector<double> roots;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    double a = -1 + 2.0 * i / n, b = -1 + 2.0 * (i + 1) / n;
    if (f(a) == 0) { roots.push_back(a); continue; }
    if (f(a) * f(b) > 0) continue;
    for (int it = 0; it < 200; ++it) {
      const double m = 0.5 * (a + b);
      (f(a) * f(m) <= 0 ? b : a) = m;
    }
    roots.push_back(0.5 * (a + b));
  }
  return roots;
}

}  // namespace

TEST(RigidBody, LagrangeTopNutatesBetweenTheRootsOfItsCubic) {
  RigidBody b;
  b.inertia = {0.05, 0.05, 0.03};
  b.com = {0, 0, 0.1};
  b.mass = 2;
  b.gravity = 9.81;
  // Released at θ0 = 1 rad (57°) with spin 40 rad/s about its axis and no precession: θ̇ = 0 there, so cos θ0
  // is one turning point; the top nutates down to the other.
  RigidState s;
  const double theta0 = 1.0;
  s.q = Eigen::Quaterniond(Eigen::AngleAxisd(theta0, Eigen::Vector3d::UnitX()));
  s.omega = {0, 0, 40};
  const double A = 0.05, mgl = 2 * 9.81 * 0.1, L3 = 0.03 * 40, Lz = angular_momentum(b, s).z();
  const double Ep = energy(b, s) - L3 * L3 / (2 * 0.03);
  const auto roots = turning_points(A, Ep, mgl, Lz, L3);
  ASSERT_GE(roots.size(), 2u);
  const TopRun r = integrate(b, s, 1e-4, 2.0);
  const double lower = roots.front(), upper = roots[1];
  std::printf("  turning points of cos(theta): closed form %.12f, %.12f; integrated %.12f, %.12f; drift E %.2e, "
              "L_z %.2e\n", lower, upper, r.u_min, r.u_max, r.energy_drift, r.Lz_drift);
  EXPECT_NEAR(r.u_max, std::cos(theta0), 1e-9);  // released there at rest in θ (sampled every h: 3.7e-11 short)
  EXPECT_NEAR(r.u_min, lower, 1e-8);
  EXPECT_NEAR(upper, std::cos(theta0), 1e-8);
  EXPECT_LT(r.energy_drift, 1e-10);
  EXPECT_LT(r.Lz_drift, 1e-10);
}

TEST(RigidBody, IntegratorIsOfOrderFour) {
  RigidBody b;
  b.inertia = {0.05, 0.04, 0.03};  // asymmetric, heavy: nothing but the energy and L_z is conserved
  b.com = {0.01, 0.0, 0.1};
  b.mass = 2;
  b.gravity = 9.81;
  RigidState s;
  s.q = Eigen::Quaterniond(Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, 1, 0).normalized()));
  s.omega = {1.0, -2.0, 25.0};
  const double e1 = integrate(b, s, 2e-3, 1.0).energy_drift, e2 = integrate(b, s, 1e-3, 1.0).energy_drift;
  const double order = std::log2(e1 / e2);
  std::printf("  energy drift over 1 s: h = 2e-3 %.3e, h = 1e-3 %.3e: observed order %.2f\n", e1, e2, order);
  EXPECT_GT(order, 3.5);
  EXPECT_LT(order, 4.5);
}

TEST(RigidBody, FreeAsymmetricBodyKeepsItsAngularMomentumVector) {
  RigidBody b;
  b.inertia = {1.0, 2.0, 3.0};  // spun near the intermediate axis: the classic tumbling instability
  RigidState s;
  s.omega = {1e-3, 1.0, 1e-3};
  const Eigen::Vector3d L0 = angular_momentum(b, s);
  double drift = 0, min_wy = 1;
  for (int k = 0; k < 40000; ++k) {  // 40 s at h = 1e-3
    s = rkmk4_step(b, s, 1e-3);
    drift = std::max(drift, (angular_momentum(b, s) - L0).norm() / L0.norm());
    min_wy = std::min(min_wy, s.omega.y());
  }
  std::printf("  free body: |L - L0| / |L0| <= %.2e over 40 s; omega_y reached %.4f (it flips to -1 and back)\n", drift,
              min_wy);
  EXPECT_LT(drift, 1e-10);
  EXPECT_LT(min_wy, -0.99);  // the intermediate axis is unstable: the body turns over
}
