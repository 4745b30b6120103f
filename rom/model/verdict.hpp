// The stability verdict of a chain's characteristic roots σ (solutions e^{iσt}): real, growing or neutral, by the
// rules of docs/rom.md ("Spectrum", "Verdict with dissipation"). Any chain's roots take it: (26)'s (spectrum.hpp) and
// the chain without axial symmetry's (general_system.hpp), so it sits in the model layer below both.
#pragma once

#include "eigen_dense.hpp"

namespace rc::rom {

// The verdict alone (eigenvalues only: no eigenvectors, owners or det residuals), by the same
// rules as compute_spectrum; what `chain-rom sweep` evaluates at every point.
struct Verdict {
  bool stable = false;
  double margin = 0, growth = 0, tolerance = 0;
  int nonreal = 0;
  int roots = 0;
  double radius = 0;  // the size of the oscillating roots the tolerance is relative to
  // Friction or viscous fluid (docs/rom.md, "Verdict with dissipation"): a root grows when -Im sigma exceeds `noise`
  // (kGrowthNoise of the spectral radius: rounding, not physics); roots within `tolerance` of sigma = 0 are neutral
  // (a multiple zero root's rounding is of order sqrt(eps)) and take no part in `growth`.
  double noise = 0;
  int growing = 0, at_zero = 0;
};

// Relative tolerance on |Im sigma| (times the spectral radius) for calling a root real.
inline constexpr double kRealTolerance = 1e-7;
// With dissipation: growth below this times the spectral radius is rounding (the eigen-roots agree with Newton on
// (22) to 5e-13 of it on the water chain, docs/rom.md, "Viscous tanks"); anything above it grows.
inline constexpr double kGrowthNoise = 1e-12;

// The verdict of a complete set of roots: `dissipative` as ChainModel::dissipative() (the chain without axial
// symmetry's too).
// `neutral` > 0: roots at σ = ±neutral within the tolerance are neutral too, left out as those at σ = 0 are (the
// chain without axial symmetry's frame turns at the spin, where a free chain's rigid turn in space sits).
Verdict verdict_of_roots(const Eigen::VectorXcd& sigma, bool dissipative, double neutral = 0);
// The size of the oscillating roots the verdict's tolerance is relative to (tolerance = kRealTolerance * radius).
inline double verdict_radius(const Verdict& v) { return v.radius; }

}  // namespace rc::rom
