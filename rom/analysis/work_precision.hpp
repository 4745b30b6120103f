// The work-precision part of `chain-rom bench` (docs/rom.md, "Benchmark"), for any first-order system y' = B y: the
// state at T by 2-stage Gauss over a sweep of steps and by Dormand–Prince 5(4) over a sweep of tolerances, each
// against a reference state, timed. Shared by (26)'s bench (bench.cpp) and the general chain's (general_bench.cpp).
#pragma once

#include "bench.hpp"
#include "scene.hpp"

#include "eigen_dense.hpp"

#include <functional>

namespace rc::rom {

struct Timing {
  double wall = 0, cpu = 0;
};

// Runs f until the runs add up to min_seconds of wall time (at least once, at most 1000 times): the best wall time of
// one run (least disturbed by other load) and the mean CPU time per run.
Timing time_runs(const std::function<void()>& f, double min_seconds);

struct WorkProblem {
  Eigen::MatrixXcd B;          // y' = B y
  Eigen::VectorXcd y0, ref;    // the initial state and the reference state at T
  double T = 0, rho = 0;       // the time and B's spectral radius
};

double relative_error(const Eigen::VectorXcd& y, const Eigen::VectorXcd& ref);

// What a roots-part row was run with: the body (0-based), the tank's kept modes, static correction (0/1), spin
// factor, the tank's coverage.
struct RootsRowSetting {
  int body = 0, kept = 0, static_correction = 0;
  double spin_factor = 1, coverage = 0;
};
// Appends the roots part's row (method "modes", parameter "kept_modes") with its timing and error; calls `progress`.
void add_roots_row(BenchResult& out, const std::function<void(const BenchRow&)>& progress, const RootsRowSetting& s,
                   const Timing& t, double error);

// A work-precision row: appended to `rows`, and shown to `progress`.
BenchRow add_work_row(std::vector<BenchRow>& rows, const std::function<void(const BenchRow&)>& progress,
                      const char* method, const char* parameter, double value, long steps, const Timing& tm,
                      double error);

// ρh = 8, 4, 2, 1, 1/2, … until the rounding floor or opt.max_steps.
void sweep_gauss(const WorkProblem& w, const BenchOptions& opt, std::vector<BenchRow>& rows,
                 const std::function<void(const BenchRow&)>& progress);
// tolerance 1e-2 … 1e-14 until the rounding floor or opt.max_steps (`run` for the step estimate).
void sweep_rk45(const WorkProblem& w, const RunSpec& run, const BenchOptions& opt, std::vector<BenchRow>& rows,
                const std::function<void(const BenchRow&)>& progress);

}  // namespace rc::rom
