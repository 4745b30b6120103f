#include "volume_survey.hpp"

#include "block_clusters.hpp"
#include "lanczos.hpp"
#include "progress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace rc::modes {
namespace {

// Clusters of a rule sorted by λ (block_clusters.hpp).
std::vector<VolumeMode> clusters(std::vector<BlockGaussNode> rule, double width) {
  return block_clusters<VolumeMode, 3>(std::move(rule), width);
}

double relative_change(const Hermitian3& a, const Hermitian3& b) {
  const double n = a.norm();
  return n > 0 ? (a - b).norm() / n : 0.0;
}

// The heavy clusters in [lo, hi], with their change against the previous check's clusters.
std::vector<VolumeMode> watched(const std::vector<VolumeMode>& now, const std::vector<VolumeMode>& before, double lo,
                                double hi, double heavy) {
  std::vector<VolumeMode> out;
  for (VolumeMode m : now) {
    if (m.lambda < lo || m.lambda > hi || m.H.trace().real() < heavy) continue;
    m.dlambda = m.dH = std::numeric_limits<double>::infinity();
    for (const auto& b : before)
      if (std::abs(b.lambda - m.lambda) < m.dlambda) {
        m.dlambda = std::abs(b.lambda - m.lambda);
        m.dH = relative_change(m.H, b.H);
      }
    out.push_back(m);
  }
  return out;
}

// Stopped moving: λ and H changed less than the tolerances between two checks.
bool still(const VolumeMode& m, const VolumeSurveySettings& s) {
  return m.dlambda <= s.lambda_tolerance * lambda_scale(m.lambda) && m.dH <= s.weight_tolerance;
}

// A mode: still, and its Ritz vector an eigenvector (a Gauss node can stop moving long before that in a dense
// spectrum; its λ is good to about the residual² over the gap).
bool settled(const VolumeMode& m, const VolumeSurveySettings& s) {
  return still(m, s) && m.residual <= s.residual_tolerance * lambda_scale(m.lambda);
}

struct RuleRun {
  std::vector<VolumeMode> all, watch;  // the last rule's clusters; the watched ones with their last change
  int columns = 0;
  bool exhausted = false;
};

// Block Lanczos until `finished` says so of the heavy clusters in [lo, hi] (with their last change) or the budget is
// spent; `map` takes the operator's Ritz value to λ (the identity for A, σ + 1/θ for (A − σ)⁻¹), `residual_map` its
// Ritz residual to a bound on ‖(A − λ) z‖.
using Finished = std::function<bool(const std::vector<VolumeMode>&)>;
template <class Map, class ResidualMap>
RuleRun run_rule(const VolumeVelocity& V, const Eigen::MatrixXd& start, const BlockLanczos::Apply& apply, int columns,
                 Map map, ResidualMap residual_map, double lo, double hi, double heavy, const VolumeSurveySettings& s,
                 const Finished& finished) {
  BlockLanczos lanczos(V.weights(), start, columns, V.comm());
  RuleRun run;
  std::vector<VolumeMode> before;
  bool more = true;
  for (int block = 1; more; ++block) {
    more = lanczos.step(apply);
    if (block % s.check_every != 0 && more) continue;
    auto rule = lanczos.rule();
    for (auto& n : rule) {
      const double theta = n.lambda;
      n.lambda = map(theta);
      n.residual = residual_map(theta, n.residual);
    }
    run.all = clusters(std::move(rule), s.merge_width);
    if (lanczos.exhausted()) before = run.all;  // the rule is exact
    run.watch = watched(run.all, before, lo, hi, heavy);
    before = run.all;
    if (block > s.check_every && finished(run.watch)) break;
  }
  run.columns = lanczos.columns();
  run.exhausted = lanczos.exhausted();
  return run;
}


// The heavy clusters of `watch` within the smallest window about σ that holds any: s.window · max(|σ|, 0.1), widened
// ×4 up to kWidenings times (a plain Gauss node stands for weight spread over eigenvalues near it, not at it).
constexpr int kWidenings = 4;
std::vector<VolumeMode> nearest_heavy(const std::vector<VolumeMode>& watch, double sigma, const VolumeSurveySettings& s) {
  double half = s.window * lambda_scale(sigma);
  for (int k = 0; k <= kWidenings; ++k, half *= 4) {
    std::vector<VolumeMode> in;
    for (const auto& m : watch)
      if (std::abs(m.lambda - sigma) <= half) in.push_back(m);
    if (!in.empty()) return in;
  }
  return {};
}

// A shift-and-invert run at σ: until the heavy clusters nearest σ (nearest_heavy) have settled. Returns them (settled
// or not) in `watch`.
RuleRun shift_invert_run(const VolumeVelocity& V, const PoincareForms& real, const Eigen::MatrixXd& start,
                         double sigma, double heavy, const VolumeSurveySettings& s) {
  const PMat Q = shifted_real_pencil(real, sigma);
  const StiffnessSolver factor(Q, "shift_", fmt::format("the 3-D Q(sigma) at sigma = {:.9g}", sigma));
  const double c = sigma * (sigma * sigma - 4);
  std::vector<double> g, p;
  Eigen::VectorXd t;
  const auto apply = [&](const Eigen::VectorXd& u, Eigen::VectorXd& v) {
    v = u;
    VolumeVelocity::shifted_coriolis_inverse(sigma, v);
    V.divergence(v, g);
    for (double& x : g) x *= c;
    factor.solve(g, p);
    t.setZero(v.size());
    V.add_gradient(p, 1.0, t);
    VolumeVelocity::shifted_coriolis_inverse(sigma, t);
    v += t;
  };
  double widest = s.window * lambda_scale(sigma);
  for (int k = 0; k < kWidenings; ++k) widest *= 4;
  const Finished finished = [&](const std::vector<VolumeMode>& watch) {
    const auto near = nearest_heavy(watch, sigma, s);
    // Nothing heavy in the widest window: the plain node was a Gauss average over light eigenvalues, not a mode.
    return std::all_of(near.begin(), near.end(), [&](const auto& m) { return settled(m, s); });
  };
  // (A − σ)⁻¹z = θz + r gives (A − λ)z = −(A − σ) r / θ, of norm <= ‖A − σ‖ ‖r‖/|θ| <= (2 + |σ|) ‖r‖/|θ|.
  RuleRun run = run_rule(
      V, start, apply, s.shift_columns, [sigma](double theta) { return sigma + 1 / theta; },
      [sigma](double theta, double r) { return (2 + std::abs(sigma)) * r / std::abs(theta); }, sigma - widest,
      sigma + widest, heavy, s, finished);
  run.watch = nearest_heavy(run.watch, sigma, s);
  return run;
}

// Keeps the first of modes within the merge width of each other (two shifts' windows may hold the same mode).
void dedupe(std::vector<VolumeMode>& modes, double width) {
  std::vector<VolumeMode> kept;
  for (const auto& m : modes)
    if (std::none_of(kept.begin(), kept.end(), [&](const auto& x) { return within_width(m.lambda, x.lambda, width); }))
      kept.push_back(m);
  modes = std::move(kept);
}

// Every plain node that is not a mode yet, by a shift-and-invert run just off it (survey_volume_modes' step 3).
void resolve_by_shifts(const VolumeVelocity& V, const VolumeForms& forms, const Eigen::MatrixXd& start,
                       std::vector<VolumeMode> pending, double heavy, const VolumeSurveySettings& s, VolumeSurvey& out) {
  const PoincareForms real = real_form_pencil(forms);
  // Heaviest first; a node near a mode already found that carries 100 times its weight is that mode's leakage in
  // the plain rule (its shift would only settle the same mode again, slowly, from afar).
  std::sort(pending.begin(), pending.end(),
            [](const auto& a, const auto& b) { return a.H.trace().real() > b.H.trace().real(); });
  const double widest = s.window * std::pow(4.0, kWidenings);
  for (const auto& node : pending) {
    const bool leakage = std::any_of(out.modes.begin(), out.modes.end(), [&](const auto& m) {
      return within_width(node.lambda, m.lambda, widest) && m.H.trace().real() >= 100 * node.H.trace().real();
    });
    const bool resolved = std::any_of(out.modes.begin(), out.modes.end(),
                                      [&](const auto& m) { return within_width(node.lambda, m.lambda, s.window); });
    if (leakage || resolved) continue;
    // Just off the node: σ must not be an eigenvalue (Q(σ) singular).
    const double sigma = node.lambda * (1 + 1e-4);
    progress_tick();
    const RuleRun run = shift_invert_run(V, real, start, sigma, heavy, s);
    ++out.shifts;
    // An empty watch: nothing heavy near σ, the plain node was a Gauss average over light eigenvalues, not a mode.
    for (const auto& m : run.watch) (settled(m, s) ? out.modes : out.unsettled).push_back(m);
    dedupe(out.modes, s.merge_width);
    dedupe(out.unsettled, s.merge_width);
  }
  // A cluster one shift left unsettled may have settled in another's window.
  std::erase_if(out.unsettled, [&](const VolumeMode& u) {
    return std::any_of(out.modes.begin(), out.modes.end(),
                       [&](const auto& m) { return within_width(u.lambda, m.lambda, s.merge_width); });
  });
}

}  // namespace

VolumeSurvey survey_volume_modes(const VolumeVelocity& V, const StiffnessSolver& M, const VolumeForms& forms,
                                 const VolumeSurveySettings& s) {
  Eigen::MatrixXd start(V.size(), 6);
  for (int k = 0; k < 3; ++k) {
    Eigen::VectorXd w = V.rotation_field(k);
    V.project(M, w);
    start.col(k) = w;
    start.col(3 + k) = VolumeVelocity::times_i(w);
  }
  Eigen::VectorXd t;
  const auto apply = [&](const Eigen::VectorXd& in, Eigen::VectorXd& out) {  // out = P_H S in
    V.coriolis(in, t);
    V.project(M, t);
    out = t;
  };
  double mass = 0.5 * (start.transpose() * V.weights().asDiagonal() * start).trace();
  V.sum_over_ranks(&mass, 1);
  const double heavy = s.floor * mass;
  const RuleRun plain = run_rule(
      V, start, apply, s.max_columns, [](double l) { return l; }, [](double, double r) { return r; }, s.lambda_floor,
      std::numeric_limits<double>::infinity(), heavy, s, [&](const std::vector<VolumeMode>& watch) {
        return std::all_of(watch.begin(), watch.end(), [&](const auto& m) { return still(m, s); });
      });
  VolumeSurvey out;
  std::vector<VolumeMode> pending;
  // A plain node may stop moving before its Ritz vector is an eigenvector (settled() asks for a small residual too):
  // the shift-and-invert run then resolves it.
  for (const auto& m : plain.watch) (settled(m, s) ? out.modes : pending).push_back(m);

  if (!pending.empty()) resolve_by_shifts(V, forms, start, std::move(pending), heavy, s, out);
  out.rule = plain.all;
  for (const auto& m : plain.all) {
    out.total += m.H;
    if (std::abs(m.lambda) <= s.lambda_floor) out.geostrophic += m.H;
  }
  const auto transverse = [](const VolumeMode& m) { return (m.H(0, 0) + m.H(1, 1)).real(); };
  std::sort(out.modes.begin(), out.modes.end(), [&](const auto& a, const auto& b) { return transverse(a) > transverse(b); });
  out.columns = plain.columns;
  return out;
}

}  // namespace rc::modes
