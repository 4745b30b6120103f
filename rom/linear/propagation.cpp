#include "propagation.hpp"

#include "energy.hpp"
#include "first_order_system.hpp"
#include "forced_solution.hpp"
#include "verdict.hpp"

#include "eigen_dense.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <ctime>
#include <cstdio>
#include <stdexcept>

namespace rc::rom {
using cd = std::complex<double>;

namespace {

// Largest |sigma| of the first-order system (eigenvalues only).
double spectral_radius_of(const FirstOrderSystem& f) {
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(f.B, false);
  double rho = 0;
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) rho = std::max(rho, std::abs(es.eigenvalues()[i]));
  return rho;
}

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", x);
  return buf;
}

}  // namespace

namespace {

// The initial state of (26) in first-order form: the scene's tilts and rates, the fluid at rest relative to its
// body unless the scene says otherwise.
Eigen::VectorXcd initial_state(const ChainModel& m, const Scene& scene, const FirstOrderSystem& f) {
  const int n = m.n, nm = m.n_modes();
  Eigen::VectorXcd u0(n), v0(n);
  for (int k = 0; k < n; ++k) {
    u0[k] = scene.tilt[k];
    v0[k] = scene.rate[k];
  }
  return f.to_state(m, u0, v0, initial_fluid(scene, nm));
}

// The integrators' cost before any work: refused, with why, when the scene is too stiff for them.
double checked_spectral_radius(const FirstOrderSystem& f, const Scene& scene, const LinearIntegrator& integrator) {
  const std::string& method = integrator.name;
  if (!integrator.estimate_steps) return -1;
  const double rho = spectral_radius_of(f);
  const double est = integrator.estimate_steps(rho, scene.run);
  if (!(est <= kMaxIntegratorSteps))
    throw std::runtime_error(scene.file.string() + ": run.method: " + method + " would need about " + sci(est) +
                             " steps (fastest root |sigma| = " + sci(rho) + " rad/s, t_end = " +
                             sci(scene.run.t_end) + " s, tolerance = " + sci(scene.run.tolerance) +
                             "; limit " + sci(kMaxIntegratorSteps) +
                             "): the scene is too stiff for it, use method = \"exact\"");
  return rho;
}

// Writes the states of a run into its History: tilts, fluid amplitudes relative to their bodies, the energy and,
// with viscous tanks, the frozen chain's budget (energy_budget.hpp) and, with Galerkin tanks, the fluid's energy
// balance (galerkin_energy.hpp).
class Recorder final : public StateSink {
 public:
  // `forced`: the particular solution added to every stored state (the run propagates the free part only).
  Recorder(const ChainModel& m, const FirstOrderSystem& f, double h, long steps, History& hist,
           const ForcedSolution* forced)
      : m_(m), f_(f), h_(h), n_(m.n), nm_(m.n_modes()), hist_(hist), meter_(m), forced_(forced) {
    // Sized here, not when first written: exact propagation stores its blocks from several threads.
    if (forced) power_.resize(steps + 1);
    hist.t.resize(steps + 1);
    hist.u.resize(steps + 1, n_);
    hist.z.resize(steps + 1, nm_);
    hist.H.resize(steps + 1);
    hist.H_scale.resize(steps + 1);
    // The frozen chain's budget (energy_budget.hpp) has no base translation: not kept for a free chain with a partially
    // filled tank (base_translation.hpp).
    if (m.viscous && !m.extended) {
      budget_meter_.emplace(m, f);
      budget_.resize(steps + 1);
    }
    if (m.viscous && galerkin_energy_unavailable(m).empty()) {
      balance_meter_.emplace(m);
      balance_.resize(steps + 1);
    }
  }

  void store(long j, const Eigen::VectorXcd& free_part) override {
    const Eigen::VectorXcd y = forced_ ? Eigen::VectorXcd(free_part + forced_->at(j * h_)) : free_part;
    if (budget_meter_) budget_[j] = (*budget_meter_)(y);
    if (balance_meter_) measure_balance(j, y);
    Eigen::VectorXcd u, v, w;
    f_.from_state(m_, y, u, v, w);
    hist_.t[j] = j * h_;
    hist_.u.row(j) = u.transpose();
    hist_.z.row(j) = fluid_coordinates(m_, v, w).transpose();
    if (forced_) record_power(j, v);
    const Energy e = meter_(u, v, w);
    hist_.H[j] = e.total();
    hist_.H_scale[j] = e.scale();
  }

  // Columns of re + i*im are the states at j0, j0 + 1, ... (exact propagation's blocks).
  void store_block(long j0, const Eigen::Ref<const Eigen::MatrixXd>& re,
                   const Eigen::Ref<const Eigen::MatrixXd>& im) override {
    if (!forced_) return store_states(j0, re, im);
    Eigen::MatrixXd re_total = re, im_total = im;
    for (long i = 0; i < re.cols(); ++i) {
      const Eigen::VectorXcd yp = forced_->at((j0 + i) * h_);
      re_total.col(i) += yp.real();
      im_total.col(i) += yp.imag();
    }
    store_states(j0, re_total, im_total);
  }

  // The energy's drift (no H with viscous tanks: the budget and the balance instead).
  void finish(long steps) {
    const double H0 = hist_.H[0], S0 = std::max(hist_.H_scale[0], 1e-300);
    hist_.forced = forced_ != nullptr;
    if (m_.viscous) {
      hist_.max_energy_drift = std::numeric_limits<double>::quiet_NaN();  // no H (energy.cpp)
      hist_.budget = energy_budget(budget_, h_);
      if (balance_meter_) hist_.balance = energy_balance(balance_, h_);
      return;
    }
    if (forced_) {  // the moments do work: H is the chain's energy, not an integral, and its change is their work
      hist_.max_energy_drift = std::numeric_limits<double>::quiet_NaN();
      if (!m_.has_circulatory()) hist_.work_balance = work_balance(steps, H0, S0);
      return;
    }
    for (long j = 1; j <= steps; ++j) {
      if (m_.has_friction()) hist_.max_energy_drift = std::max(hist_.max_energy_drift, (hist_.H[j] - hist_.H[j - 1]) / S0);
      else hist_.max_energy_drift = std::max(hist_.max_energy_drift, std::abs(hist_.H[j] - H0) / S0);
    }
  }

 private:
  void store_states(long j0, const Eigen::Ref<const Eigen::MatrixXd>& re, const Eigen::Ref<const Eigen::MatrixXd>& im) {
    const long cols = re.cols();
    const double is = 1.0 / f_.s;
    for (long i = 0; i < cols; ++i) {
      const long j = j0 + i;
      hist_.t[j] = j * h_;
      for (int k = 0; k < n_; ++k) hist_.u(j, k) = cd(re(k, i) * is, im(k, i) * is);
      // z = w - w_rowᵀ u-dot (the mode's coupling row, chain_model.hpp)
      const Eigen::VectorXcd v = re.col(i).segment(n_, n_).cast<cd>() + cd(0, 1) * im.col(i).segment(n_, n_).cast<cd>(),
                             w = re.col(i).tail(nm_).cast<cd>() + cd(0, 1) * im.col(i).tail(nm_).cast<cd>();
      hist_.z.row(j) = fluid_coordinates(m_, v, w).transpose();
    }
    if (forced_)
      for (long i = 0; i < cols; ++i) {
        const Eigen::VectorXcd y = re.col(i).cast<cd>() + cd(0, 1) * im.col(i).cast<cd>();
        record_power(j0 + i, y.segment(n_, n_));
      }
    if (budget_meter_)
      for (long i = 0; i < cols; ++i) budget_[j0 + i] = (*budget_meter_)(re.col(i).cast<cd>() + cd(0, 1) * im.col(i).cast<cd>());
    if (balance_meter_)
      for (long i = 0; i < cols; ++i) measure_balance(j0 + i, re.col(i).cast<cd>() + cd(0, 1) * im.col(i).cast<cd>());
    meter_.block(re.topRows(n_) * is, im.topRows(n_) * is, re.middleRows(n_, n_), im.middleRows(n_, n_),
                 re.bottomRows(nm_), im.bottomRows(nm_), &hist_.H[j0], &hist_.H_scale[j0]);
  }

  // The power of the external moments less the friction's at sample j: Re(F̄ᵀu̇) − u̇ᴴDu̇ (dH/dt, docs/rom.md "Energy").
  void record_power(long j, const Eigen::VectorXcd& v) {
    power_[j] = forced_->moments_at(j * h_).dot(v).real() - v.dot(m_.D.cast<cd>() * v).real();
  }

  // Against the largest energy scale of the run (the moments may pump it up from next to nothing).
  double work_balance(long steps, double H0, double S0) const {
    double work = 0, worst = 0, scale = S0;
    for (long j = 1; j <= steps; ++j) {
      work += 0.5 * h_ * (power_[j - 1] + power_[j]);
      worst = std::max(worst, std::abs(hist_.H[j] - H0 - work));
      scale = std::max(scale, hist_.H_scale[j]);
    }
    return worst / scale;
  }

  void measure_balance(long j, const Eigen::VectorXcd& y) {
    Eigen::VectorXcd u, v, w;
    f_.from_state(m_, y, u, v, w);
    const Eigen::VectorXcd z = fluid_coordinates(m_, v, w);
    balance_[j] = (*balance_meter_)(u, v, z);
  }

  const ChainModel& m_;
  const FirstOrderSystem& f_;
  const double h_;
  const int n_, nm_;
  History& hist_;
  const EnergyMeter meter_;
  std::optional<BudgetMeter> budget_meter_;
  std::vector<BudgetSample> budget_;
  std::optional<GalerkinEnergyMeter> balance_meter_;
  std::vector<EnergySample> balance_;
  const ForcedSolution* forced_;
  std::vector<double> power_;  // forced runs: dH/dt at each sample
};

}  // namespace

History propagate(const ChainModel& m, const Scene& scene) {
  if (!scene.run.present) throw std::runtime_error(scene.file.string() + ": run: missing [run] section");
  const auto start = std::chrono::steady_clock::now();
  timespec cpu0{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu0);
  const FirstOrderSystem f = build_first_order(m);
  const Eigen::VectorXcd y0 = initial_state(m, scene, f);
  const double h = scene.run.output_step;
  const long steps = static_cast<long>(std::floor(scene.run.t_end / h + 1e-9));
  if (steps > 50000000L) throw std::runtime_error("run.output_step: more than 5e7 output steps");
  const LinearIntegrator& integrator = linear_integrator(scene);
  const double rho = checked_spectral_radius(f, scene, integrator);  // fastest |sigma|, for the step-controlled ones

  // External moments: the particular solution in closed form, the free part from y(0) − y_p(0) (forced_solution.hpp).
  const ForcedSolution forced = forced_solution(m, f, scene);
  const Eigen::VectorXcd y_free = forced.present ? Eigen::VectorXcd(y0 - forced.at(0)) : y0;
  History hist;
  Recorder rec(m, f, h, steps, hist, forced.present ? &forced : nullptr);
  integrator.run({m, f, y_free, h, steps, rho, scene.run, rec, hist});
  rec.finish(steps);
  if (m.axial.moves()) {
    const AxialHistory axial = axial_history(m.axial, hist.t);
    hist.spin = axial.spin;
    hist.axial_angle = axial.angle;
  }
  hist.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  timespec cpu1{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu1);
  hist.cpu_seconds = static_cast<double>(cpu1.tv_sec - cpu0.tv_sec) + 1e-9 * static_cast<double>(cpu1.tv_nsec - cpu0.tv_nsec);
  return hist;
}

}  // namespace rc::rom
