#include "free_surface_survey.hpp"

#include "block_clusters.hpp"
#include "block_lanczos.hpp"
#include "lanczos.hpp"
#include "progress.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace rc::modes {
namespace {

constexpr int kEmptyWindow = 48;  // basis vectors after which a shift's window without heavy weight ends the run

constexpr int kN = FreeSurfaceDynamics::kDirections;

// The start block: U_x, U_y, U_z, T̂_x, T̂_y and each times i (the real form of a complex space).
Eigen::MatrixXd start_block(const FreeSurfaceDynamics& A) {
  Eigen::MatrixXd B(A.size(), 2 * kN);
  for (int j = 0; j < kN; ++j) B.col(j) = A.direction(j);
  for (int j = 0; j < kN; ++j) B.col(kN + j) = A.times_i(B.col(j));
  return B;
}

std::vector<FreeSurfaceMode> free_surface_clusters(std::vector<BlockGaussNode> rule, double width) {
  return block_clusters<FreeSurfaceMode, kN>(std::move(rule), width);
}

// The rule's clusters of Lanczos on `apply` from `start`, λ = map(θ) and the bound on λ's distance to an eigenvalue
// from the Ritz residual r: r itself for A; r/θ² for (A − σ)⁻¹ (an eigenvalue 1/(λ − σ) lies within r of θ). Checked
// every two blocks: `done` ends the run early (at most `columns` basis vectors).
template <class Map, class Bound, class Done>
std::vector<FreeSurfaceMode> run_rule(const FreeSurfaceDynamics& A, const Eigen::MatrixXd& start,
                                      const BlockLanczos::Apply& apply, int columns, Map map, Bound bound, double width,
                                      Done done) {
  BlockLanczos lanczos(A.weights(), start, columns);
  std::vector<FreeSurfaceMode> out;
  for (int block = 1;; ++block) {
    const bool more = lanczos.step(apply);
    progress_tick();
    if (more && block % 2 != 0) continue;
    auto rule = lanczos.rule();
    for (auto& n : rule) {
      n.residual = bound(n.lambda, n.residual);
      n.lambda = map(n.lambda);
    }
    out = free_surface_clusters(std::move(rule), width);
    if (!more || done(out, lanczos.columns())) return out;
  }
}

bool known(const std::vector<FreeSurfaceMode>& modes, double lambda, double width) {
  return std::any_of(modes.begin(), modes.end(), [&](const auto& m) { return within_width(lambda, m.lambda, width); });
}

// A shift's window's light clusters: a dense band of discrete modes none of which is heavy alone. Their weight is the
// measure's in the window (the shifted rule resolves it there), tabled as one unsettled row at its mean λ, so that it
// is not lost when no single mode carries it; a part an earlier shift's window held is left to that one. None when
// the band's weight is below `heavy`.
template <class Heavy>
std::optional<FreeSurfaceMode> light_band(const std::vector<FreeSurfaceMode>& near, double sigma,
                                          const std::vector<double>& shifted, const FreeSurfaceSurveySettings& s,
                                          Heavy is_heavy, double heavy) {
  const auto in = [&](double lambda, double x) { return std::abs(lambda - x) <= s.window * lambda_scale(x); };
  FreeSurfaceMode band;
  double first = 0, second = 0;
  for (const auto& m : near) {
    if (is_heavy(m) || m.lambda <= s.lambda_floor || !in(m.lambda, sigma)) continue;
    if (std::any_of(shifted.begin(), shifted.end(), [&](double x) { return in(m.lambda, x); })) continue;
    const double w = m.H.trace().real();
    band.H += m.H;
    band.members += m.members;
    band.residual = std::max(band.residual, m.residual);
    first += w * m.lambda;
    second += w * m.lambda * m.lambda;
  }
  const double w = band.H.trace().real();
  if (!(w >= heavy)) return std::nullopt;
  band.lambda = first / w;
  band.spread = std::sqrt(std::max(0.0, second / w - band.lambda * band.lambda));
  band.residual = std::max({band.residual, band.spread, 2 * s.residual_tolerance * lambda_scale(band.lambda)});
  return band;
}

}  // namespace

FreeSurfaceSurvey survey_free_surface_modes(const FreeSurfaceDynamics& A, const FreeSurfaceSurveySettings& s) {
  const Eigen::MatrixXd B = start_block(A);
  FreeSurfaceSurvey out;
  const Eigen::Index nv = A.velocity_size();
  for (int j = 0; j < kN; ++j)
    for (int k = 0; k < kN; ++k) {
      out.gram(j, k) = {A.inner(B.col(j), B.col(k)), A.inner(B.col(j), B.col(kN + k))};
      const auto n = B.rows() - nv;  // the surface part: the directions' η are real
      out.surface_gram(j, k) = B.col(j).tail(n).dot(A.weights().tail(n).cwiseProduct(B.col(k).tail(n)));
    }
  const double heavy = s.floor * out.gram.trace().real();
  const auto is_heavy = [&](const FreeSurfaceMode& m) { return m.lambda > s.lambda_floor && m.H.trace().real() >= heavy; };
  const auto settled = [&](const FreeSurfaceMode& m) { return m.residual <= s.residual_tolerance * lambda_scale(m.lambda); };
  out.rule = run_rule(A, B, [&](const Eigen::VectorXd& in, Eigen::VectorXd& o) { A.apply(in, o); }, s.plain_columns,
                      [](double t) { return t; }, [](double, double r) { return r; }, s.merge_width,
                      [](const auto&, int) { return false; });
  out.columns = s.plain_columns;
  std::vector<FreeSurfaceMode> pending;
  std::vector<double> shifted;  // the shifts' σ, in order
  for (const auto& m : out.rule) {
    out.total += m.H;
    if (!is_heavy(m)) continue;
    (settled(m) ? out.modes : pending).push_back(m);
  }
  std::sort(pending.begin(), pending.end(), [](const auto& a, const auto& b) { return a.H.trace().real() > b.H.trace().real(); });
  for (const auto& node : pending) {
    // A shift's window held it: its weight is there, settled or named unsettled (so that no weight is counted twice).
    if ((known(out.modes, node.lambda, s.window) || known(out.unsettled, node.lambda, s.window)) && out.shifts > 0) continue;
    if (out.shifts >= s.max_shifts) {
      out.unsettled.push_back(node);
      continue;
    }
    const double sigma = node.lambda * (1 + 1e-3);  // just off: a node may sit on its eigenvalue
    const FreeSurfaceShiftedInverse inverse(A, sigma);
    ++out.shifts;
    const auto in_window = [&](const FreeSurfaceMode& m) {
      return is_heavy(m) && std::abs(m.lambda - sigma) <= s.window * lambda_scale(sigma);
    };
    // Done when the window's heavy weight has all settled, or when it holds none after kEmptyWindow columns (the plain
    // node was a Gauss average over light eigenvalues, not a mode).
    const auto done = [&](const std::vector<FreeSurfaceMode>& rule, int columns) {
      bool any = false;
      for (const auto& m : rule)
        if (in_window(m)) {
          if (!settled(m)) return false;
          any = true;
        }
      return any || columns >= kEmptyWindow;
    };
    const auto near = run_rule(A, B, [&](const Eigen::VectorXd& in, Eigen::VectorXd& o) { inverse.apply(in, o); },
                               s.shift_columns, [sigma](double t) { return sigma + 1 / t; },
                               [](double t, double r) { return r / (t * t); }, s.merge_width, done);
    if (auto band = light_band(near, sigma, shifted, s, is_heavy, heavy)) out.unsettled.push_back(*band);
    shifted.push_back(sigma);
    for (const auto& m : near) {
      if (!in_window(m)) continue;
      if (!settled(m)) {
        if (!known(out.unsettled, m.lambda, s.merge_width)) out.unsettled.push_back(m);
      } else if (!known(out.modes, m.lambda, s.merge_width)) {
        out.modes.push_back(m);
      }
    }
  }
  // A node still unsettled that a later shift settled is that mode; unsettled weight merely near a mode stays named.
  std::erase_if(out.unsettled, [&](const auto& m) { return known(out.modes, m.lambda, s.merge_width); });
  std::sort(out.modes.begin(), out.modes.end(), [](const auto& a, const auto& b) { return a.transverse() > b.transverse(); });
  return out;
}

}  // namespace rc::modes
