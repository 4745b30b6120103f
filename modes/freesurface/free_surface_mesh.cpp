#include "free_surface_mesh.hpp"

#include "complex_eigen.hpp"
#include "free_surface_quadratic.hpp"

#include "eigen_dense.hpp"
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rc::modes {

namespace {

constexpr double kGeostrophic = 1e-5;  // |λ| below this is the geostrophic λ = 0 (see below)

// The companion matrix [0 I; −A2⁻¹A0, −A2⁻¹A1] of the symmetric quadratic (header) in (x, y).
Eigen::MatrixXd companion(const FreeSurfaceQuadratic& f) {
  const auto A = f.coefficients();
  const Eigen::Index n = f.pressure_dofs(), m = f.unknowns();
  const Eigen::MatrixXd A2 = Eigen::MatrixXd(A[2]);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A2);
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(2 * m, 2 * m);
  L.topRightCorner(m, m).setIdentity();
  L.bottomLeftCorner(m, m) = -lu.solve(Eigen::MatrixXd(A[0]));
  L.block(m, m, m, n) = -lu.solve(Eigen::MatrixXd(A[1]).leftCols(n));  // λx̂'s x part: A1 is zero on y
  return L;
}

}  // namespace

PartialFillSpectrum solve_partially_filled_mesh(const FESpace& space, int max_unknowns, bool keep_pressure) {
  const FreeSurfaceQuadratic f = free_surface_quadratic(space);
  const long n = f.pressure_dofs(), m = f.unknowns();
  if (m > max_unknowns)
    throw std::runtime_error(fmt::format("free surface: {} unknowns (pressure and surface) > {}, the dense solver's "
                                         "limit: take a larger --mesh-size or a lower --order", m, max_unknowns));
  PartialFillSpectrum out = spectrum_integrals(space, f);

  const ComplexEigen eig = real_eigen(companion(f), true, "the free surface's companion matrix");
  for (Eigen::Index i = 0; i < eig.values.size(); ++i) {
    const std::complex<double> lc = eig.values(i);
    // λ = 0 is a defective eigenvalue of high multiplicity (the steady geostrophic motions, Kz p = 0): rounding
    // splits it into a cloud of |λ| ~ 1e-7 with complex members (measured: 28 of 1000 on the fill 0.9 cylinder, all
    // |λ| < 2e-7). Those hold no surface displacement and couple to nothing; real small ones are kept (a cone's
    // dense spectrum near 0 carries 3e-8 of its sum rule at 1e-9 < |λ| < 1e-5).
    const bool complex = std::abs(lc.imag()) > 1e-7 * std::max(1.0, std::abs(lc));
    if (complex && std::abs(lc) < kGeostrophic) {
      out.pairs.push_back(PartialFillPair{});
      continue;
    }
    if (complex)
      throw std::runtime_error(fmt::format("free surface: a complex eigenvalue {} + {}i", lc.real(), lc.imag()));
    Eigen::Index big = 0;
    eig.vectors.col(i).head(n).cwiseAbs().maxCoeff(&big);
    const std::complex<double> phase = eig.vectors(big, i) / std::abs(eig.vectors(big, i));
    const Eigen::VectorXd x = (eig.vectors.col(i).head(n) / phase).real();
    out.pairs.push_back(free_surface_pair(f, lc.real(), x));
    if (keep_pressure) out.pairs.back().pressure.assign(x.data(), x.data() + x.size());
  }
  std::sort(out.pairs.begin(), out.pairs.end(),
            [](const PartialFillPair& x, const PartialFillPair& y) { return x.coupling.E > y.coupling.E; });
  for (const auto& p : out.pairs) out.sum_E += p.coupling.E;
  return out;
}

}  // namespace rc::modes
