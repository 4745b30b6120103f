// The quadrature-point velocity space in which the discrete Poincaré problem is the eigenproblem of a
// self-adjoint operator (derivation: spectral_survey.hpp). An m = 1 field V = (i a, b, i c) e^{iφ} is stored
// as real (a, b, c) at each quadrature point of the meridian mesh, with inner product
// ⟨u, v⟩ = Σ ω (a a' + b b' + c c'), ω = w r. G p = (p_r, −p/r, p_z) is the gradient of an m = 1 pressure,
// S(a, b, c) = (−2b, −2a, 0) the Coriolis term 2iẑ× (ω0 = 1), and Gᵀ Ω G = Kh + Kz = M.
#pragma once

#include "fe_space.hpp"

#include <Eigen/Core>

#include <vector>

namespace rc::modes {

class VelocitySpace {
 public:
  // centroid_z: the origin of z in the coupling field e1 × r (docs/physics.md §2).
  VelocitySpace(const FESpace& space, double centroid_z);

  Eigen::Index size() const { return static_cast<Eigen::Index>(W_.size()); }
  // e1 × r = (z', −z', −r) in the (a, b, c) representation.
  Eigen::VectorXd coupling_vector() const;
  // ω repeated for the three components: ⟨u, v⟩ = Σ weights ∘ u ∘ v.
  const Eigen::VectorXd& component_weights() const { return weights_; }
  double dot(const Eigen::VectorXd& u, const Eigen::VectorXd& v) const { return u.dot(weights_.cwiseProduct(v)); }

  // out = S v.
  void coriolis(const Eigen::VectorXd& v, Eigen::VectorXd& out) const;
  // v <- (S − σ)⁻¹ v, pointwise (σ ∉ {0, ±2}).
  void shifted_coriolis_inverse(double sigma, Eigen::VectorXd& v) const;
  // g = Gᵀ Ω v (length ndof): the weak divergence of v tested with every basis function.
  void divergence(const Eigen::VectorXd& v, std::vector<double>& g) const;
  // v <- v + scale · G p.
  void add_gradient(const std::vector<double>& p, double scale, Eigen::VectorXd& v) const;

 private:
  int npe_, ndof_;
  std::vector<double> omega_, W_;
  std::vector<int> dof_;
  std::vector<double> ga_, gb_, gc_;  // rows of G at each point, per local basis function
  Eigen::VectorXd weights_;
};

}  // namespace rc::modes
