#include "free_surface_table.hpp"

#include "volume_table.hpp"

#include <cmath>

namespace rc::modes {
namespace {

// H's leading n × n block, row-major, into (re, im).
void append_block(const Hermitian5& H, int n, std::vector<double>& re, std::vector<double>& im) {
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) {
      re.push_back(H(j, k).real());
      im.push_back(H(j, k).imag());
    }
}

std::vector<double> flat_rows(const Tensor3& t) {
  std::vector<double> v;
  for (const auto& row : t) v.insert(v.end(), row.begin(), row.end());
  return v;
}

}  // namespace

ModeTable free_surface_table(const FreeSurfaceRunResult& r, const geometry::VolumeShapeSpec& shape,
                             const FreeSurfaceSurveySettings& settings) {
  const FreeSurfaceSurvey& s = r.survey;
  ModeTable t;
  t.shape = shape.kind;
  t.dimensions = shape.dims;
  t.fe_order = r.order;
  t.mesh_h = r.mesh_size;
  t.ndof = r.pressure_dofs;
  t.volume = r.liquid.volume;
  t.centroid_z = r.liquid.centroid[2];
  const Tensor3& I = r.liquid.inertia;
  t.A_f = 0.5 * (I[0][0] + I[1][1]);
  t.C_f = I[2][2];
  // About P0 (the frozen inertia moved there from C by the parallel-axis theorem): J_D = I_f(P0) + K − Gram.
  const double m = r.liquid.volume, dx = r.liquid.centroid[0] - r.axis_point[0], dy = r.liquid.centroid[1] - r.axis_point[1];
  const Eigen::Vector3d d(dx, dy, 0);
  Eigen::Matrix3d IP0;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) IP0(j, k) = I[j][k];
  IP0 += m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  const Eigen::Matrix3d gram = s.gram.topLeftCorner<3, 3>().real(), K = s.surface_gram.topLeftCorner<3, 3>();
  const Eigen::Matrix3d J = IP0 + K - gram;
  t.sum_rule = 0.5 * (gram(0, 0) + gram(1, 1));
  t.J_zh = t.A_f + 0.5 * (K(0, 0) + K(1, 1)) - t.sum_rule;  // the identity sum_rule = A_f + K − J_zh (docs/volume.md §8)
  t.solver = "block Lanczos Gauss rule of the free-surface operator's coupling measure, five directions, plain then "
             "shift-and-invert (docs/volume.md §8)";
  t.tolerance = settings.residual_tolerance;  // a row above it did not settle (chain-rom says so: general_tank.cpp)
  t.normalisation = "3-D partial fill: H = c c^H over (U_x, U_y, U_z, T_x, T_y) about the spin axis's point at the "
                    "centroid's height, |W| = 1 (docs/volume.md §8); a = sqrt(E/2), N2 = 1";
  auto& v = t.volume_cavity;
  v.centroid.assign(r.liquid.centroid.begin(), r.liquid.centroid.end());
  v.tilt = shape.tilt;
  v.inertia = flat_rows(I);
  Hermitian5 geo = Hermitian5::Zero();
  for (const auto& n : s.rule)
    if (std::abs(n.lambda) <= settings.lambda_floor) geo += n.H;
  geo = 0.5 * (geo + geo.adjoint()).eval();
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) {
      v.zhukovsky.push_back(J(j, k));
      v.sum_rule.push_back(gram(j, k));
      v.geostrophic_re.push_back(geo(j, k).real());
      v.geostrophic_im.push_back(geo(j, k).imag());
    }
  auto& f = t.volume_free_surface;
  f.fill = shape.fill;
  f.radius = r.surface_radius;
  f.axis = {shape.spin_axis[0], shape.spin_axis[1]};
  append_block(Hermitian5(0.5 * (s.gram + s.gram.adjoint())), 5, f.gram_re, f.gram_im);
  append_block(geo, 5, f.geostrophic_re, f.geostrophic_im);
  for (int j = 0; j < 5; ++j)
    for (int k = 0; k < 5; ++k) f.surface_gram.push_back(0.5 * (s.surface_gram(j, k) + s.surface_gram(k, j)));
  double kept = 0;
  std::vector<FreeSurfaceMode> rows = s.modes;  // the unsettled weight too, as rows whose bound says so (docs/cones.md)
  rows.insert(rows.end(), s.unsettled.begin(), s.unsettled.end());
  for (const auto& md : rows) {
    const Hermitian5 H = 0.5 * (md.H + md.H.adjoint());
    const double E = (H(0, 0) + H(1, 1)).real();
    push_ideal_volume_row(t, md.lambda, E, md.residual, md.spread, md.members);
    append_block(H, 3, v.coupling_re, v.coupling_im);
    append_block(H, 5, f.coupling_re, f.coupling_im);
    kept += E;
  }
  t.coverage = t.sum_rule > 0 ? kept / t.sum_rule : 0;
  t.sort_by_energy();
  t.validate();
  return t;
}

}  // namespace rc::modes
