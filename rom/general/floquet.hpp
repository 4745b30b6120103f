// The roots of the chain at two spins (docs/rom.md, "Bodies at different spins"): its coefficients are T-periodic in
// every frame (periodic_system.hpp), so its motions are Floquet solutions y = p(t) e^{iσt}, p T-periodic, whose
// multipliers μ = e^{iσT} are the eigenvalues of the monodromy matrix Φ(T) (y(T) = Φ(T) y(0)). Φ is built by the
// sixth-order Magnus method (Blanes, Casas and Ros, "Improved high order integrators based on the Magnus expansion",
// BIT 40, 2000: three Gauss points per step, each step the exponential of a combination of B and its commutators;
// error O(h⁶)), doubling the steps until two monodromies give the same roots.
#pragma once

#include "general_chain.hpp"
#include "general_system.hpp"

#include "eigen_dense.hpp"

#include <complex>
#include <vector>

namespace rc::rom {

// y(t0 + steps·h) = transition · y(t0) for y' = B(t) y (periodic_matrix with q's scale s).
Eigen::MatrixXd magnus_transition(const GeneralChain& g, double s, double t0, double h, int steps);

// σ = −i log(μ)/T: Im σ = −ln|μ|/T exactly; Re σ is defined modulo Ω = 2π/T, and each is given in the branch nearest
// the averaged chain's root (B averaged over a period) it is paired with. The verdict as general_spectrum's, a
// dissipative chain's growth noise raised to ten times the measured error. The monodromy's eigenvalues are good to
// about ε‖Φ‖: a root whose multiplier is far below the largest (it decays by many e-foldings a period more than the
// fastest-growing root) can stay unsettled; it is counted as unresolved when it moved by more than 1e-9 of the
// spectral radius in the last doubling. Throws std::runtime_error when the roots whose multipliers are within 1e-6
// of the largest have not settled to 1e-10 of the spectral radius at 2^16 steps per period.
GeneralSpectrum floquet_spectrum(const GeneralChain& g);

// The Floquet roots as floquet_spectrum gives them (unfolded, unsorted) with the eigenvectors of the monodromy (each
// the Floquet solution's state at t = 0), column by column.
struct FloquetModes {
  std::vector<std::complex<double>> roots;
  Eigen::MatrixXcd vectors;
};
FloquetModes floquet_modes(const GeneralChain& g);

// y(t) of the periodic chain from y(0), t increasing from call to call: Magnus steps on the grid of T/N (each of the N
// steps of a period made once and kept), and one step of its own from the last grid point to t.
class PeriodicPropagator {
 public:
  PeriodicPropagator(const GeneralChain& g, double s, int steps_per_period, const Eigen::VectorXd& y0);
  Eigen::VectorXd at(double t);

 private:
  const GeneralChain& g_;
  double s_, h_;
  std::vector<Eigen::MatrixXd> steps_;  // over [i h, (i + 1) h], made when first needed
  long grid_ = 0;                       // the grid point y_ stands at
  Eigen::VectorXd y_;
};

// The steps per period floquet_spectrum settles with, and q's scale s: what `run` propagates with; and the spectral
// radius of B(0) (at least the period's frequency), which the steps resolve.
struct FloquetSteps {
  int per_period = 0;
  double s = 1;
  double radius = 0;
};
FloquetSteps floquet_steps(const GeneralChain& g);

}  // namespace rc::rom
