#include "block_lanczos.hpp"

#include "dense_blas.hpp"
#include "progress.hpp"

#include "eigen_dense.hpp"

#include <cmath>
#include <stdexcept>

namespace rc::modes {
namespace {
constexpr double kDeflation = 1e-10;  // a column this small against the block's scale is in the span already
}

BlockLanczos::BlockLanczos(const Eigen::VectorXd& weights, const Eigen::MatrixXd& start, int max_columns,
                           MPI_Comm comm)
    : comm_(comm), weights_(weights), basis_(start.rows(), std::max<Eigen::Index>(max_columns, start.cols())),
      T_(Eigen::MatrixXd::Zero(basis_.cols(), basis_.cols())) {
  double scale = 0;
  for (Eigen::Index j = 0; j < start.cols(); ++j) scale = std::max(scale, weighted_norm(start.col(j)));
  if (!(scale > 0)) throw std::invalid_argument("block Lanczos: zero start block");
  R0_ = append_block(start, scale);
  if (R0_.rows() == 0) throw std::invalid_argument("block Lanczos: zero start block");
  block_begin_ = 0;
  block_end_ = used_;
}

Eigen::MatrixXd BlockLanczos::project(const Eigen::MatrixXd& U, Eigen::Index begin, Eigen::Index end) const {
  const Eigen::MatrixXd WU = weights_.asDiagonal() * U;
  Eigen::MatrixXd H;
  blas_product(basis_.middleCols(begin, end - begin), true, WU, H);
  sum_over_ranks(H);
  return H;
}

Eigen::MatrixXd BlockLanczos::append_block(Eigen::MatrixXd U, double scale) {
  const Eigen::Index first = used_;
  // Against the basis so far, once more and a block at a time: step() took the first pass, whose projections are T's,
  // and two passes of classical Gram–Schmidt are enough (BCGS2; the constructor's start block has no basis before
  // it). Each pass is two matrix products in the system BLAS (dense_blas.hpp). Column by column, twice, in Eigen's
  // matrix–vector products, the basis was read four times per column: 47 % of a 3-D survey's time (2026-12-07:
  // VolumeModes.TiltedFileIsTheClosedForm 39.6 s before, 21.2 s after, each beside another job).
  if (first > 0) blas_subtract_product(basis_.leftCols(first), project(U, 0, first), U);
  // Within the block: each column against the block's columns kept so far, twice. These coefficients are B's (the
  // ones on the older basis are T's, or reorthogonalisation).
  Eigen::MatrixXd coef = Eigen::MatrixXd::Zero(U.cols(), U.cols());  // rows: new columns
  Eigen::Index kept = 0;
  for (Eigen::Index j = 0; j < U.cols(); ++j) {
    Eigen::VectorXd u = U.col(j);
    for (int pass = 0; pass < 2 && kept > 0; ++pass) {
      const Eigen::MatrixXd h = project(u, first, used_);
      u.noalias() -= basis_.middleCols(first, kept) * h;
      coef.col(j).head(kept) += h.col(0);
    }
    const double norm = weighted_norm(u);
    if (!(norm > kDeflation * scale) || used_ >= basis_.cols()) continue;
    basis_.col(used_++) = u / norm;
    coef(kept++, j) = norm;
  }
  return coef.topRows(kept);
}

void BlockLanczos::sum_over_ranks(Eigen::MatrixXd& m) const {
  int ranks = 1;
  MPI_Comm_size(comm_, &ranks);
  if (ranks > 1) MPI_Allreduce(MPI_IN_PLACE, m.data(), static_cast<int>(m.size()), MPI_DOUBLE, MPI_SUM, comm_);
}

double BlockLanczos::weighted_norm(const Eigen::VectorXd& u) const {
  Eigen::MatrixXd square(1, 1);
  square(0, 0) = u.dot(weights_.cwiseProduct(u));
  sum_over_ranks(square);
  return std::sqrt(square(0, 0));
}

bool BlockLanczos::step(const Apply& apply) {
  if (exhausted_ || block_end_ >= basis_.cols()) return false;
  progress_tick();
  const Eigen::Index b = block_end_ - block_begin_;
  Eigen::MatrixXd U(basis_.rows(), b);
  Eigen::VectorXd out;
  double scale = 0;
  for (Eigen::Index j = 0; j < b; ++j) {
    apply(basis_.col(block_begin_ + j), out);
    U.col(j) = out;
    scale = std::max(scale, weighted_norm(out));
  }
  // T's columns of this block: the projections on every basis vector so far (full orthogonalisation).
  const Eigen::MatrixXd H = project(U, 0, used_);
  T_.block(0, block_begin_, used_, b) = H;
  blas_subtract_product(basis_.leftCols(used_), H, U);
  const Eigen::Index before = used_;
  last_B_ = append_block(U, std::max(scale, 1e-300));
  if (used_ == before) { exhausted_ = true; last_B_.resize(0, b); return false; }
  block_begin_ = before;
  block_end_ = used_;
  return used_ < basis_.cols();
}

std::vector<BlockGaussNode> BlockLanczos::rule() const {
  // The blocks already applied: columns [0, block_begin_) have their T columns (all of them when exhausted).
  const Eigen::Index k = exhausted_ ? used_ : block_begin_;
  if (k == 0) return {};
  // Column j of T holds the projections on the basis that existed when block j was applied, i.e. T's upper triangle
  // and diagonal blocks (the next block's coefficients B_j are its transposed upper block): mirror the upper part.
  Eigen::MatrixXd T = T_.topLeftCorner(k, k).triangularView<Eigen::Upper>();
  T.triangularView<Eigen::StrictlyLower>() = T.transpose().triangularView<Eigen::StrictlyLower>();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(T);
  if (es.info() != Eigen::Success) throw std::runtime_error("block Lanczos: projected eigen-solve failed");
  const Eigen::Index b0 = R0_.rows(), last = k - last_B_.cols();
  std::vector<BlockGaussNode> nodes(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    nodes[i].lambda = es.eigenvalues()(i);
    nodes[i].weight = R0_.transpose() * es.eigenvectors().col(i).head(b0);
    nodes[i].residual = exhausted_ || last_B_.size() == 0
                            ? 0.0
                            : (last_B_ * es.eigenvectors().col(i).segment(last, last_B_.cols())).norm();
  }
  return nodes;
}

}  // namespace rc::modes
