#include "spectrum.hpp"

#include "characteristic.hpp"
#include "complex_eigen.hpp"
#include "first_order_system.hpp"
#include "real_root_certificate.hpp"
#include "root_newton.hpp"

#include "eigen_dense.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace rc::rom {

// Verdict from the roots sigma (their largest modulus is the spectral radius of B).
Verdict verdict_from_roots(const ChainModel& m, const Eigen::VectorXcd& sigma) {
  return verdict_of_roots(sigma, m.dissipative());
}

Eigen::VectorXcd verdict_roots(const ChainModel& m) {
  using cd = std::complex<double>;
  const FirstOrderSystem f = build_first_order(m);
  if (!m.dissipative()) {
    // Without friction, sigma are the eigenvalues of -iB, and -iB conjugated by diag(iI, I, I)
    // (rows of the s*u block times -i, its columns times i) is real: the real QR algorithm does
    // the same job at about a quarter of the cost of the complex one.
    Eigen::MatrixXcd A = cd(0, -1) * f.B;
    const int n = f.n;
    A.topRows(n) *= cd(0, -1);
    A.leftCols(n) *= cd(0, 1);
    const Eigen::MatrixXd real_part = A.real();  // a plain matrix: compute() for it is compiled once (eigen_dense.hpp)
    Eigen::EigenSolver<Eigen::MatrixXd> es(real_part, false);
    if (es.info() != Eigen::Success) throw std::runtime_error("eigen-solver did not converge");
    return es.eigenvalues();
  }
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(f.B, false);
  if (es.info() != Eigen::Success) throw std::runtime_error("eigen-solver did not converge");
  return cd(0, -1) * es.eigenvalues();
}

Verdict compute_verdict(const ChainModel& m) { return verdict_from_roots(m, verdict_roots(m)); }

namespace {

// Root j of the first-order system with its owner (the largest share of the eigenvector's kinetic measure), its
// residual in (22) and how far Newton on det Φ moves it.
Root root_of(const ChainModel& m, const ComplexEigen& es, int j, double radius, Spectrum& sp) {
  using cd = std::complex<double>;
  const int n = m.n;
  Root r;
  r.sigma = cd(0, -1) * es.values[j];  // y ~ e^{mu t} = e^{i sigma t}
  const Eigen::VectorXcd y = es.vectors.col(j);
  double best = -1;
  for (int k = 0; k < n; ++k) {
    const double wgt = m.M_eff(k, k) * (std::norm(y[k]) + std::norm(y[n + k]));
    if (wgt > best) { best = wgt; r.owner = "body " + std::to_string(k + 1); }
  }
  std::vector<int> count(n, 0);
  const Eigen::VectorXcd z = fluid_coordinates(m, y.segment(n, n), y.tail(m.n_modes()));
  for (int l = 0; l < m.n_modes(); ++l) {
    const FluidMode& md = m.modes[l];
    ++count[md.body];
    const double wgt = std::abs(md.E_c()) * std::norm(z[l]);
    if (wgt > best) {
      best = wgt;
      r.owner = "fluid " + std::to_string(md.body + 1) + "." + std::to_string(count[md.body]);
      r.unconverged_owner = md.converged == 0;
    }
  }
  r.residual = characteristic_residual(m, r.sigma, std::max(radius, 1e-300));
  r.newton_shift = std::numeric_limits<double>::quiet_NaN();
  if (!std::isnan(r.residual)) {
    const NewtonRoot nr = newton_root(m, r.sigma, std::max(radius, 1e-300));
    if (nr.converged) r.newton_shift = std::abs(nr.sigma - r.sigma) / std::max(radius, 1e-300);
    else ++sp.newton_failed;
  }
  return r;
}

// The spectrum's tallies over its (sorted) roots: residuals, Newton's agreement, unconverged owners and the roots
// outside a response fit's window.
void tally_roots(const ChainModel& m, Spectrum& sp) {
  for (Root& r : sp.roots) {
    if (std::isnan(r.residual)) ++sp.unchecked;
    else sp.det_residual = std::max(sp.det_residual, r.residual);
    if (!std::isnan(r.newton_shift)) sp.root_agreement = std::max(sp.root_agreement, r.newton_shift);
    if (r.unconverged_owner) ++sp.unconverged_owners;
    for (const BodyModel& b : m.bodies)
      if (b.fit_hi > b.fit_lo && b.omega != 0) {
        const double s = ((r.sigma + b.omega) / b.omega).real();
        r.fit_decay_error = std::max(r.fit_decay_error, b.fit_decay_error_at(s));
        if ((s < b.fit_lo || s > b.fit_hi) && !r.outside_fit) {
          ++sp.outside_fit;
          r.outside_fit = true;
        }
      }
  }
}

// The verdict's numbers, the fits' passivity and the certificate of real roots.
void set_verdict(const ChainModel& m, const Verdict& v, Spectrum& sp) {
  sp.margin = v.margin;
  sp.growth = v.growth;
  sp.noise = v.noise;
  sp.growing = v.growing;
  sp.at_zero = v.at_zero;
  sp.nonreal = v.nonreal;
  sp.stable = v.stable;
  for (int k = 0; k < m.n; ++k) {
    sp.passivity.push_back(fit_passivity(m, k));
    if (!sp.passivity.back().passive()) ++sp.fits_not_passive;
  }
  const RealRootCertificate c = certify_real_roots(m, sp);
  if (c.applies) {
    sp.certified_real = c.proven;
    sp.certificate_roots = c.roots;
    sp.roots_at_zero = c.at_zero;
  }
  if (v.stable && !m.dissipative()) {
    Eigen::VectorXcd sigma(sp.roots.size());
    for (size_t j = 0; j < sp.roots.size(); ++j) sigma[static_cast<Eigen::Index>(j)] = sp.roots[j].sigma;
    sp.krein = krein_gap(m, sigma, sp.tolerance);
  }
}

}  // namespace

Spectrum compute_spectrum(const ChainModel& m) {
  using cd = std::complex<double>;
  const FirstOrderSystem f = build_first_order(m);
  const ComplexEigen es = complex_eigen(f.B, true);
  Spectrum sp;
  const Verdict v = verdict_from_roots(m, cd(0, -1) * es.values);
  sp.tolerance = v.tolerance;
  for (int j = 0; j < f.dim(); ++j) sp.roots.push_back(root_of(m, es, j, v.radius, sp));
  std::sort(sp.roots.begin(), sp.roots.end(), [](const Root& a, const Root& b) {
    if (a.sigma.real() != b.sigma.real()) return a.sigma.real() < b.sigma.real();
    return a.sigma.imag() < b.sigma.imag();
  });
  tally_roots(m, sp);
  set_verdict(m, v, sp);
  sp.axial = axial_spectrum(m.axial);
  return sp;
}

}  // namespace rc::rom
