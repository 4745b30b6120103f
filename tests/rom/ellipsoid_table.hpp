// The triaxial ellipsoid's closed-form 3-D table (docs/volume.md §3 and §5), written as cavity-modes writes one: the
// spin-over mode, the geostrophic weight, the frozen and Zhukovsky tensors from modes/volume/ellipsoid_closed_form.
// For the chain-rom tests of tanks without axial symmetry (test_general_chain.cpp, rom-ellipsoid-table).
#pragma once

#include "ellipsoid_closed_form.hpp"
#include "mode_table.hpp"

#include <cmath>
#include <vector>

namespace rc::rom::test {

inline std::vector<double> row_major(const Eigen::Matrix3d& m) {
  std::vector<double> v;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v.push_back(m(i, j));
  return v;
}

// Semi-axes a, b, c (table units), the c axis turned by `tilt` (radians) about x as `cavity-modes ellipsoid --tilt`.
inline rc::ModeTable ellipsoid_table(double a, double b, double c, double tilt) {
  const modes::EllipsoidModes e = modes::ellipsoid_modes(a, b, c, tilt);
  rc::ModeTable t;
  t.shape = "ellipsoid";
  t.dimensions = {{"a", a}, {"b", b}, {"c", c}};
  t.m = 1;
  t.volume = e.mass;
  auto& v = t.volume_cavity;
  v.centroid = {0, 0, 0};
  v.tilt = tilt;
  v.inertia = row_major(e.inertia);
  v.zhukovsky = row_major(e.zhukovsky);
  v.sum_rule = row_major(e.inertia - e.zhukovsky);
  v.geostrophic_re = row_major(e.geostrophic);
  v.geostrophic_im = row_major(Eigen::Matrix3d::Zero());
  v.coupling_re = row_major(e.H.real());
  v.coupling_im = row_major(e.H.imag());
  t.A_f = 0.5 * (e.inertia(0, 0) + e.inertia(1, 1));
  t.C_f = e.inertia(2, 2);
  t.J_zh = 0.5 * (e.zhukovsky(0, 0) + e.zhukovsky(1, 1));
  t.sum_rule = t.A_f - t.J_zh;
  t.coverage = 1;
  t.solver = "closed form (docs/volume.md §3)";
  t.normalisation = "N2 = 1, a = sqrt(E/2)";
  const double E = (e.H(0, 0) + e.H(1, 1)).real();
  t.lambda = {e.lambda};
  t.kappa = {2 / e.lambda};
  t.E = {E};
  t.a = {std::sqrt(E / 2)};
  t.N2 = {1};
  t.residual = {0};
  return t;
}

}  // namespace rc::rom::test
