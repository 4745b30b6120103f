// The linear chain (26) under the scene's external moments (Batyr (1)–(3): the forced form of Kononov (26)/(28);
// docs/rom.md, "External moments in the linear chain"): a particular solution in closed form, so that the run stays
// exact — y(t) = y_p(t) + e^{Bt}(y(0) − y_p(0)), the free part propagated as without moments.
//
// A moment on body k enters (26) on body k's row as F_k = M_y + i M_x (the tilts' convention u = n_x − i n_y,
// frequency_response.hpp; checked against the nonlinear chain), in first-order form the forcing (0, M_eff⁻¹F, 0). The
// scene's `space` part is constant, its `harmonic` part h_k sin(2π f_k t) = h_k (e^{iΩt} − e^{−iΩt})/2i, so
//   constant:  y_c = −B⁻¹ f_c,
//   harmonic:  y_± = ±(±iΩ − B)⁻¹ f_h/(2i)  for e^{±iΩt}, one pair per body's frequency.
// Where B − iΩ is singular (a constant moment on a chain with a zero root, a moment at a resonance of an undamped
// chain) the response grows without bound, which no closed form of this kind holds: refused in one line.
#pragma once

#include "chain_model.hpp"
#include "first_order_system.hpp"
#include "scene.hpp"

#include "eigen_dense.hpp"
#include <complex>
#include <utility>
#include <vector>

namespace rc::rom {

struct ForcedSolution {
  struct Harmonic {
    double omega = 0;  // rad/s
    Eigen::VectorXcd plus, minus;  // coefficients of e^{iΩt} and e^{−iΩt} (balanced state)
  };
  bool present = false;
  Eigen::VectorXcd constant;
  std::vector<Harmonic> harmonics;
  Eigen::VectorXcd at(double t) const;  // y_p(t) in the balanced state of FirstOrderSystem
  // The generalised moments F(t) on the tilts themselves (moments, forces, field: M_y + i M_x per body), constant plus
  // Σ amplitude · sin(Ω t): their power Re(F̄ᵀu̇) is the work the run's energy balance counts.
  Eigen::VectorXcd moments;
  std::vector<std::pair<double, Eigen::VectorXcd>> moment_harmonics;  // (Ω rad/s, amplitude)
  Eigen::VectorXcd moments_at(double t) const;
};

// The complex moment F_k = M_y + i M_x on each body: the constant part and, per body, the harmonic amplitude.
// Throws SceneError naming body[k].moment for what the linear chain cannot take (axial parts: they change spins).
Eigen::VectorXcd constant_moments(const Scene& scene);

// Empty (present = false) when the scene has no moments. Throws std::runtime_error where the response is unbounded.
ForcedSolution forced_solution(const ChainModel& m, const FirstOrderSystem& f, const Scene& scene);

}  // namespace rc::rom
