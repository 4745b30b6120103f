// The frequency response of the chain at two spins (docs/rom.md, "Frequency response at two spins"): the steady
// motion under a moment F e^{iσt} on one body when the chain's coefficients are T-periodic (periodic_system.hpp).
//
// In the frame F (turning at ω0) the moment is the force Re[e^{iΩt} f] on body K's rows, Ω = σ + ω0, f = (1, i)
// (general_response.hpp). y' = B(t) y + b(t) e^{iΩt}, b = input(t) f, has the steady solution y = e^{iΩt} p(t) with p
// T-periodic: p' = (B − iΩ) p + b. The augmented (p, 1)' = [[B − iΩ, b], [0, 0]] (p, 1) is stepped by the sixth-order
// Magnus method (magnus.hpp) on the grid of T/N; with w the p reached from p(0) = 0 after a period,
//   p(0) = (I − e^{−iΩT} Φ)⁻¹ w      (Φ the monodromy of y' = B y),
// and p is sampled on the grid. Each body's complex tilt in F is v = q_x − i q_y = a(t) e^{iΩt} + b(t) e^{−iΩt} with
// a = (p̂_x − i p̂_y)/2, b = conj(p̂_x + i p̂_y)/2 (p̂ the body's q-rows of p over s), T-periodic, so that in the
// inertial frame u = e^{−iω0t} v holds the frequencies σ + kν and −σ − 2ω0 + kν (ν = 2π/T, every integer k):
//   tilt     A₊ = mean of a   (k = 0: the moment's own frequency σ, what (26) and a chain at one spin give),
//   mirror   A₋ = mean of b   (k = 0: −σ − 2ω0, the mirror of F's body),
//   sideband the root mean square of all the others, ‖a − A₊‖ and ‖b − A₋‖ over the period (Parseval).
// The period means are the trapezoid rule on the grid: exact for the harmonics below N/2.
#pragma once

#include "general_response.hpp"

namespace rc::rom {

// As general_frequency_response for a periodic chain (g.periodic()), with `sideband` filled. Throws
// std::runtime_error as floquet_spectrum.
GeneralFrequencyResponse periodic_frequency_response(const GeneralChain& g, int body, double from, double to,
                                                     int steps);

}  // namespace rc::rom
