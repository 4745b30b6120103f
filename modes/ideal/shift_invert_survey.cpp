#include "shift_invert_survey.hpp"

#include "stiffness_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace rc::modes {
namespace {

// Q(σ) = σ² M + 2σ Gc − 4 Kz (docs/physics.md §2, m = 1).
PMat quadratic_at(const PoincareForms& forms, double sigma) {
  PMat Q;
  petsc_check(MatDuplicate(forms.M, MAT_COPY_VALUES, Q.out()), "MatDuplicate");
  petsc_check(MatScale(Q, sigma * sigma), "MatScale");
  petsc_check(MatAXPY(Q, 2 * sigma, forms.Gc, SUBSET_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatAXPY(Q, -4.0, forms.Kz, SUBSET_NONZERO_PATTERN), "MatAXPY");
  return Q;
}

// The rule's nodes mapped back to λ = σ + 1/θ, with residual bounds in λ terms, relative to ‖A‖ = 2 (the spectrum
// fills (−2, 2)): T y = θ y + r gives (A − λ) y = −(A − σ) r / θ, and ‖A − σ‖ <= 2 + |σ|.
std::vector<GaussNode> mapped_rule(const LanczosProcess& lanczos, double sigma, double mass) {
  auto rule = lanczos.rule(mass);
  for (auto& n : rule) {
    const double theta = n.lambda;
    n.lambda = theta != 0 ? sigma + 1 / theta : std::numeric_limits<double>::infinity();
    n.residual = theta != 0 ? (2 + std::abs(sigma)) * n.residual / (2 * std::abs(theta)) : n.residual;
  }
  return rule;
}

// Nodes closer than width · max(|λ|, 0.1) to their neighbour merged: weights summed, λ weighted.
std::vector<GaussNode> merged(std::vector<GaussNode> rule, double width) {
  std::sort(rule.begin(), rule.end(), [](const GaussNode& a, const GaussNode& b) { return a.lambda < b.lambda; });
  std::vector<GaussNode> out;
  for (const auto& n : rule) {
    if (!out.empty() && std::isfinite(n.lambda) &&
        within_width(out.back().lambda, n.lambda, width)) {
      GaussNode& m = out.back();
      const double E = m.E + n.E;
      if (E > 0) m.lambda = (m.E * m.lambda + n.E * n.lambda) / E;
      m.E = E;
      m.residual = std::max(m.residual, n.residual);
    } else {
      out.push_back(n);
    }
  }
  return out;
}

// The nodes of `now` in [lo, hi] at least as heavy as the floor, with their change against `before`.
std::vector<SettledNode> watched_nodes(const std::vector<GaussNode>& now, const std::vector<GaussNode>& before,
                                       double lo, double hi, double floor) {
  std::vector<SettledNode> out;
  for (const auto& n : now) {
    if (n.E < floor || n.lambda < lo || n.lambda > hi) continue;
    SettledNode s{n.lambda, n.E, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                  n.residual};
    for (const auto& b : before) {
      const double d = std::abs(b.lambda - n.lambda);
      if (d < s.dlambda) { s.dlambda = d; s.dE = std::abs(b.E - n.E) / n.E; }
    }
    out.push_back(s);
  }
  return out;
}

bool is_settled(const SettledNode& s, const ShiftInvertSettings& st) {
  return s.dlambda <= st.lambda_tolerance * std::max(std::abs(s.lambda), 0.1) && s.dE <= st.weight_tolerance;
}

}  // namespace

ShiftInvertSurvey::ShiftInvertSurvey(const VelocitySpace& V, const PoincareForms& forms, const Eigen::VectorXd& w,
                                     double mass)
    : V_(V), forms_(forms), w_(w), mass_(mass) {}

ShiftInvertRule ShiftInvertSurvey::run(double sigma, double lo, double hi, double floor,
                                       const ShiftInvertSettings& settings) const {
  if (!(std::abs(sigma) > 0 && std::abs(sigma) < 2))
    throw std::invalid_argument("shift-invert survey: the shift must be in (-2, 2) and non-zero");
  const PMat Q = quadratic_at(forms_, sigma);
  const StiffnessSolver factor(Q, "shift_", fmt::format("Q(sigma) at sigma = {:.9g}", sigma));
  const double c = sigma * (sigma * sigma - 4);
  std::vector<double> g, p;
  Eigen::VectorXd t;
  // v = (A − σ)⁻¹ u (see the header).
  const auto apply = [&](const Eigen::VectorXd& u, Eigen::VectorXd& v) {
    v = u;
    V_.shifted_coriolis_inverse(sigma, v);
    V_.divergence(v, g);
    for (double& x : g) x *= c;
    factor.solve(g, p);
    t.setZero(v.size());
    V_.add_gradient(p, 1.0, t);
    V_.shifted_coriolis_inverse(sigma, t);
    v += t;
  };
  LanczosProcess lanczos(V_.component_weights(), w_, settings.max_steps);
  std::vector<GaussNode> previous;
  std::vector<SettledNode> watched;
  auto all_settled = [&] {
    return std::all_of(watched.begin(), watched.end(), [&](const SettledNode& s) { return is_settled(s, settings); });
  };
  bool more = true;
  while (more) {
    more = lanczos.step(apply);
    const bool check = lanczos.steps() % settings.check_every == 0 || !more;
    if (!check) continue;
    auto rule = merged(mapped_rule(lanczos, sigma, mass_), settings.merge_width);
    if (lanczos.exhausted()) previous = rule;  // the rule is exact: nothing moves any more
    watched = watched_nodes(rule, previous, lo, hi, floor);
    previous = std::move(rule);
    if (lanczos.steps() >= settings.min_steps && lanczos.steps() > settings.check_every && all_settled()) break;
  }
  ShiftInvertRule out;
  out.steps = lanczos.steps();
  for (const auto& s : watched) (is_settled(s, settings) ? out.settled : out.unsettled).push_back(s);
  return out;
}

}  // namespace rc::modes
