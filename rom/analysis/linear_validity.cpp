#include "linear_validity.hpp"

#include "nonlinear_run.hpp"
#include "propagation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::rom {
namespace {

Scene with_tolerance(const Scene& scene) {
  Scene s = scene;
  s.run.method = "exact";
  s.run.tolerance = kValidityTolerance;
  return s;
}

}  // namespace

namespace {

// The scene's amplitude, or why the check does not run (at rest, too many turns).
LinearValidity validity_scope(const Scene& scene, bool& forced) {
  LinearValidity v;
  double spin = 0;
  for (const auto& b : scene.bodies) spin = std::max(spin, std::abs(b.spin));
  for (std::size_t k = 0; k < scene.size(); ++k)
    v.amplitude = std::max(v.amplitude, std::abs(scene.tilt[k]) + std::abs(scene.rate[k]) / std::max(1.0, spin));
  forced = std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const BodySpec& b) { return b.moment; });
  const bool fluid_moves = std::any_of(scene.fluid.begin(), scene.fluid.end(), [](auto z) { return z != 0.0; });
  if (v.amplitude == 0 && !forced)
    v.why_not = fluid_moves ? "the bodies start at rest in the straight chain, only the fluid in motion"
                            : "the scene starts at rest in the straight chain";
  else if (scene.run.t_end * spin / (2 * std::numbers::pi) > kValidityMaxTurns)
    v.why_not = "the run is longer than " + std::to_string(long(kValidityMaxTurns)) + " turns of the fastest body";
  return v;
}

// The nonlinear chain's tilts against `linear` (one row per output time) at the scene's amplitude.
void compare_with_nonlinear(const Scene& checked, const History::Rows& linear, bool forced, LinearValidity& v) {
  const NonlinearChain chain = nonlinear_chain(checked);
  const NonlinearHistory nonlinear = integrate_nonlinear(chain, nonlinear_initial_state(checked, chain), checked.run);
  const double scale = linear.cwiseAbs().maxCoeff();
  double diff = 0;
  for (Eigen::Index j = 0; j < linear.rows(); ++j)
    diff = std::max(diff, (linear.row(j) - nonlinear.base.u.row(j)).cwiseAbs().maxCoeff());
  if (!(scale > 0) || !std::isfinite(diff)) throw std::runtime_error("no finite tilts to compare");
  v.difference = diff / scale;
  if (forced) v.amplitude = std::max(v.amplitude, scale);  // the moments' response is the amplitude
  v.amplitude_at_limit = v.difference > 0 ? v.amplitude * std::sqrt(kLinearValidityLimit / v.difference) : INFINITY;
  v.measured = true;
}

}  // namespace

LinearValidity linear_validity(const Scene& scene, const ChainModel& model, const History* exact_linear) {
  const auto t0 = std::chrono::steady_clock::now();
  bool forced = false;
  LinearValidity v = validity_scope(scene, forced);
  if (!v.why_not.empty()) return v;
  try {
    // Every tank, ideal or viscous, enters both models with its kept modes.
    const Scene checked = with_tolerance(scene);
    History own;
    if (!exact_linear) own = propagate(model, checked);
    compare_with_nonlinear(checked, exact_linear ? exact_linear->u : own.u, forced, v);
  } catch (const std::exception& e) {
    v.why_not = e.what();
  }
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return v;
}

LinearValidity linear_validity(const Scene& scene, const History::Rows& linear) {
  const auto t0 = std::chrono::steady_clock::now();
  bool forced = false;
  LinearValidity v = validity_scope(scene, forced);
  if (!v.why_not.empty()) return v;
  try {
    compare_with_nonlinear(with_tolerance(scene), linear, forced, v);
  } catch (const std::exception& e) {
    v.why_not = e.what();
  }
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return v;
}

}  // namespace rc::rom
