// Mode tables from the closed forms of docs/physics.md §2 (rho = 1, omega0 = 1), written with
// rc::write_mode_table: they stand in for cavity-modes output in the chain-rom tests.
#pragma once

#include "mode_table.hpp"

#include <cmath>
#include <filesystem>

namespace rc::rom::test {

// Sphere of radius R: one coupling mode, lambda = 1 (kappa = 2), E = A_f = (8 pi/15) R^5, J_zh = 0.
inline rc::ModeTable sphere_table(double R) {
  rc::ModeTable t;
  t.shape = "sphere";
  t.dimensions = {{"radius", R}};
  t.m = 1;
  t.volume = 4.0 / 3.0 * M_PI * R * R * R;
  t.A_f = t.C_f = 8.0 * M_PI / 15.0 * std::pow(R, 5);
  t.J_zh = 0;
  t.sum_rule = t.A_f;
  t.coverage = 1;
  t.solver = "closed form (docs/physics.md §2)";
  t.normalisation = "N2 = 1, a = sqrt(E/2)";
  t.kappa = {2.0};
  t.lambda = {1.0};
  t.E = {t.A_f};
  t.a = {std::sqrt(t.A_f / 2)};
  t.N2 = {1.0};
  t.residual = {0.0};
  return t;
}

// Spheroid, equatorial semi-axis a, polar c: lambda = 2a^2/(a^2+c^2), E = (4/5) m a^2 c^2/(a^2+c^2),
// J_zh = m (a^2-c^2)^2 / (5 (a^2+c^2)), A_f = m (a^2+c^2)/5, C_f = 2 m a^2/5.
inline rc::ModeTable spheroid_table(double a, double c) {
  rc::ModeTable t;
  t.shape = "spheroid";
  t.dimensions = {{"a", a}, {"c", c}};
  t.m = 1;
  t.volume = 4.0 / 3.0 * M_PI * a * a * c;
  const double m = t.volume, s = a * a + c * c;
  t.A_f = m * s / 5;
  t.C_f = 2 * m * a * a / 5;
  t.J_zh = m * (a * a - c * c) * (a * a - c * c) / (5 * s);
  t.sum_rule = t.A_f - t.J_zh;
  t.coverage = 1;
  t.solver = "closed form (docs/physics.md §2)";
  t.normalisation = "N2 = 1, a = sqrt(E/2)";
  const double lam = 2 * a * a / s;
  t.lambda = {lam};
  t.kappa = {2 / lam};
  t.E = {0.8 * m * a * a * c * c / s};
  t.a = {std::sqrt(t.E[0] / 2)};
  t.N2 = {1.0};
  t.residual = {0.0};
  return t;
}

inline std::filesystem::path write_table(const rc::ModeTable& t, const std::filesystem::path& p) {
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  rc::write_mode_table(t, p);
  return p;
}

}  // namespace rc::rom::test
