// A block Lanczos process for a self-adjoint operator in a weighted inner product, and the Gauss rule of the
// start block's matrix-valued spectral measure (the block form of lanczos.hpp). Used by the 3-D survey, whose
// measure is matrix-valued: a mode couples to the three axes of rotation at once (modes/volume/volume_survey.hpp).
//
// With the start block B = Q1 R0 (weighted-orthonormal Q1) and T = Qᵀ Ω A Q the projected operator on the Krylov
// space, the rule's node θ_i is an eigenvalue of T with eigenvector y_i, and its weight vector is
// u_i = R0ᵀ y_i[first block] = (⟨B_j, z_i⟩)_j for the Ritz vector z_i = Q y_i: Σ_i u_i u_iᵀ = Bᵀ Ω B exactly.
// Columns of a new block that are (numerically) in the span of the basis are dropped: the space is then invariant
// in those directions, and the process stops when no column is left.
#pragma once

#include <Eigen/Core>
#include <petscsys.h>  // MPI, as PETSc includes it (without the C++ bindings)

#include <functional>
#include <vector>

namespace rc::modes {

struct BlockGaussNode {
  double lambda = 0;
  Eigen::VectorXd weight;  // ⟨B_j, z⟩ for each start column j
  double residual = 0;     // ‖A z − λ z‖ bound (the last block's coupling)
};

class BlockLanczos {
 public:
  using Apply = std::function<void(const Eigen::VectorXd& in, Eigen::VectorXd& out)>;

  // weights: the inner product; start: the block (columns); at most max_columns basis vectors in all. Under mpirun
  // each rank may hold some of the vectors' rows (`comm`: the inner products are summed over it); the small
  // projected problem is then the same on every rank.
  BlockLanczos(const Eigen::VectorXd& weights, const Eigen::MatrixXd& start, int max_columns,
               MPI_Comm comm = MPI_COMM_SELF);

  // One block step; false when the space became invariant or the column budget is spent.
  bool step(const Apply& apply);
  int columns() const { return static_cast<int>(used_); }
  bool exhausted() const { return exhausted_; }
  std::vector<BlockGaussNode> rule() const;

 private:
  // Orthonormalises the columns of U, already projected once off the basis, against it (a second time) and each other
  // (twice), appends the independent ones and returns their coefficients (rows: new columns, in order) — the block's B.
  Eigen::MatrixXd append_block(Eigen::MatrixXd U, double scale);
  // Qᵀ Ω U for the basis's columns [begin, end), summed over the ranks.
  Eigen::MatrixXd project(const Eigen::MatrixXd& U, Eigen::Index begin, Eigen::Index end) const;
  // Sums a block of inner products over the ranks' rows (in place).
  void sum_over_ranks(Eigen::MatrixXd& m) const;
  double weighted_norm(const Eigen::VectorXd& u) const;

  MPI_Comm comm_;
  Eigen::VectorXd weights_;
  Eigen::MatrixXd basis_, T_, R0_, last_B_;
  Eigen::Index used_ = 0, block_begin_ = 0, block_end_ = 0;
  bool exhausted_ = false;
};

}  // namespace rc::modes
