#include "bench.hpp"

#include "atomic_file.hpp"

#include "chain_model.hpp"
#include "complex_eigen.hpp"
#include "energy.hpp"
#include "exact_propagation.hpp"
#include "first_order_system.hpp"
#include "general_bench.hpp"
#include "general_chain.hpp"
#include "propagation.hpp"
#include "reference_propagation.hpp"
#include "spectrum.hpp"
#include "work_precision.hpp"

#include "eigen_dense.hpp"
#include "matrix_exponential.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace rc::rom {
namespace fs = std::filesystem;
namespace {
using cd = std::complex<double>;

struct WorkSetup {
  const ChainModel& m;
  FirstOrderSystem f;
  WorkProblem p;
};

// H is conserved without friction (docs/rom.md, "Energy"): its change from y0 to the reference's final state,
// relative to the size of its parts, as a row beside the reference's.
void add_energy_drift_row(const WorkSetup& w, const BenchRow& reference, BenchResult& out,
                          const std::function<void(const BenchRow&)>& progress) {
  const EnergyMeter meter(w.m);
  Eigen::VectorXcd u, v, wv;
  w.f.from_state(w.m, w.p.y0, u, v, wv);
  const Energy e0 = meter(u, v, wv);
  w.f.from_state(w.m, w.p.ref, u, v, wv);
  const Energy e1 = meter(u, v, wv);
  BenchRow re = reference;
  re.parameter = "energy_drift";
  re.error = std::abs(e1.total() - e0.total()) / std::max(e0.scale(), 1e-300);
  re.wall_seconds = re.cpu_seconds = BenchRow::nan;
  out.rows.push_back(re);
  if (progress) progress(re);
}

// exact in double: eigen-decomposition (real form when it applies) + the state at t_end.
void add_exact_row(const WorkSetup& w, const BenchOptions& opt, BenchResult& out,
                   const std::function<void(const BenchRow&)>& progress) {
  Eigen::VectorXcd y;
  const Timing te = time_runs([&] {
    ModalForm mf = modal_form(w.f, !w.m.dissipative(), kRealTolerance);
    if (mf.usable) {
      if (mf.undamped_real && !mf.real) snap_to_imaginary_axis(mf);
      y = modal_state_at(mf, w.p.y0, w.p.T);
    } else {
      // defective spectrum: the exponential itself
      y = rc::matrix_exponential(Eigen::MatrixXcd(w.f.B * cd(w.p.T))) * w.p.y0;
    }
  }, opt.min_seconds);
  BenchRow rx;
  rx.part = "work";
  rx.method = "exact";
  rx.parameter = "none";
  rx.wall_seconds = te.wall;
  rx.cpu_seconds = te.cpu;
  rx.error = relative_error(y, w.p.ref);
  out.rows.push_back(rx);
  if (progress) progress(rx);
}

void work_precision(const ChainModel& m, const Scene& scene, const BenchOptions& opt, BenchResult& out,
                    const std::function<void(const BenchRow&)>& progress) {
  WorkSetup w{m, build_first_order(m), {}};
  w.p.T = scene.run.t_end;
  w.p.B = w.f.B;
  Eigen::VectorXcd u0(m.n), v0(m.n);
  for (int k = 0; k < m.n; ++k) {
    u0[k] = scene.tilt[k];
    v0[k] = scene.rate[k];
  }
  w.p.y0 = w.f.to_state(m, u0, v0, Eigen::VectorXcd::Zero(m.n_modes()));
  if (!(w.p.y0.norm() > 0))
    throw std::runtime_error(scene.file.string() + ": initial: the initial state is zero (nothing moves): "
                             "give initial.tilt or initial.rate");
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(w.f.B, false);
  w.p.rho = es.eigenvalues().cwiseAbs().maxCoeff();
  out.spectral_radius = w.p.rho;
  out.dimension = w.f.dim();

  // The reference, its self-check (two long double methods) and its energy.
  ReferenceState ref;
  const Timing tr = time_runs([&] { ref = reference_state(m, w.f.s, w.p.y0, w.p.T); }, 0);
  w.p.ref = ref.y;
  out.reference_mantissa_bits = ref.mantissa_bits;
  const BenchRow r = add_work_row(out.rows, progress, "reference", "method_difference", BenchRow{}.value,
                                  BenchRow{}.steps, tr, ref.method_difference);
  if (!m.dissipative()) add_energy_drift_row(w, r, out, progress);
  add_exact_row(w, opt, out, progress);
  sweep_gauss(w.p, opt, out.rows, progress);
  sweep_rk45(w.p, scene.run, opt, out.rows, progress);
}

// ---- part 2: roots against kept modes ------------------------------------------------------------

std::vector<cd> roots_of(const ChainModel& m) {
  const FirstOrderSystem f = build_first_order(m);
  const ComplexEigen es = complex_eigen(f.B, false);  // as `spectrum` finds them (complex_eigen.hpp)
  std::vector<cd> r;
  for (Eigen::Index i = 0; i < es.values.size(); ++i) r.push_back(cd(0, -1) * es.values[i]);
  return r;
}

void roots_against_modes(const Scene& scene, BenchResult& out, const std::function<void(const BenchRow&)>& progress) {
  TableCache tables;
  // Reference scene: every coupling mode of every table, static correction on.
  Scene full = scene;
  for (BodySpec& b : full.bodies)
    if (b.cavity) {
      b.cavity->modes.reset();
      b.cavity->coverage.reset();
      b.cavity->static_correction = true;
    }
  // Zhukovsky's case (every spin 0) needs ideal tables: a viscous table holds for its spin's Ekman number only.
  const bool viscous = build_model(full, &tables).viscous;
  for (const double factor : {1.0, 0.0}) {
    if (factor == 0 && viscous) continue;
    Scene ref_scene = full;
    for (BodySpec& b : ref_scene.bodies) b.spin *= factor;
    const ChainModel ref_model = build_model(ref_scene, &tables);
    const Spectrum sp = compute_spectrum(ref_model);
    std::vector<cd> body_ref;
    for (const Root& r : sp.roots)
      if (r.owner.rfind("body", 0) == 0) body_ref.push_back(r.sigma);
    for (int k = 0; k < ref_model.n; ++k) {
      int all = 0;
      for (const FluidMode& md : ref_model.modes) all += md.body == k ? 1 : 0;
      if (all < 2) continue;  // nothing to truncate
      std::vector<int> kept;
      for (int q = 1; q < all; q *= 2) kept.push_back(q);
      kept.push_back(all);
      for (const int q : kept)
        for (const int corrected : {0, 1}) {
          Scene s = ref_scene;
          s.bodies[k].cavity->modes = q;
          s.bodies[k].cavity->static_correction = corrected == 1;
          ChainModel model;
          std::vector<cd> roots;
          const Timing t = time_runs([&] {
            model = build_model(s, &tables);
            roots = roots_of(model);
          }, 0);
          add_roots_row(out, progress, {k, q, corrected, factor, model.bodies[k].coverage}, t,
                        body_root_error(body_ref, roots));
        }
    }
  }
}

std::string field(double x, const char* fmt = "%.6e") {
  if (std::isnan(x)) return "";
  char buf[48];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

}  // namespace

double body_root_error(const std::vector<std::complex<double>>& body_ref, const std::vector<std::complex<double>>& roots) {
  double worst = 0;
  for (const cd& r : body_ref) {
    double best = 1e300;
    for (const cd& s : roots) best = std::min(best, std::abs(s - r));
    worst = std::max(worst, best / std::max(std::abs(r), 1e-300));
  }
  return worst;
}

BenchResult run_bench(const Scene& scene, const BenchOptions& options,
                      const std::function<void(const BenchRow&)>& progress) {
  if (!scene.run.present)
    throw std::runtime_error(scene.file.string() + ": run: missing [run] section (bench needs run.t_end)");
  if (!(scene.run.t_end > 0) || !std::isfinite(scene.run.t_end))
    throw std::runtime_error(scene.file.string() + ": run.t_end: must be > 0 for bench");
  for (std::size_t k = 0; k < scene.size(); ++k)  // its extended-precision reference propagates the free chain only
    if (scene.bodies[k].moment)
      throw std::runtime_error(scene.file.string() + ": body[" + std::to_string(k + 1) + "].moment: bench compares "
                               "the integrators on the free motion; remove the moments");
  BenchResult out;
  out.t_end = scene.run.t_end;
  TableCache tables;
  if (needs_general_chain(scene, tables)) {  // bodies or tanks without axial symmetry
    general_bench(scene, options, out, progress);
    return out;
  }
  const ChainModel m = build_model(scene, &tables);
  work_precision(m, scene, options, out, progress);
  roots_against_modes(scene, out, progress);
  return out;
}

std::string format_bench_row(const BenchRow& r) {
  char buf[256];
  if (r.part == "work") {
    std::string what = r.method;
    if (r.parameter == "step") what += " h = " + field(r.value, "%.3g") + " s (" + std::to_string(r.steps) + " steps)";
    else if (r.parameter == "tolerance") what += " tol = " + field(r.value, "%.0e") + " (" + std::to_string(r.steps) + " steps)";
    else if (r.parameter == "method_difference") what += ": eigen-decomposition vs matrix exponential, long double";
    else if (r.parameter == "magnus_difference") what += ": Magnus steps, 4 against 2 times the roots' count";
    else if (r.parameter == "energy_drift") what += ": energy change 0 -> t_end, relative";
    else what += " (double)";
    std::snprintf(buf, sizeof buf, "%-62s error %9.2e   wall %s s  cpu %s s", what.c_str(), r.error,
                  std::isnan(r.wall_seconds) ? "-" : field(r.wall_seconds, "%.3g").c_str(),
                  std::isnan(r.cpu_seconds) ? "-" : field(r.cpu_seconds, "%.3g").c_str());
  } else {
    std::snprintf(buf, sizeof buf, "roots, spin x %g, body %d: %3d modes kept (coverage %.4f), %s: body-root error %9.2e",
                  r.spin_factor, r.body, static_cast<int>(r.value), r.coverage,
                  r.static_correction ? "static correction   " : "no static correction", r.error);
  }
  return buf;
}

void write_bench_csv(const BenchResult& res, const fs::path& out) {
  write_text_atomically(out, [&](std::ostream& os) {
    os << "part,method,parameter,value,steps,body,static_correction,spin_factor,coverage,wall_seconds,"
          "cpu_seconds,error\n";
    for (const BenchRow& r : res.rows) {
      os << r.part << ',' << r.method << ',' << r.parameter << ',' << field(r.value, "%.10g") << ','
         << (r.steps >= 0 ? std::to_string(r.steps) : "") << ',' << (r.body > 0 ? std::to_string(r.body) : "")
         << ',' << (r.static_correction >= 0 ? std::to_string(r.static_correction) : "") << ','
         << field(r.spin_factor, "%g") << ',' << field(r.coverage, "%.8f") << ',' << field(r.wall_seconds)
         << ',' << field(r.cpu_seconds) << ',' << field(r.error) << '\n';
    }
  });
}

}  // namespace rc::rom
