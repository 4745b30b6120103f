#include "work_precision.hpp"

#include "propagation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace rc::rom {
namespace {

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

Timing time_runs(const std::function<void()>& f, double min_seconds) {
  using clock = std::chrono::steady_clock;
  Timing t{1e300, 0};
  double total = 0;
  int reps = 0;
  const double cpu0 = process_cpu_seconds();
  do {
    const auto a = clock::now();
    f();
    const double w = std::chrono::duration<double>(clock::now() - a).count();
    t.wall = std::min(t.wall, w);
    total += w;
    ++reps;
  } while (total < min_seconds && reps < 1000);
  t.cpu = (process_cpu_seconds() - cpu0) / reps;
  return t;
}

double relative_error(const Eigen::VectorXcd& y, const Eigen::VectorXcd& ref) {
  return (y - ref).norm() / ref.norm();
}

void add_roots_row(BenchResult& out, const std::function<void(const BenchRow&)>& progress, const RootsRowSetting& s,
                   const Timing& t, double error) {
  BenchRow r;
  r.part = "roots";
  r.method = "modes";
  r.parameter = "kept_modes";
  r.value = s.kept;
  r.body = s.body + 1;
  r.static_correction = s.static_correction;
  r.spin_factor = s.spin_factor;
  r.coverage = s.coverage;
  r.wall_seconds = t.wall;
  r.cpu_seconds = t.cpu;
  r.error = error;
  out.rows.push_back(r);
  if (progress) progress(r);
}

BenchRow add_work_row(std::vector<BenchRow>& rows, const std::function<void(const BenchRow&)>& progress,
                      const char* method, const char* parameter, double value, long steps, const Timing& tm,
                      double error) {
  BenchRow r;
  r.part = "work";
  r.method = method;
  r.parameter = parameter;
  r.value = value;
  r.steps = steps;
  r.wall_seconds = tm.wall;
  r.cpu_seconds = tm.cpu;
  r.error = error;
  rows.push_back(r);
  if (progress) progress(r);
  return r;
}

namespace {

// Stop a sweep once the error reaches the rounding floor: below 1e-14, or below 1e-9 and no longer
// halving when the work doubles (or more).
bool at_floor(double err, double previous) { return err < 1e-14 || (err < 1e-9 && err > 0.5 * previous); }

}  // namespace

void sweep_gauss(const WorkProblem& w, const BenchOptions& opt, std::vector<BenchRow>& rows,
                 const std::function<void(const BenchRow&)>& progress) {
  // rho h = 8, 4, 2, 1, 1/2, ...: 2-stage Gauss is A-stable, so every step size gives a bounded answer.
  double previous = 1e300;
  for (int k = -3; k < 40; ++k) {
    const long N = std::max(1L, static_cast<long>(std::ceil(w.T * w.rho * std::ldexp(1.0, k))));
    if (static_cast<double>(N) > opt.max_steps) break;
    const double h = w.T / static_cast<double>(N);
    Eigen::VectorXcd y, tmp(w.y0.size());
    const Timing tm = time_runs([&] {
      const Eigen::MatrixXcd P = gauss_step_matrix(w.B, h);
      y = w.y0;
      for (long j = 0; j < N; ++j) {
        tmp.noalias() = P * y;
        y.swap(tmp);
      }
    }, opt.min_seconds);
    const BenchRow r = add_work_row(rows, progress, "gauss", "step", h, N, tm, relative_error(y, w.ref));
    if (at_floor(r.error, previous)) break;
    previous = r.error;
  }
}

void sweep_rk45(const WorkProblem& w, const RunSpec& scene_run, const BenchOptions& opt, std::vector<BenchRow>& rows,
                const std::function<void(const BenchRow&)>& progress) {
  double previous = 1e300;
  for (int k = 2; k <= 14; ++k) {
    const double tol = std::pow(10.0, -k);
    RunSpec run = scene_run;
    run.tolerance = tol;
    run.output_step = run.t_end;  // one output: the final state
    if (estimate_integrator_steps("rk45", w.rho, run) > opt.max_steps) break;
    Eigen::VectorXcd y;
    long steps = 0;
    const Timing tm = time_runs([&] {
      y = w.y0;
      steps = 0;
      double h = std::min(w.T, 1.0 / std::max(w.rho, 1e-300));
      rk45_advance(w.B, y, 0.0, w.T, tol, h, steps);
    }, opt.min_seconds);
    const BenchRow r = add_work_row(rows, progress, "rk45", "tolerance", tol, steps, tm, relative_error(y, w.ref));
    if (at_floor(r.error, previous)) break;
    previous = r.error;
  }
}


}  // namespace rc::rom
