// A certificate for the verdict of an undamped chain, "all roots real" (Kononov's necessary condition), that does not
// rest on the tolerance |Im σ| <= 1e-7 ρ: a Sturm-type count of real roots by sign changes.
//
// For real σ the matrix Φ(σ) of (22) is real symmetric when nothing dissipates (characteristic.hpp), and
//   P(σ) = σ^{2n} · Π_l (σ − p_l) · det Φ(σ),   p_l = λ_kl − ω_k0 the poles of its fluid terms,
// is a real polynomial whose roots are the chain's D = 2n + (kept modes) roots. Between consecutive computed roots
// (their real parts, sorted) P is sampled at the midpoints; each sign change proves a real root in its interval
// (intermediate value theorem). D sign changes over D disjoint intervals prove every root real and simple, whatever
// the eigen-solver's rounding. sign P comes from the LU pivots of Φ and the signs of the factors; σ = 0 is a known
// root of multiplicity z (rigid precession of a chain without restoring torque) that sign changes cannot certify:
// the count is then D − z.
#pragma once

#include "chain_model.hpp"
#include "spectrum.hpp"

#include <string>

namespace rc::rom {

struct RealRootCertificate {
  bool applies = false;  // the chain dissipates nothing (with friction or viscous tanks roots are not real)
  int roots = 0;         // roots away from σ = 0 that the count must prove real
  int at_zero = 0;       // roots at σ = 0 (|σ| <= the verdict's tolerance): not counted
  int proven = 0;        // real roots proven by sign changes
  bool certified() const { return applies && proven == roots; }
};

RealRootCertificate certify_real_roots(const ChainModel& m, const Spectrum& sp);

}  // namespace rc::rom
