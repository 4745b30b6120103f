// The quadrature-point velocity space of a 3-D cavity, in which the discrete Poincaré problem is the eigenproblem
// of a self-adjoint operator (the 3-D form of modes/ideal/velocity_space.hpp; docs/volume.md §2). A complex
// velocity V = V_r + i V_i is stored at each quadrature point as six reals (V_r, V_i), with the real inner product
// ⟨u, v⟩ = Σ ω (u·v), ω the point's weight — the real part of the complex ∫ ū·v. S V = 2iẑ × V is the Coriolis
// term (ω0 = 1), G the gradient of a complex pressure (P_r, P_i) (two dof vectors one after the other),
// P_H = I − G M⁻¹ Gᵀ Ω the projection on discretely solenoidal fields, and A = P_H S: λV = A V is the mode.
// Multiplying by i, (V_r, V_i) → (−V_i, V_r), commutes with A: every eigenvalue is double in this real form.
#pragma once

#include "stiffness_solver.hpp"
#include "volume_forms.hpp"
#include "volume_space.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace rc::modes {

class VolumeVelocity {
 public:
  // Under mpirun (`comm` of several ranks) each rank holds the points of its share of the elements (rank_elements):
  // the vectors' rows are split, divergence() sums over the ranks, and inner products need sum_over_ranks.
  VolumeVelocity(const VolumeSpace& space, const std::array<double, 3>& centroid, MPI_Comm comm = PETSC_COMM_SELF);

  MPI_Comm comm() const { return comm_; }
  // Σ over the ranks, in place (identity on one rank).
  void sum_over_ranks(double* values, int count) const;

  Eigen::Index size() const { return weights_.size(); }
  const Eigen::VectorXd& weights() const { return weights_; }
  // e_k × (x − centroid), real (k = 0, 1, 2: x, y, z).
  Eigen::VectorXd rotation_field(int k) const;
  // The uniform field e_j (real).
  Eigen::VectorXd uniform_field(int j) const;
  // The same field times i.
  static Eigen::VectorXd times_i(const Eigen::VectorXd& v);

  // out = S v.
  void coriolis(const Eigen::VectorXd& v, Eigen::VectorXd& out) const;
  // g = Gᵀ Ω v: the weak divergence of (V_r, V_i), 2·ndof, whole on every rank.
  void divergence(const Eigen::VectorXd& v, std::vector<double>& g) const;
  // v += scale · G p, p of length 2·ndof (whole).
  void add_gradient(const std::vector<double>& p, double scale, Eigen::VectorXd& v) const;
  // v <- P_H v (`solver` factorises M).
  void project(const StiffnessSolver& solver, Eigen::VectorXd& v) const;
  // v <- (S − σ)⁻¹ v, pointwise (σ ∉ {0, ±2}): (2iẑ× − σ)⁻¹ = (−2iẑ× − σ)/(σ² − 4) across the axis, −1/σ along it.
  static void shifted_coriolis_inverse(double sigma, Eigen::VectorXd& v);

 private:
  MPI_Comm comm_;
  int npe_ = 0, ndof_ = 0;
  std::vector<double> omega_, rel_;   // weight and position relative to the centroid at each point
  std::vector<int> dof_;              // per point, per local basis function
  std::vector<double> gx_, gy_, gz_;  // gradients of the local basis functions at each point
  Eigen::VectorXd weights_;
};

}  // namespace rc::modes
