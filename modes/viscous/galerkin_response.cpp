#include "galerkin_response.hpp"

#include <fmt/format.h>

#include <numbers>
#include <stdexcept>

namespace rc::modes {

std::complex<double> GalerkinReduction::response(std::complex<double> s) const {
  std::complex<double> r = 0;
  for (std::size_t l = 0; l < lambda.size(); ++l) r += residue[l] / (s - lambda[l]);
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
  const Eigen::VectorXcd gl = out.gram.llt().solve(out.coupling.conjugate());  // G′ = WᴴW: Hermitian definite
  for (Eigen::Index l = 0; l < r; ++l) {
    const cd lambda = ritz.eigenvalues()[l];
    if (lambda.imag() < -1e-10 * std::abs(lambda))
      throw std::runtime_error(fmt::format("a Ritz value grows ({:.6g}{:+.3g}i): the reduced viscous form is not "
                                           "semi-definite", lambda.real(), lambda.imag()));
    out.lambda.push_back(lambda);
    out.residue.push_back(std::numbers::pi * out.coupling[l] * gl[l]);
  }
  return out;
}

}  // namespace rc::modes
