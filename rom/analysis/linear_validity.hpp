// How far the linear model's amplitude is from its validity (docs/rom.md, "Nonlinear chain"): the scene run once by
// the linearised equations (26) propagated exactly and once by the nonlinear chain (nonlinear_chain.hpp) from the same
// initial state; their largest tilt difference relative to the largest linear tilt measures the nonlinearity at this
// amplitude. Every tank, ideal or viscous, enters both with its kept modes. Since the difference grows like the
// amplitude squared (tested), the amplitude at which it reaches 1 % is amplitude · (0.01 / difference)^{1/2}.
#pragma once

#include "chain_model.hpp"
#include "propagation.hpp"
#include "scene.hpp"

#include <string>

namespace rc::rom {

inline constexpr double kLinearValidityLimit = 0.01;     // relative tilt difference that triggers the warning
inline constexpr double kValidityMaxTurns = 2e3;          // skip the check past t_end · max|spin| / 2π turns (~1 s)
inline constexpr double kValidityTolerance = 1e-10;       // local error of the nonlinear run (1e-9 moved the default scene's 0.88 % by 2 %)

struct LinearValidity {
  bool measured = false;
  std::string why_not;          // when not measured
  double difference = 0;        // max_t |u_nonlinear − u_linear| / max_t |u_linear|
  double amplitude = 0;         // max_k |u_k(0)| + |u̇_k(0)| / max(1, |spin|) — the scene's initial amplitude (rad)
  double amplitude_at_limit = 0;  // amplitude · (kLinearValidityLimit / difference)^{1/2}
  double seconds = 0;
};

// `exact_linear`: the run's own history when it was propagated exactly (method "exact"), which is then not propagated
// again.
LinearValidity linear_validity(const Scene& scene, const ChainModel& model, const History* exact_linear = nullptr);
// The same for tilts another linear model computed (the chain without axial symmetry, general_run.hpp): `linear` holds
// u_k at the scene's output times (t = 0, output_step, …), one row per time.
LinearValidity linear_validity(const Scene& scene, const History::Rows& linear);

}  // namespace rc::rom
