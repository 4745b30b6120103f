#include "boundary_layer_table.hpp"

#include "boundary_layer_response.hpp"
#include "viscous_volume_krylov.hpp"
#include "viscous_volume_response_table.hpp"
#include "viscous_volume_table.hpp"
#include "volume_space.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace rc::modes {
namespace {

using cd = std::complex<double>;

// A row's H = Σ s_i u_i v_iᴴ as rank-one rows at the same λ (a chain takes each row as one mode).
void add_rank_one(std::vector<VolumePole>& rows, cd lambda, const Eigen::MatrixXcd& H) {
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s(i) > 1e-12 * s(0)) rows.push_back({lambda, s(i) * svd.matrixU().col(i) * svd.matrixV().col(i).adjoint()});
}

Eigen::MatrixXcd block(const std::vector<double>& re, const std::vector<double>& im, std::size_t row, int n) {
  Eigen::MatrixXcd H(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const std::size_t k = row * n * n + i * n + j;
      H(i, j) = cd(re[k], im.empty() ? 0.0 : im[k]);
    }
  return H;
}

// A row's H over its directions and its frequency.
struct IdealRow {
  double lambda = 0;
  Eigen::MatrixXcd H;
};

std::vector<IdealRow> table_rows(const ModeTable& ideal) {
  const bool fill = ideal.volume_free_surface.present();
  const int n = fill ? 5 : 3;
  const auto& re = fill ? ideal.volume_free_surface.coupling_re : ideal.volume_cavity.coupling_re;
  const auto& im = fill ? ideal.volume_free_surface.coupling_im : ideal.volume_cavity.coupling_im;
  std::vector<IdealRow> rows;
  for (std::size_t r = 0; r < ideal.lambda.size(); ++r) rows.push_back({ideal.lambda[r], block(re, im, r, n)});
  return rows;
}

// Each row's damping by the layers, read off the boundary-layer response at the row's own frequency: near an isolated
// mode R ≈ H/(s − λ − iΓ), so Γ = H_jj / Im R_jj(λ) on the row's heaviest direction j. A row in a dense cluster or
// under the response's background gets a larger Γ than its own, which a chain's body roots barely feel; where the
// response is not passive there, Γ = Ek^{1/2}. Every row then decays, as the liquid's modes do.
// The frequencies at which row_dampings reads the response: each row's λ (kept off the band's edge, where the
// formulation's 4 − σ² vanishes).
std::vector<cd> row_frequencies(const std::vector<IdealRow>& rows) {
  std::vector<cd> at;
  for (const auto& r : rows) at.emplace_back(std::abs(std::abs(r.lambda) - 2) < 1e-6 ? r.lambda * (1 - 1e-5) : r.lambda, 0);
  return at;
}

std::vector<double> row_dampings(double ekman, const std::vector<IdealRow>& rows, const Eigen::MatrixXcd* R) {
  std::vector<double> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Eigen::Index j = 0;
    rows[i].H.diagonal().real().maxCoeff(&j);
    const double im = R[i](j, j).imag(), h = rows[i].H(j, j).real();
    out.push_back(im > 0 && h > 0 ? std::max(h / im, std::sqrt(ekman) * 1e-3) : std::sqrt(ekman));
  }
  return out;
}

// The ideal rows with their dampings, and the λ = 0 weight G as a purely damped row at i Ek^{1/2} (self-paired:
// H = Re G / 2).
std::vector<VolumePole> damped_rows(const ModeTable& ideal, const std::vector<IdealRow>& rows,
                                    const std::vector<double>& damping, double ekman) {
  std::vector<VolumePole> out;
  for (std::size_t r = 0; r < rows.size(); ++r) add_rank_one(out, cd(rows[r].lambda, damping[r]), rows[r].H);
  const bool fill = ideal.volume_free_surface.present();
  const int n = fill ? 5 : 3;
  const Eigen::MatrixXcd G = fill ? block(ideal.volume_free_surface.geostrophic_re, ideal.volume_free_surface.geostrophic_im, 0, n)
                                  : block(ideal.volume_cavity.geostrophic_re, ideal.volume_cavity.geostrophic_im, 0, n);
  if (G.norm() > 0) add_rank_one(out, cd(0, std::sqrt(ekman)), 0.5 * G.real().cast<cd>());
  return out;
}

// The exact-at frequencies with Re s ≥ 0 (−s̄ is the same frequency to a real liquid), each once.
std::vector<cd> folded(const std::vector<cd>& points) {
  std::vector<cd> out;
  for (cd s : points) {
    if (s.real() < 0) s = -std::conj(s);
    if (std::none_of(out.begin(), out.end(), [&](cd t) { return std::abs(t - s) < 1e-12 * (1 + std::abs(s)); }))
      out.push_back(s);
  }
  return out;
}

// C_e of the dipoles C_e [1/(s − p_e) − 1/(s − p'_e)] (p'_e = p_e + i w, each with its mirror), whose tails fall off
// as 1/|s − p_e|², with Σ_e (dipole e at s_k) = M_k at every exact point: real-linear in C = A + iB, one square system
// for every entry.
cd far_pole(cd p) { return p + cd(0, p.imag()); }

std::vector<Eigen::MatrixXcd> corrections(const std::vector<cd>& s, const std::vector<cd>& p,
                                          const std::vector<Eigen::MatrixXcd>& M) {
  const Eigen::Index E = static_cast<Eigen::Index>(s.size()), rows = M.front().rows(), cols = M.front().cols();
  Eigen::MatrixXd A(2 * E, 2 * E), B(2 * E, rows * cols);
  for (Eigen::Index k = 0; k < E; ++k) {
    for (Eigen::Index e = 0; e < E; ++e) {
      const cd q = far_pole(p[e]);
      const cd g = 1.0 / (s[k] - p[e]) - 1.0 / (s[k] - q), h = 1.0 / (s[k] + std::conj(p[e])) - 1.0 / (s[k] + std::conj(q));
      const cd u = g + h, v = cd(0, 1) * (g - h);
      A(k, e) = u.real();
      A(E + k, e) = u.imag();
      A(k, E + e) = v.real();
      A(E + k, E + e) = v.imag();
    }
    for (Eigen::Index q = 0; q < rows * cols; ++q) {
      B(k, q) = M[k](q / cols, q % cols).real();
      B(E + k, q) = M[k](q / cols, q % cols).imag();
    }
  }
  const Eigen::MatrixXd X = A.fullPivLu().solve(B);
  std::vector<Eigen::MatrixXcd> C;
  for (Eigen::Index e = 0; e < E; ++e) {
    Eigen::MatrixXcd c(rows, cols);
    for (Eigen::Index q = 0; q < rows * cols; ++q) c(q / cols, q % cols) = cd(X(e, q), X(E + e, q));
    C.push_back(c);
  }
  return C;
}

// Each exact point and a companion a step h off it, so that the table's R matches the response's value and slope
// there: a root found near a point then moves with the square of its distance, and remaking the table at the roots
// converges at once (the ideal rows may miss a third of the response where the survey did not settle).
std::vector<cd> with_companions(const std::vector<cd>& points) {
  constexpr double h = 1e-4;
  std::vector<cd> matched;
  for (const cd s : points) matched.insert(matched.end(), {s, s + cd(0, -h)});
  return matched;
}

// Adds the correction dipoles that make the rows' R the response R[e] at every matched point (the companion's dipole
// twice as wide), and records how large they are and how exact the result is.
void add_corrections(std::vector<VolumePole>& rows, const std::vector<cd>& matched, const Eigen::MatrixXcd* R,
                     double width, BoundaryLayerTableResult& r) {
  std::vector<cd> poles;
  std::vector<Eigen::MatrixXcd> mismatch;
  double top = 0;
  for (std::size_t e = 0; e < matched.size(); ++e) {
    const cd s = matched[e];
    poles.emplace_back(s.real() > 1e-6 ? s.real() : width, e % 2 == 0 ? width : 2 * width);
    mismatch.push_back(R[e] - pole_sum(rows, s));
    top = std::max(top, R[e].cwiseAbs().maxCoeff());
  }
  const std::vector<Eigen::MatrixXcd> C = corrections(matched, poles, mismatch);
  for (std::size_t e = 0; e < C.size(); ++e) {
    r.correction = std::max(r.correction, C[e].cwiseAbs().maxCoeff() / top);
    add_rank_one(rows, poles[e], C[e]);
    add_rank_one(rows, far_pole(poles[e]), -C[e]);
  }
  for (std::size_t e = 0; e < matched.size(); ++e)
    r.exact_error = std::max(r.exact_error, (pole_sum(rows, matched[e]) - R[e]).cwiseAbs().maxCoeff() / top);
}

// The table: the ideal table's tensors, the rows, the window and how it was made.
ModeTable table_of(const ModeTable& ideal, const BoundaryLayerTableRequest& request, const BoundaryLayerTableResult& r,
                   const std::vector<VolumePole>& rows, double mesh_h, std::size_t wall_points) {
  ModeTable t = viscous_volume_table_start(ideal, request.mesh, mesh_h, r.unknowns, request.ekman);
  // The λ = 0 weight is a row (damped_rows), as a Krylov table's spin-up is.
  for (auto* g : {&t.volume_cavity.geostrophic_re, &t.volume_cavity.geostrophic_im,
                  &t.volume_free_surface.geostrophic_re, &t.volume_free_surface.geostrophic_im})
    std::fill(g->begin(), g->end(), 0.0);
  add_response_table_rows(t, rows);
  t.fit_lo = request.lo;
  t.fit_hi = request.hi;
  t.fit_error = r.exact_error;
  std::string points;
  for (const cd s : r.exact_at) points += fmt::format("{}{:.6g}{:+.6g}i", points.empty() ? "" : ", ", s.real(), s.imag());
  t.solver = fmt::format(
      "ideal liquid with Ekman layers on its walls (docs/volume.md section 9): the ideal table's rows damped as the "
      "boundary-layer response at each row's frequency says, its lambda = 0 weight spinning up at Ek^(1/2), and {} "
      "correction dipole(s) (poles at Re s + {:g}i, + {:g}i and + {:g}i) making R and its slope the boundary-layer "
      "response's at s = {} (to {:.1e}; the corrections {:.2g} of R there); P{} tetrahedra, {} pressure unknowns, {} "
      "wall points; exact only there: remake it at the roots until they stay",
      2 * r.exact_at.size(), request.width, 2 * request.width, 4 * request.width, points, r.exact_error, r.correction,
      request.mesh.order, r.unknowns, wall_points);
  return t;
}

}  // namespace

BoundaryLayerTableResult boundary_layer_table(const ModeTable& ideal, const BoundaryLayerTableRequest& request) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!(request.ekman > 0 && request.ekman < 1)) throw std::runtime_error("--ekman must be in (0, 1)");
  BoundaryLayerTableResult r;
  r.exact_at = folded(request.exact_at);
  if (r.exact_at.empty())
    throw std::runtime_error("a boundary-layer table is exact where a chain's roots are: give --exact-at (the tank "
                             "frequencies of the roots, e.g. from chain-rom spectrum on the ideal table; remade at "
                             "the root it gives, it settles in one or two rounds: docs/volume.md section 9)");
  const VolumeSpace space(geometry::mesh_volume(request.shape, request.mesh), 0, !(request.shape.fill < 1));
  // One assembly for every frequency: the matched points, then the rows' own.
  const std::vector<cd> matched = with_companions(r.exact_at);
  const std::vector<IdealRow> ideal_rows = table_rows(ideal);
  std::vector<cd> at = matched;
  for (const cd s : row_frequencies(ideal_rows)) at.push_back(s);
  const BoundaryLayerResponse bl = boundary_layer_response(space, request.ekman, at);
  r.unknowns = bl.unknowns;
  const Eigen::MatrixXcd* at_rows = bl.R.data() + matched.size();
  std::vector<VolumePole> rows =
      damped_rows(ideal, ideal_rows, row_dampings(request.ekman, ideal_rows, at_rows), request.ekman);
  add_corrections(rows, matched, bl.R.data(), request.width, r);
  r.table = table_of(ideal, request, r, rows, space.mesh().size, bl.wall_points);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.table.wall_seconds = r.seconds + ideal.wall_seconds;
  r.table.sort_by_energy();
  r.table.validate();
  return r;
}

}  // namespace rc::modes
