#include "galerkin_fluid.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::rom {
namespace {

using cd = std::complex<double>;

Eigen::MatrixXcd submatrix(const std::vector<double>& re, const std::vector<double>& im, std::size_t n,
                           const std::vector<int>& rows) {
  const Eigen::Index k = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXcd S(k, k);
  for (Eigen::Index i = 0; i < k; ++i)
    for (Eigen::Index j = 0; j < k; ++j) {
      const std::size_t ij = static_cast<std::size_t>(rows[i]) * n + static_cast<std::size_t>(rows[j]);
      S(i, j) = cd(re[ij], im[ij]);
    }
  return S;
}

}  // namespace

GalerkinFluid galerkin_fluid(const rc::ModeTable& t, const std::vector<int>& rows) {
  const Eigen::Index k = static_cast<Eigen::Index>(rows.size());
  GalerkinFluid out;
  if (!t.viscous()) {  // orthogonal modes: G = I, f_l = √(E_l/π), V = 0
    out.residue.resize(k);
    for (Eigen::Index i = 0; i < k; ++i) out.residue[i] = t.E[rows[i]];
    out.energy = out.residue.real().asDiagonal().toDenseMatrix().cast<cd>();
    out.dissipation = Eigen::MatrixXcd::Zero(k, k);
    return out;
  }
  if (!t.has_galerkin())
    throw std::runtime_error(t.response_fit()
                                 ? "a rational fit's poles are not modes and carry no Galerkin matrices; use a damped-"
                                   "mode table (cavity-modes SHAPE ... --ekman Ek) or a Galerkin response table "
                                   "(cavity-modes response ... --galerkin -o FILE.h5)"
                                 : "the table holds no /galerkin matrices (made before they were written); make it "
                                   "again with cavity-modes SHAPE ... --ekman Ek");
  const std::size_t n = t.size();
  const Eigen::MatrixXcd G = submatrix(t.galerkin.gram_re, t.galerkin.gram_im, n, rows);
  const Eigen::MatrixXcd V = submatrix(t.galerkin.viscous_re, t.galerkin.viscous_im, n, rows);
  // f_l = fᵀx_l: stored for a Galerkin response table's Ritz vectors, else the damped mode's √(2/π)(a + i a_imag).
  const bool stored = !t.galerkin.coupling_re.empty();
  Eigen::VectorXcd f(k);
  for (Eigen::Index i = 0; i < k; ++i)
    f[i] = stored ? cd(t.galerkin.coupling_re[rows[i]], t.galerkin.coupling_im[rows[i]])
                  : std::sqrt(2 / std::numbers::pi) * cd(t.a[rows[i]], t.a_imag[rows[i]]);
  const Eigen::LLT<Eigen::MatrixXcd> llt(G);
  if (llt.info() != Eigen::Success)
    throw std::runtime_error("the kept modes' Gram matrix is not positive definite (two kept modes alike)");
  const Eigen::VectorXcd g = llt.solve(f.conjugate());
  out.residue = std::numbers::pi * f.cwiseProduct(g);
  const auto Dg = g.asDiagonal();
  out.energy = std::numbers::pi * (Dg.toDenseMatrix().adjoint() * G * Dg);
  out.dissipation = std::numbers::pi * (Dg.toDenseMatrix().adjoint() * V * Dg);
  return out;
}

}  // namespace rc::rom
