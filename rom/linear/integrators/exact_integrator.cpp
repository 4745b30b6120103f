// run.method = "exact" (the default): y(t) = V e^{i sigma t} V^{-1} y(0) at every output time (no accumulation), or,
// where V is ill-conditioned (a defective spectrum), y_{j+1} = exp(B h) y_j.
#include "integrator.hpp"

#include "exact_propagation.hpp"
#include "matrix_exponential.hpp"
#include "verdict.hpp"

namespace rc::rom {
namespace {

// method = "exact": the eigen-decomposition, or the step's matrix exponential where its eigenvectors are
// ill-conditioned.
void run_exact(const IntegratorRun& r) {
  const ChainModel& m = r.model;
  const FirstOrderSystem& f = r.system;
  const double h = r.h;
  const long steps = r.steps;
  StateSink& rec = r.sink;
  History& hist = r.history;
  ModalForm mf = modal_form(f, !m.dissipative(), kRealTolerance);
  hist.eigvec_condition = mf.condition;
  hist.integrator_steps = steps;
  if (mf.usable) {
    // Undamped and stable: the roots are real; drop their rounding-level imaginary parts so that
    // |e^{i sigma t}| = 1 exactly and the energy cannot drift over long runs (the real form has
    // exactly real roots already).
    const bool snap = mf.undamped_real;
    if (snap && !mf.real) snap_to_imaginary_axis(mf);
    modal_states(mf, r.y0, h, steps,
                 [&](long j0, const Eigen::Ref<const Eigen::MatrixXd>& re, const Eigen::Ref<const Eigen::MatrixXd>& im) {
                   rec.store_block(j0, re, im);
                 });
    hist.method_used = snap ? "exact (eigen-decomposition, real roots)" : "exact (eigen-decomposition)";
    return;
  }
  const Eigen::MatrixXcd Phi = rc::matrix_exponential(Eigen::MatrixXcd(f.B * std::complex<double>(h)));
  Eigen::VectorXcd y = r.y0;
  rec.store(0, y);
  for (long j = 1; j <= steps; ++j) {
    y = Phi * y;
    rec.store(j, y);
  }
  hist.method_used = "exact (matrix exponential of the step; eigenvectors ill-conditioned)";
}

}  // namespace

LinearIntegrator exact_integrator() { return {"exact", nullptr, run_exact}; }

}  // namespace rc::rom
