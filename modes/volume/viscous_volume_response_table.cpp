#include "viscous_volume_response_table.hpp"

#include "viscous_volume_run.hpp"
#include "viscous_volume_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace rc::modes {
namespace {

// The window's frequencies and three more between each two: where the estimate is scanned.
std::vector<double> refined(const std::vector<double>& window) {
  std::vector<double> out;
  for (std::size_t k = 0; k < window.size(); ++k) {
    if (k > 0)
      for (int j = 1; j < 4; ++j) out.push_back(window[k - 1] + (window[k] - window[k - 1]) * j / 4);
    out.push_back(window[k]);
  }
  return out;
}

// The geometric tail beyond the window (1.5 × max(σ_max, 1) … 1000 ×, factor 1.5), the response's far side, which a
// chain's high frequencies see; σ < 0 is the same response conjugated (viscous_volume_krylov.hpp).
std::vector<double> tail(double hi) {
  const double reach = std::max(hi, 1.0);
  std::vector<double> out;
  for (double t = 1.5 * reach; t <= 1000 * reach; t *= 1.5) out.push_back(t);
  return out;
}

// max over the frequencies and entries of |R_rows − R_G| / scale: the pole–residue form against the model it comes
// from (they part where the reduced eigenvectors are ill-conditioned).
double rows_error(const VolumeKrylovReduction& k, const std::vector<VolumePole>& poles, const std::vector<double>& s) {
  double worst = 0;
  for (const double x : s)
    worst = std::max(worst, ((pole_sum(poles, x) - k.model(x)).cwiseAbs().array() / k.scale.array()).maxCoeff());
  return worst;
}

std::string solver_line(const VolumeResponseTableRequest& req, const VolumeResponseTableResult& r,
                        std::size_t window, const std::vector<double>& beyond) {
  const VolumeKrylovReduction& k = r.reduction;
  return fmt::format(
      "Galerkin (Hermitian) projection of the {} on J-symmetric rational Krylov spaces (docs/volume.md "
      "section 7, \"The response table\"): {} expansion points chosen greedily on {} frequencies of [{:g}, {:g}] and "
      "{} beyond it up to {:.3g}{}, {} vectors per input and point, {} primal and {} dual basis vectors, {} poles; "
      "dual-weighted residual estimate at most {:.2g} of each entry's scale, measured by a forced solve at its worst, "
      "s = {:.6g}: {:.2g}{}; the rows against the reduced model {:.2g}; Taylor-Hood P{}/P{}, {} unknowns",
      req.shape.fill < 1 ? "partially filled tank's 5 x 5 response (docs/volume.md section 8)" : "3 x 3 response",
      k.points.size(), window, req.window.front(), req.window.back(), beyond.size(), beyond.back(),
      req.krylov.exact_at.empty() ? std::string() : fmt::format(", and {} more at the given frequencies (--exact-at), "
                                                                "where R is exact", req.krylov.exact_at.size()),
      req.krylov.vectors_per_point, k.primal_vectors,
      k.dual_vectors, r.poles.size(), k.estimate, k.check_point, k.check_error,
      k.within_tolerance ? "" : fmt::format(" (NOT within --max-fit-error {:.2g})", req.krylov.tolerance),
      r.rows_error, req.mesh.order, req.mesh.order - 1, r.unknowns);
}

}  // namespace

void add_response_table_rows(ModeTable& t, const std::vector<VolumePole>& poles) {
  auto& vf = t.volume_free_surface;  // a partially filled tank's (docs/volume.md §8): its five directions' residues
  for (const VolumePole& p : poles) {
    add_viscous_volume_row(t, {p.lambda.real(), std::max(p.lambda.imag(), 0.0)}, p.H.topLeftCorner<3, 3>(), 0.0);
    if (!vf.present()) continue;
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        vf.coupling_re.push_back(p.H(i, j).real());
        vf.coupling_im.push_back(p.H(i, j).imag());
      }
  }
  t.normalisation = "3-D viscous response table: each row a pole lambda + i decay of the response with its "
                    "rank-one residue H (its conjugate at -conj(lambda) implied; a row with lambda = 0 carries half "
                    "its own), R(s) = sum H/(s - lambda) + conj(H)/(s + conj(lambda)); E + i E_imag = H_xx + H_yy, "
                    "a + i a_imag = sqrt((E + i E_imag)/2), N2 = 1 (docs/volume.md section 7)";
  if (vf.present()) t.normalisation += "; a partially filled tank's H over (U_x, U_y, U_z, T_x, T_y) about P0 (section 8)";
  double kept = 0;
  for (const double E : t.E) kept += E;
  t.coverage = t.sum_rule > 0 ? kept / t.sum_rule : 0;
}

VolumeResponseTableResult viscous_volume_response_table(const ModeTable* ideal,
                                                        const VolumeResponseTableRequest& request,
                                                        const std::function<void(const std::string&)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const ViscousVolumeSystem system = viscous_volume_system(request.shape, request.mesh, request.ekman, progress);
  const std::vector<double> window = refined(request.window), beyond = tail(request.window.back());
  VolumeResponseTableResult r;
  r.reduction = volume_krylov_reduction(system.forms, window, beyond, request.krylov, progress);
  r.poles = volume_poles(r.reduction.model);
  std::vector<double> scanned = window;
  scanned.insert(scanned.end(), beyond.begin(), beyond.end());
  r.rows_error = rows_error(r.reduction, r.poles, scanned);
  r.unknowns = system.space->size();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!ideal) return r;

  ModeTable& t = r.table;
  t = viscous_volume_table_start(*ideal, request.mesh, system.space->geometry().mesh().size, r.unknowns, request.ekman);
  // The rows hold the viscous spin-up that the ideal fluid's λ = 0 weight stands for elsewhere.
  std::fill(t.volume_cavity.geostrophic_re.begin(), t.volume_cavity.geostrophic_re.end(), 0.0);
  std::fill(t.volume_cavity.geostrophic_im.begin(), t.volume_cavity.geostrophic_im.end(), 0.0);
  auto& vf = t.volume_free_surface;  // a partially filled tank's (docs/volume.md §8): its five directions' residues
  std::fill(vf.geostrophic_re.begin(), vf.geostrophic_re.end(), 0.0);
  std::fill(vf.geostrophic_im.begin(), vf.geostrophic_im.end(), 0.0);
  add_response_table_rows(t, r.poles);
  t.fit_lo = request.window.front();
  t.fit_hi = request.window.back();
  t.fit_error = std::max({r.reduction.estimate, r.reduction.check_error, r.rows_error});
  t.solver = solver_line(request, r, window.size(), beyond);
  t.wall_seconds = r.seconds + ideal->wall_seconds;
  t.sort_by_energy();
  t.validate();
  return r;
}

}  // namespace rc::modes
