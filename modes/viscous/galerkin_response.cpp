#include "galerkin_response.hpp"

#include <fmt/format.h>

#include <numbers>
#include <stdexcept>

namespace rc::modes {

OffsetResponse GalerkinReduction::entries(std::complex<double> s) const {
  OffsetResponse r{0, 0, 0};
  for (std::size_t l = 0; l < lambda.size(); ++l) {
    const std::complex<double> w = 1.0 / (s - lambda[l]);
    r.ff += residue[l] * w;
    if (!residue_fg.empty()) {
      r.fg += residue_fg[l] * w;
      r.gg += residue_gg[l] * w;
    }
  }
  return r;
}

GalerkinReduction reduce_on_span(const GalerkinMatrices& g, double rank_tolerance) {
  using cd = std::complex<double>;
  // Orthonormal coordinates: T = U_k Γ_k^{-1/2} from G = UΓUᴴ, so that TᴴGT = I (Q = XT).
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> es(g.gram);
  const Eigen::VectorXd& gamma = es.eigenvalues();  // ascending
  const double top = gamma.maxCoeff();
  Eigen::Index first = 0;
  while (first < gamma.size() && !(gamma[first] > rank_tolerance * top)) ++first;
  const Eigen::Index r = gamma.size() - first;
  if (r == 0) throw std::runtime_error("the forced solutions span nothing (their Gram matrix is 0)");
  const Eigen::MatrixXcd T = es.eigenvectors().rightCols(r) * gamma.tail(r).cwiseSqrt().cwiseInverse().asDiagonal();
  const Eigen::MatrixXcd Hq = T.adjoint() * g.op * T;
  const Eigen::VectorXcd cq = T.adjoint() * g.coupling;  // Qᴴf
  const Eigen::MatrixXcd Vq = (Hq - Hq.adjoint()) / cd(0, 2);

  const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> ritz(Hq);
  if (ritz.info() != Eigen::Success) throw std::runtime_error("the reduced pencil's eigen-decomposition failed");
  const Eigen::MatrixXcd& W = ritz.eigenvectors();  // unit columns
  GalerkinReduction out;
  out.dropped = static_cast<int>(first);
  out.gram = W.adjoint() * W;
  out.viscous = W.adjoint() * Vq * W;
  out.coupling = (cq.adjoint() * W).transpose();  // fᵀQw_l = conj(Qᴴf)ᵀ w_l
  const Eigen::LLT<Eigen::MatrixXcd> gram(out.gram);  // G′ = WᴴW: Hermitian definite
  const Eigen::VectorXcd gl = gram.solve(out.coupling.conjugate());
  // With a free surface, R_xy = π xᵀQ(s − H_q)⁻¹Qᴴy has the residue π (xᵀQw_l)(G′⁻¹WᴴQᴴy)_l; the exact R_fg = R_gf (the
  // pencil is complex symmetric), the projection's only nearly: the mean of the two approximates R_fg no worse.
  Eigen::VectorXcd offset, offset_left;
  if (g.offset.size() > 0) {
    offset = ((T.adjoint() * g.offset).adjoint() * W).transpose();
    offset_left = gram.solve(offset.conjugate());
  }
  for (Eigen::Index l = 0; l < r; ++l) {
    const cd lambda = ritz.eigenvalues()[l];
    if (lambda.imag() < -1e-10 * std::abs(lambda))
      throw std::runtime_error(fmt::format("a Ritz value grows ({:.6g}{:+.3g}i): the reduced viscous form is not "
                                           "semi-definite", lambda.real(), lambda.imag()));
    out.lambda.push_back(lambda);
    out.residue.push_back(std::numbers::pi * out.coupling[l] * gl[l]);
    if (offset.size() > 0) {
      out.residue_fg.push_back(0.5 * std::numbers::pi * (out.coupling[l] * offset_left[l] + offset[l] * gl[l]));
      out.residue_gg.push_back(std::numbers::pi * offset[l] * offset_left[l]);
    }
  }
  return out;
}

}  // namespace rc::modes
