// `chain-rom bench` on a scene that needs the chain without axial symmetry (docs/rom.md, "Benchmark", and "Bodies and
// tanks without axial symmetry"): the same two parts as (26)'s bench (bench.hpp) on general_system.hpp's first-order
// form —
//  1. work-precision: the state at run.t_end by `exact` (the balanced matrix exponential in double, as `run` does),
//     `gauss` over a sweep of steps and `rk45` over a sweep of tolerances, against the long double reference of the
//     same matrix (reference_propagation.hpp);
//  2. roots against kept modes: for each tank whose table has more than one coupling row, the body roots with 1, 2,
//     4, … up to all of its rows kept, against those with every row of every tank; a root is the bodies' when its
//     eigenvector's kinetic energy Q̇ᴴ M Q̇ outweighs the modes' Σ|z|². At the scene's spin only (the general chain
//     has no static correction, and its Zhukovsky limit is not a separate case).
#pragma once

#include "bench.hpp"
#include "scene.hpp"

#include <functional>

namespace rc::rom {

// Fills `out` (rows, spectral radius, dimension, mantissa bits). Throws std::runtime_error for a zero initial state,
// SceneError for what the general chain refuses.
void general_bench(const Scene& scene, const BenchOptions& options, BenchResult& out,
                   const std::function<void(const BenchRow&)>& progress);

}  // namespace rc::rom
