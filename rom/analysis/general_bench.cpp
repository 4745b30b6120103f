#include "general_bench.hpp"

#include "balancing.hpp"
#include "floquet.hpp"
#include "general_chain.hpp"
#include "general_run.hpp"
#include "general_system.hpp"
#include "periodic_system.hpp"
#include "reference_propagation.hpp"
#include "work_precision.hpp"

#include "eigen_dense.hpp"
#include "matrix_exponential.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace rc::rom {
namespace {

using cd = std::complex<double>;

// `exact` as `run` does it: the balanced matrix exponential, here over the whole of T.
void add_exact_row(const WorkProblem& w, const BenchOptions& opt, BenchResult& out,
                   const std::function<void(const BenchRow&)>& progress) {
  Eigen::VectorXcd y;
  const Timing te = time_runs([&] {
    Eigen::MatrixXcd B = w.B;
    const Eigen::VectorXd S = balance_in_place(B);  // B = S B' S⁻¹
    const Eigen::MatrixXcd E = rc::matrix_exponential(Eigen::MatrixXcd(B * cd(w.T)));
    y = S.cast<cd>().asDiagonal() * (E * (w.y0.array() / S.cast<cd>().array()).matrix());
  }, opt.min_seconds);
  add_work_row(out.rows, progress, "exact", "none", BenchRow::nan, -1, te, relative_error(y, w.ref));
}

void work_precision(const Scene& scene, const GeneralChain& g, const BenchOptions& opt, BenchResult& out,
                    const std::function<void(const BenchRow&)>& progress) {
  const GeneralSystem sys = build_general_system(g);
  WorkProblem w;
  w.T = scene.run.t_end;
  w.B = sys.B.cast<cd>();
  w.y0 = general_initial_state(g, sys, scene).cast<cd>();
  if (!(w.y0.norm() > 0))
    throw std::runtime_error(scene.file.string() + ": initial: the initial state is zero (nothing moves): "
                             "give initial.tilt or initial.rate");
  w.rho = Eigen::EigenSolver<Eigen::MatrixXd>(sys.B, false).eigenvalues().cwiseAbs().maxCoeff();
  out.spectral_radius = w.rho;
  out.dimension = sys.dim();
  ReferenceState ref;
  const Timing tr = time_runs([&] { ref = reference_state(w.B, w.y0, w.T); }, 0);
  w.ref = ref.y;
  out.reference_mantissa_bits = ref.mantissa_bits;
  add_work_row(out.rows, progress, "reference", "method_difference", BenchRow::nan, -1, tr, ref.method_difference);
  add_exact_row(w, opt, out, progress);
  sweep_gauss(w, opt, out.rows, progress);
  sweep_rk45(w, scene.run, opt, out.rows, progress);
}

// At two spins (floquet.hpp): the state at run.t_end by Magnus steps, 8, 16, … a period up to twice the steps the roots
// settled with, against four times those (the reference row: its difference from twice them).
void periodic_work_precision(const Scene& scene, const GeneralChain& g, const BenchOptions& opt, BenchResult& out,
                             const std::function<void(const BenchRow&)>& progress) {
  const FloquetSteps settled = floquet_steps(g);
  const GeneralSystem sys = build_general_system(turned_chain(g, 0), settled.s);
  const Eigen::VectorXd y0 = general_initial_state(g, sys, scene);
  if (!(y0.norm() > 0))
    throw std::runtime_error(scene.file.string() + ": initial: the initial state is zero (nothing moves): "
                             "give initial.tilt or initial.rate");
  const double T = scene.run.t_end;
  const auto state_at_end = [&](int per_period) { return PeriodicPropagator(g, settled.s, per_period, y0).at(T); };
  Eigen::VectorXd ref;
  const Timing tr = time_runs([&] { ref = state_at_end(4 * settled.per_period); }, 0);
  const Eigen::VectorXd half = state_at_end(2 * settled.per_period);
  out.spectral_radius = Eigen::EigenSolver<Eigen::MatrixXd>(periodic_matrix(g, 0, settled.s), false)
                            .eigenvalues().cwiseAbs().maxCoeff();
  out.dimension = static_cast<int>(y0.size());
  out.reference_mantissa_bits = 0;  // a double-precision reference: Magnus steps, four times as many
  add_work_row(out.rows, progress, "reference", "magnus_difference", BenchRow::nan, -1, tr,
               relative_error(half.cast<cd>(), ref.cast<cd>()));
  for (int n = 8; n <= 2 * settled.per_period; n *= 2) {
    const long steps = std::lround(std::ceil(T / (g.period / n)));
    if (steps > opt.max_steps) break;
    Eigen::VectorXd y;
    const Timing t = time_runs([&] { y = state_at_end(n); }, opt.min_seconds);
    add_work_row(out.rows, progress, "magnus", "step", g.period / n, steps, t, relative_error(y.cast<cd>(), ref.cast<cd>()));
  }
}

// The tanks of body k in scene order: [body.cavity] then every further [[body.cavity]].
std::vector<CavitySpec*> tanks_of(BodySpec& b) {
  std::vector<CavitySpec*> out;
  if (b.cavity) out.push_back(&*b.cavity);
  for (auto& c : b.more_cavities) out.push_back(&c);
  return out;
}

// The roots σ = −i μ of the chain whose eigenvector is mostly the bodies' (kinetic energy Q̇ᴴ M Q̇ against the modes'
// Σ|z|²), leaving out roots below 1e-8 of the spectral radius (the axial angles' zero roots).
// (At two spins: the Floquet roots, each with the monodromy's eigenvector, its state at t = 0.)
std::vector<cd> body_roots(const GeneralChain& g) {
  std::vector<cd> sigma;
  Eigen::MatrixXcd vectors;
  if (g.periodic()) {
    FloquetModes f = floquet_modes(g);
    sigma = std::move(f.roots);
    vectors = std::move(f.vectors);
  } else {
    const Eigen::EigenSolver<Eigen::MatrixXd> es(build_general_system(g).B, true);
    if (es.info() != Eigen::Success) throw std::runtime_error("bench: the eigen-solver did not converge");
    for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) sigma.push_back(cd(0, -1) * es.eigenvalues()[i]);
    vectors = es.eigenvectors();
  }
  const int nq = 2 * g.n, dq = g.dim_q();
  double rho = 0;
  for (const cd x : sigma) rho = std::max(rho, std::abs(x));
  std::vector<cd> roots;
  for (std::size_t i = 0; i < sigma.size(); ++i) {
    const Eigen::VectorXcd v = vectors.col(static_cast<Eigen::Index>(i));
    const Eigen::VectorXcd rates = v.segment(nq, dq);
    const double bodies = (rates.adjoint() * g.M.cast<cd>() * rates)(0).real(), modes = v.tail(v.size() - nq - dq).squaredNorm();
    if (bodies > modes && std::abs(sigma[i]) > 1e-8 * rho) roots.push_back(sigma[i]);
  }
  return roots;
}

// At two spins a root's frequency is defined modulo Ω: each root moved by a multiple of Ω to the reference root
// nearest it, so that a truncation is compared with the roots it approximates, not with another branch.
std::vector<cd> nearest_branches(std::vector<cd> roots, const std::vector<cd>& reference, double omega) {
  for (cd& r : roots) {
    double best = 1e300, shift = 0;
    for (const cd& x : reference) {
      const double k = std::round((x.real() - r.real()) / omega);
      const double d = std::abs(r + cd(k * omega, 0) - x);
      if (d < best) best = d, shift = k * omega;
    }
    r += cd(shift, 0);
  }
  return roots;
}

void roots_against_rows(const Scene& scene, BenchResult& out, const std::function<void(const BenchRow&)>& progress) {
  TableCache tables;
  Scene full = scene;
  for (BodySpec& b : full.bodies)
    for (CavitySpec* c : tanks_of(b)) c->modes.reset(), c->coverage.reset();
  const std::vector<cd> reference = body_roots(build_general_chain(full, &tables));
  const std::vector<GeneralBody> bodies = general_bodies(full, tables);
  int tank_index = 0;  // GeneralChain::coverage runs over the tanks body by body
  for (int k = 0; k < static_cast<int>(bodies.size()); ++k)
    for (std::size_t i = 0; i < bodies[k].tanks.size(); ++i, ++tank_index) {
      std::set<int> rows;
      for (const GeneralMode& m : bodies[k].tanks[i].modes) rows.insert(m.table_row);
      const int all = static_cast<int>(rows.size());
      if (all < 2 || tanks_of(full.bodies[k])[i]->bands) continue;  // nothing to truncate (bands: the whole measure)
      for (int q = 1;; q = std::min(2 * q, all)) {
        Scene s = full;
        tanks_of(s.bodies[k])[i]->modes = q;
        GeneralChain g;
        std::vector<cd> roots;
        const Timing t = time_runs([&] {
          g = build_general_chain(s, &tables);
          roots = general_spectrum(g).roots;
        }, 0);
        if (g.periodic()) roots = nearest_branches(roots, reference, 2 * M_PI / g.period);
        add_roots_row(out, progress, {k, q, 0, 1.0, g.coverage[tank_index].second}, t, body_root_error(reference, roots));
        if (q == all) break;
      }
    }
}

}  // namespace

void general_bench(const Scene& scene, const BenchOptions& options, BenchResult& out,
                   const std::function<void(const BenchRow&)>& progress) {
  TableCache tables;
  const GeneralChain g = build_general_chain(scene, &tables);
  if (g.periodic())
    periodic_work_precision(scene, g, options, out, progress);
  else
    work_precision(scene, g, options, out, progress);
  roots_against_rows(scene, out, progress);
}

}  // namespace rc::rom
