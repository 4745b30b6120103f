#include "general_bench.hpp"

#include "balancing.hpp"
#include "general_chain.hpp"
#include "general_run.hpp"
#include "general_system.hpp"
#include "reference_propagation.hpp"
#include "work_precision.hpp"

#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/MatrixFunctions>

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
    y = S.cast<cd>().asDiagonal() * ((B * cd(w.T)).exp() * (w.y0.array() / S.cast<cd>().array()).matrix());
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

// The tanks of body k in scene order: [body.cavity] then every further [[body.cavity]].
std::vector<CavitySpec*> tanks_of(BodySpec& b) {
  std::vector<CavitySpec*> out;
  if (b.cavity) out.push_back(&*b.cavity);
  for (auto& c : b.more_cavities) out.push_back(&c);
  return out;
}

// The roots σ = −i μ of the chain whose eigenvector is mostly the bodies' (kinetic energy Q̇ᴴ M Q̇ against the modes'
// Σ|z|²), leaving out roots below 1e-8 of the spectral radius (the axial angles' zero roots).
std::vector<cd> body_roots(const GeneralChain& g) {
  const GeneralSystem sys = build_general_system(g);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(sys.B, true);
  if (es.info() != Eigen::Success) throw std::runtime_error("bench: the eigen-solver did not converge");
  const int nq = 2 * g.n, dq = g.dim_q();
  const double rho = es.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<cd> roots;
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
    const Eigen::VectorXcd v = es.eigenvectors().col(i);
    const Eigen::VectorXcd rates = v.segment(nq, dq);
    const double bodies = (rates.adjoint() * g.M.cast<cd>() * rates)(0).real(), modes = v.tail(v.size() - nq - dq).squaredNorm();
    if (bodies > modes && std::abs(es.eigenvalues()[i]) > 1e-8 * rho) roots.push_back(cd(0, -1) * es.eigenvalues()[i]);
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
        add_roots_row(out, progress, {k, q, 0, 1.0, g.coverage[tank_index].second}, t, body_root_error(reference, roots));
        if (q == all) break;
      }
    }
}

}  // namespace

void general_bench(const Scene& scene, const BenchOptions& options, BenchResult& out,
                   const std::function<void(const BenchRow&)>& progress) {
  TableCache tables;
  work_precision(scene, build_general_chain(scene, &tables), options, out, progress);
  roots_against_rows(scene, out, progress);
}

}  // namespace rc::rom
