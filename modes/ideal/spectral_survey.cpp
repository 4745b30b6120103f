#include "spectral_survey.hpp"

#include "velocity_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace rc::modes {

void project_solenoidal(const VelocitySpace& V, const StiffnessSolver& solver, Eigen::VectorXd& v) {
  std::vector<double> g, p;
  V.divergence(v, g);
  solver.solve(g, p);
  V.add_gradient(p, -1.0, v);
}

namespace {

// Largest move of the heavy nodes between two rules, relative to the slice scale max(|λ|, 0.1) used when
// they are refined. Weights are not compared: a cluster's E comes from the eigen-solve, not from the rule.
double rule_change(const std::vector<GaussNode>& now, const std::vector<GaussNode>& before, double mass,
                   const SurveySettings& settings) {
  double change = 0;
  for (const auto& n : now) {
    if (n.E < settings.weight_floor * mass || std::abs(n.lambda) < settings.lambda_floor) continue;
    double best = std::numeric_limits<double>::infinity();
    for (const auto& b : before) best = std::min(best, std::abs(b.lambda - n.lambda));
    change = std::max(change, best / std::max(std::abs(n.lambda), 0.1));
  }
  return change;
}

}  // namespace

SpectralSurvey survey_spectral_measure(const VelocitySpace& V, const StiffnessSolver& solver, const Eigen::VectorXd& w,
                                       const SurveySettings& settings) {
  SpectralSurvey survey;
  const double norm0 = std::sqrt(V.dot(w, w));
  if (!(norm0 > 0)) { survey.exhausted = true; return survey; }  // no solenoidal coupling at all
  const double mass = std::numbers::pi * norm0 * norm0;  // = A_f − J_zh
  LanczosProcess lanczos(V.component_weights(), w, settings.max_steps);
  const auto apply = [&](const Eigen::VectorXd& in, Eigen::VectorXd& out) {
    V.coriolis(in, out);
    project_solenoidal(V, solver, out);
  };
  std::vector<GaussNode> previous;
  while (lanczos.step(apply)) {
    if (lanczos.steps() % 10 != 0) continue;
    auto rule = lanczos.rule(mass);
    const bool settled = !previous.empty() && rule_change(rule, previous, mass, settings) < settings.tolerance;
    previous = std::move(rule);
    if (settled) break;
  }
  survey.steps = lanczos.steps();
  survey.exhausted = lanczos.exhausted();
  survey.nodes = lanczos.rule(mass);
  return survey;
}

}  // namespace rc::modes
