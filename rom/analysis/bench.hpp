// Error against run time of chain-rom (`chain-rom bench SCENE`; docs/rom.md, "Benchmark"):
//  1. work-precision: the state at run.t_end by `exact` (double), `gauss` over a sweep of steps and
//     `rk45` over a sweep of tolerances, each against the extended-precision reference
//     (reference_propagation.hpp): relative error in the norm of the balanced state y = (s u, u-dot, w),
//     against wall and CPU time;
//  2. roots against kept modes: for each cavity whose table has more than one coupling mode, the roots
//     owned by the bodies with 1, 2, 4, ... up to all of that cavity's modes kept, with and without
//     static_correction, against the roots with every mode of every table and the static correction
//     (the full sum rule A_f - J_zh); at the scene's spins and with every spin set to zero, where the
//     corrected roots are exact for any number of kept modes (Batyr Theorem 2).
#pragma once

#include "scene.hpp"

#include <complex>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace rc::rom {

struct BenchRow {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::string part;            // "work" or "roots"
  std::string method;          // work: reference, exact, gauss, rk45; roots: modes
  std::string parameter;       // work: none, step, tolerance, method_difference, energy_drift; roots: kept_modes
  double value = nan;          // h (s), tolerance, or number of kept modes
  long steps = -1;             // work: integrator steps (gauss, rk45)
  int body = 0;                // roots: 1-based body whose kept modes vary
  int static_correction = -1;  // roots: 0 or 1
  double spin_factor = nan;    // roots: every spin times this (1: the scene; 0: Zhukovsky's case, ideal tables only)
  double coverage = nan;       // roots: sum of the kept E over A_f - J_zh of that body
  double wall_seconds = nan;   // best of the repetitions
  double cpu_seconds = nan;    // process CPU time per repetition
  double error = nan;          // work: |y - y_ref| / |y_ref| at t_end; roots: max relative body-root error
};

struct BenchResult {
  std::vector<BenchRow> rows;
  double t_end = 0;
  double spectral_radius = 0;  // largest |sigma| (rad/s)
  int dimension = 0;           // of the first-order system
  int reference_mantissa_bits = 0;
};

struct BenchOptions {
  double max_steps = 4e6;      // no gauss / rk45 run with more (estimated) steps than this
  double min_seconds = 0.05;   // short runs are repeated until they add up to this (wall)
};

// Runs both parts; `progress` (if set) is called with every row as it is done. Throws
// std::runtime_error with a one-line cause (no [run] section, t_end not positive, ...).
BenchResult run_bench(const Scene& scene, const BenchOptions& options = {},
                      const std::function<void(const BenchRow&)>& progress = {});

// Largest relative distance from a reference body root to the nearest root of `roots` (the roots part's error).
double body_root_error(const std::vector<std::complex<double>>& body_ref, const std::vector<std::complex<double>>& roots);

// CSV, one row per BenchRow: part,method,parameter,value,steps,body,static_correction,spin_factor,
// coverage,wall_seconds,cpu_seconds,error (empty where a field does not apply); written under a temporary name and
// then renamed, so that no half-written file is left.
void write_bench_csv(const BenchResult& r, const std::filesystem::path& out);
// One line per row, readable.
std::string format_bench_row(const BenchRow& row);

}  // namespace rc::rom
