#include "spectrum.hpp"

#include "characteristic.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace rc::rom {

Spectrum compute_spectrum(const ChainModel& m) {
  using cd = std::complex<double>;
  const FirstOrderSystem f = build_first_order(m);
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(f.B, true);
  if (es.info() != Eigen::Success) throw std::runtime_error("eigen-solver did not converge");
  const int n = m.n, D = f.dim();
  Spectrum sp;
  double radius = 0;
  for (int j = 0; j < D; ++j) radius = std::max(radius, std::abs(es.eigenvalues()[j]));
  sp.tolerance = kRealTolerance * std::max(radius, 1e-300);
  for (int j = 0; j < D; ++j) {
    Root r;
    r.sigma = cd(0, -1) * es.eigenvalues()[j];  // y ~ e^{mu t} = e^{i sigma t}
    const Eigen::VectorXcd y = es.eigenvectors().col(j);
    // Owner: the largest share of the eigenvector's kinetic measure.
    double best = -1;
    for (int k = 0; k < n; ++k) {
      const double wgt = m.M_eff(k, k) * (std::norm(y[k]) + std::norm(y[n + k]));
      if (wgt > best) { best = wgt; r.owner = "body " + std::to_string(k + 1); }
    }
    std::vector<int> count(n, 0);
    for (int l = 0; l < m.n_modes(); ++l) {
      const FluidMode& md = m.modes[l];
      ++count[md.body];
      const double wgt = md.E * std::norm(y[2 * n + l] - y[n + md.body]);
      if (wgt > best) {
        best = wgt;
        r.owner = "fluid " + std::to_string(md.body + 1) + "." + std::to_string(count[md.body]);
      }
    }
    r.residual = characteristic_residual(m, r.sigma, std::max(radius, 1e-300));
    sp.roots.push_back(r);
  }
  std::sort(sp.roots.begin(), sp.roots.end(), [](const Root& a, const Root& b) {
    if (a.sigma.real() != b.sigma.real()) return a.sigma.real() < b.sigma.real();
    return a.sigma.imag() < b.sigma.imag();
  });
  for (const Root& r : sp.roots) {
    sp.margin = std::max(sp.margin, std::abs(r.sigma.imag()));
    sp.growth = std::max(sp.growth, -r.sigma.imag());
    if (std::isnan(r.residual)) ++sp.unchecked;
    else sp.det_residual = std::max(sp.det_residual, r.residual);
  }
  // Without friction the seed's necessary condition: all roots real. With friction roots move
  // into Im sigma > 0 (decay); stable then means no root with Im sigma < 0 (growth).
  sp.stable = m.has_friction() ? sp.growth <= sp.tolerance : sp.margin <= sp.tolerance;
  return sp;
}

}  // namespace rc::rom
