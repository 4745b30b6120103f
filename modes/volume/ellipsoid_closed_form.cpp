#include "ellipsoid_closed_form.hpp"

#include "eigen_dense.hpp"
#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace rc::modes {
namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& u) {  // [u]× ω = u × ω
  Eigen::Matrix3d m;
  m << 0, -u(2), u(1), u(2), 0, -u(0), -u(1), u(0), 0;
  return m;
}

// c = (∫ (e_k × r)·V)_k and ‖V‖² for V = L r, with S = ∫ r rᵀ and e_k the spin frame's axes in the body frame.
struct Coupling {
  Eigen::Vector3cd c;
  double norm2;
};
Coupling linear_field_coupling(const Eigen::Matrix3cd& L, const Eigen::Matrix3d& S, const Eigen::Matrix3d& R) {
  Coupling out;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Matrix3d E = cross_matrix(R.transpose().col(k));  // (e × r)·(L r) = rᵀ Eᵀ L r
    out.c(k) = (E.transpose().cast<std::complex<double>>() * L * S.cast<std::complex<double>>()).trace();
  }
  out.norm2 = (L.adjoint() * L * S.cast<std::complex<double>>()).trace().real();
  return out;
}

}  // namespace

EllipsoidModes ellipsoid_modes(double a, double b, double c, double tilt) {
  using C = std::complex<double>;
  EllipsoidModes out;
  out.mass = 4 * std::numbers::pi * a * b * c / 3;
  const Eigen::Vector3d d(a, b, c);
  const Eigen::Matrix3d D = d.asDiagonal(), Dinv = d.cwiseInverse().asDiagonal();
  const Eigen::Matrix3d K = Eigen::Vector3d((b * b + c * c) / (b * c), (a * a + c * c) / (a * c),
                                            (a * a + b * b) / (a * b)).asDiagonal();
  // Body frame → spin frame: the tilt about x (cavity-modes turns the shape by `tilt` about x).
  const Eigen::Matrix3d R = Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d spin = R.transpose() * Eigen::Vector3d::UnitZ();
  const Eigen::Matrix3d B = -2 * K.inverse() * D * cross_matrix(Dinv * spin);  // ω̇ = B ω
  Eigen::EigenSolver<Eigen::Matrix3d> es(B);
  const Eigen::Matrix3d S = out.mass / 5 * (D * D);  // ∫ r rᵀ over the ellipsoid
  for (int i = 0; i < 3; ++i) {
    const C mu = es.eigenvalues()(i);
    const Eigen::Vector3cd w = es.eigenvectors().col(i);
    Eigen::Matrix3cd Wx;  // [ω]× for complex ω
    Wx << 0, -w(2), w(1), w(2), 0, -w(0), -w(1), w(0), 0;
    const Eigen::Matrix3cd field = D.cast<C>() * Wx * Dinv.cast<C>();  // V = D (ω × D⁻¹ r) = field · r
    const Coupling cp = linear_field_coupling(field, S, R);
    const Eigen::Matrix3cd H = cp.c * cp.c.adjoint() / cp.norm2;
    if (mu.imag() > 1e-12) {
      out.lambda = mu.imag();  // e^{iλt}: μ = iλ
      out.H = H;
      out.field = R.cast<C>() * field * R.transpose().cast<C>();
      out.norm2 = cp.norm2;
    } else if (std::abs(mu) < 1e-12) {
      out.geostrophic = H.real();
    }
  }
  const Eigen::Matrix3d inertia_body =
      out.mass / 5 * Eigen::Vector3d(b * b + c * c, a * a + c * c, a * a + b * b).asDiagonal().toDenseMatrix();
  const auto zh = [&](double p, double q) { return out.mass * (p * p - q * q) * (p * p - q * q) / (5 * (p * p + q * q)); };
  const Eigen::Matrix3d zhukovsky_body = Eigen::Vector3d(zh(b, c), zh(a, c), zh(a, b)).asDiagonal().toDenseMatrix();
  out.inertia = R * inertia_body * R.transpose();
  out.zhukovsky = R * zhukovsky_body * R.transpose();
  return out;
}

}  // namespace rc::modes
