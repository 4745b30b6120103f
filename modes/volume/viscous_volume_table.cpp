#include "viscous_volume_table.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

#include <fmt/format.h>

namespace rc::modes {
namespace {

// Two targets may lead the shift-and-invert search to one damped mode: refused, as its weight would count twice.
void refuse_repeated_modes(const ViscousVolumeRequest& request, const ViscousVolumeResult& result) {
  for (std::size_t i = 0; i < result.modes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (std::abs(result.modes[i].lambda - result.modes[j].lambda) < 1e-8 * std::abs(result.modes[i].lambda))
        throw std::runtime_error(fmt::format("the targets {} and {} found the same damped mode (lambda = {:.8f}): give "
                                             "each mode's target once",
                                             request.targets[j], request.targets[i], result.modes[i].lambda.real()));
}

// The convergence columns, row by row in the targets' order (before the rows are sorted).
void add_convergence(ModeTable& t, const ViscousVolumeResult& fine, const ViscousVolumeCheck& check) {
  if (check.coarse->modes.size() != fine.modes.size())
    throw std::runtime_error("the convergence check found another number of modes than the table");
  for (std::size_t i = 0; i < fine.modes.size(); ++i) {
    const DampedVolumeMode &f = fine.modes[i], &c = check.coarse->modes[i];
    const std::complex<double> Ef = f.H(0, 0) + f.H(1, 1), Ec = c.H(0, 0) + c.H(1, 1);
    t.dlambda.push_back(std::abs(f.lambda - c.lambda) / std::abs(f.lambda));
    t.dE.push_back(std::abs(Ef - Ec) / std::abs(Ef));
    t.converged.push_back(t.dlambda.back() < check.tolerance && t.dE.back() < check.tolerance ? 1 : 0);
  }
  t.convergence_reference = check.reference;
  t.convergence_tolerance = check.tolerance;
}

}  // namespace

void add_viscous_volume_row(ModeTable& t, std::complex<double> lambda, const Eigen::Matrix3cd& H, double residual) {
  const std::complex<double> E = H(0, 0) + H(1, 1), a = std::sqrt(E / 2.0);
  t.lambda.push_back(lambda.real());
  t.decay.push_back(lambda.imag());
  t.kappa.push_back(lambda.real() == 0 ? 0.0 : 2 / lambda.real());  // a purely damped row has no wavelength
  t.E.push_back(E.real());
  t.E_imag.push_back(E.imag());
  t.a.push_back(a.real());
  t.a_imag.push_back(a.imag());
  t.N2.push_back(1);
  t.residual.push_back(residual);
  t.members.push_back(1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      t.volume_cavity.coupling_re.push_back(H(i, j).real());
      t.volume_cavity.coupling_im.push_back(H(i, j).imag());
    }
}

ModeTable viscous_volume_table_start(const ModeTable& ideal, const geometry::MeshOptions& mesh, double mesh_h,
                                     int unknowns, double ekman) {
  ModeTable t;
  t.shape = ideal.shape;
  t.dimensions = ideal.dimensions;
  t.volume = ideal.volume;
  t.centroid_z = ideal.centroid_z;
  t.A_f = ideal.A_f;
  t.C_f = ideal.C_f;
  t.J_zh = ideal.J_zh;
  t.sum_rule = ideal.sum_rule;
  t.volume_cavity = ideal.volume_cavity;
  t.volume_cavity.coupling_re.clear();
  t.volume_cavity.coupling_im.clear();
  // The bands are the ideal fluid's measure (docs/volume.md §5): a viscous table keeps its damped rows only.
  t.volume_cavity.band_coupling_re.clear();
  t.volume_cavity.band_coupling_im.clear();
  t.volume_cavity.band_lambda.clear();
  // A partially filled tank's surface, axis and static parts stay; its rows are the viscous table's.
  t.volume_free_surface = ideal.volume_free_surface;
  t.volume_free_surface.coupling_re.clear();
  t.volume_free_surface.coupling_im.clear();
  t.fe_order = mesh.order;
  t.mesh_h = mesh_h;
  t.mesh_h_wall = mesh.wall_size;
  t.ndof = unknowns;
  t.ekman = ekman;
  t.tolerance = ideal.tolerance;
  return t;
}

ModeTable viscous_volume_table(const ModeTable& ideal, const ViscousVolumeRequest& request,
                               const ViscousVolumeResult& result, const ViscousVolumeCheck& check) {
  refuse_repeated_modes(request, result);
  ModeTable t = viscous_volume_table_start(ideal, request.mesh, result.mesh_h, result.unknowns, request.ekman);
  t.solver = "3-D Taylor-Hood P" + std::to_string(request.mesh.order) + "/P" + std::to_string(request.mesh.order - 1) +
             ", shift-and-invert Krylov-Schur on the damped pencil, left vectors by transposed inverse iteration "
             "(docs/volume.md §7); tensors from the ideal table (" + std::to_string(ideal.ndof) + " unknowns)";
  t.normalisation = "3-D viscous: H = (f^T x)(f^T y)^T, y^T M x = 1 (docs/volume.md §7); E + i E_imag = H_xx + H_yy, "
                    "a + i a_imag = sqrt((E + i E_imag)/2), N2 = 1";
  for (const DampedVolumeMode& m : result.modes)
    add_viscous_volume_row(t, m.lambda, m.H, std::max(m.residual, m.left_residual));
  if (check.coarse) add_convergence(t, result, check);
  double kept = 0;
  for (double E : t.E) kept += E;
  t.coverage = t.sum_rule > 0 ? kept / t.sum_rule : 0;
  t.wall_seconds = result.seconds + ideal.wall_seconds + (check.coarse ? check.coarse->seconds : 0.0);
  t.sort_by_energy();
  t.validate();
  return t;
}

}  // namespace rc::modes
