#include "krylov_response.hpp"

#include "block_arrays.hpp"
#include "dense_blas.hpp"
#include "reduced_transfer.hpp"
#include "shifted_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace rc::modes {
namespace {

using cd = std::complex<double>;

// The 𝓜-orthonormal basis and the small matrices of both projections, grown a block of vectors at a time (one
// expansion point's Krylov vectors): the products with the basis are matrix–matrix products, one pass over its
// memory per block rather than one per vector.
class KrylovBasis {
 public:
  explicit KrylovBasis(const ViscousForms& forms) : forms_(forms) {
    petsc_check(PetscObjectGetComm(reinterpret_cast<PetscObject>(forms.coupling.get()), &comm_), "PetscObjectGetComm");
    petsc_check(VecDuplicate(forms.coupling, in_.out()), "VecDuplicate");
    petsc_check(VecDuplicate(forms.coupling, out_.out()), "VecDuplicate");
    const bool offset = forms.offset_coupling.get() != nullptr;
    F_.resize(local_pairs(forms.coupling).size(), offset ? 2 : 1);
    F_.col(0) = local_pairs(forms.coupling);
    if (offset) F_.col(1) = local_pairs(forms.offset_coupling);
  }

  int size() const { return m_; }

  // Orthonormalises the columns of W (local rows of block vectors, themselves 𝓜-orthonormal; MW = 𝓜W) against the
  // basis — two passes of block classical Gram–Schmidt in 𝓜's inner product — and appends what is new (directions
  // whose remaining norm is above 1e-7 of the columns' unit norm). Returns how many vectors were appended.
  int add(Eigen::MatrixXcd W, Eigen::MatrixXcd MW);

  // 𝓜 x and x̄ᵀ𝓜y-type products for the point's own Arnoldi process (krylov_reduction's expand).
  Eigen::VectorXcd apply(Mat op, const Eigen::VectorXcd& x);
  cd mdot(const Eigen::VectorXcd& x, const Eigen::VectorXcd& mx) const { return sum(x.dot(mx)); }

  // π yᵀx for a block vector x and each input y (the inputs are real: y.dot(x) = yᵀx).
  Eigen::VectorXcd moments(const Eigen::VectorXcd& x) const {
    Eigen::MatrixXcd m = F_.transpose() * x;
    sum(m);
    return std::numbers::pi * m.col(0);
  }

  // The two reduced models' transfer functions; try_poles as ReducedTransfer's.
  ReducedTransfer galerkin(bool try_poles) const {
    const auto n = m_;
    return {Mh_.topLeftCorner(n, n), Hh_.topLeftCorner(n, n), fh_.topRows(n).conjugate(), fh_.topRows(n), try_poles};
  }
  ReducedTransfer bilinear(bool try_poles) const {
    const auto n = m_;
    return {Mb_.topLeftCorner(n, n), Ab_.topLeftCorner(n, n), fh_.topRows(n).conjugate(), fh_.topRows(n).conjugate(),
            try_poles};
  }
  GalerkinMatrices projection() const;

 private:
  Eigen::MatrixXcd apply(Mat op, const Eigen::MatrixXcd& W);
  cd sum(cd local) const {
    MPI_Allreduce(MPI_IN_PLACE, &local, 2, MPI_DOUBLE, MPI_SUM, comm_);
    return local;
  }
  void sum(Eigen::MatrixXcd& v) const {
    MPI_Allreduce(MPI_IN_PLACE, v.data(), 2 * static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, comm_);
  }
  void orthogonalise(Eigen::MatrixXcd& W, Eigen::MatrixXcd& MW);
  void reserve(int n);
  void append(const Eigen::MatrixXcd& W, const Eigen::MatrixXcd& MW);

  const ViscousForms& forms_;
  MPI_Comm comm_;
  PVec in_, out_;
  Eigen::MatrixXcd F_;                  // the inputs' local rows: f, and a free surface's offset coupling g
  Eigen::MatrixXcd X_;                  // local rows, m_ columns used
  Eigen::MatrixXcd Hh_, Mh_, Ab_, Mb_;  // XᴴAX, Xᴴ𝓜X, XᵀAX, Xᵀ𝓜X
  Eigen::MatrixXcd fh_;                 // XᴴF
  int m_ = 0;
};

Eigen::VectorXcd KrylovBasis::apply(Mat op, const Eigen::VectorXcd& x) {
  store_pairs(x, in_);
  petsc_check(MatMult(op, in_, out_), "MatMult");
  return local_pairs(out_);
}

Eigen::MatrixXcd KrylovBasis::apply(Mat op, const Eigen::MatrixXcd& W) { return block_product(op, W); }

void KrylovBasis::reserve(int n) {
  if (n <= X_.cols()) return;
  const int cap = std::max(n, 2 * static_cast<int>(X_.cols()) + 16);
  X_.conservativeResize(F_.rows(), cap);
  for (auto* P : {&Hh_, &Mh_, &Ab_, &Mb_}) P->conservativeResize(cap, cap);
  fh_.conservativeResize(cap, F_.cols());
}

// The first pass takes the caller's 𝓜W; the second, which mends the first's rounding, and the result need 𝓜 applied
// afresh (𝓜W after the passes returns in MW): each application is a sparse product per column, which on a P6 mesh
// costs as much as that column's share of the products with the whole basis.
void KrylovBasis::orthogonalise(Eigen::MatrixXcd& W, Eigen::MatrixXcd& MW) {
  if (m_ == 0) return;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass > 0) MW = apply(forms_.M, W);
    Eigen::MatrixXcd H;
    blas_product(X_.leftCols(m_), true, MW, H);
    sum(H);
    blas_subtract_product(X_.leftCols(m_), H, W);
  }
  MW = apply(forms_.M, W);
}

int KrylovBasis::add(Eigen::MatrixXcd W, Eigen::MatrixXcd MW) {
  orthogonalise(W, MW);
  // What is left, made orthonormal through its Gram matrix's eigen-decomposition (small directions dropped).
  Eigen::MatrixXcd G = W.adjoint() * MW;
  sum(G);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> es(0.5 * (G + G.adjoint()));
  Eigen::Index first = 0;
  while (first < G.rows() && !(es.eigenvalues()[first] > 1e-14)) ++first;
  const Eigen::Index r = G.rows() - first;
  if (r == 0) return 0;
  const Eigen::MatrixXcd T =
      es.eigenvectors().rightCols(r) * es.eigenvalues().tail(r).cwiseSqrt().cwiseInverse().asDiagonal();
  append(W * T, MW * T);
  return static_cast<int>(r);
}

// The new columns' entries of every small matrix in one product with [X W]ᴴ and one reduction: XᴴAW; XᵀAW̄ (the new
// rows of XᴴAX, since wᴴAx = xᵀAw̄ for complex symmetric A); Xᴴ𝓜W; XᵀAW and Xᵀ𝓜W (Xᵀv = conj(Xᴴv̄)); and WᴴF.
void KrylovBasis::append(const Eigen::MatrixXcd& W, const Eigen::MatrixXcd& MW) {
  const Eigen::Index k = W.cols(), old = m_, n = old + k;
  reserve(static_cast<int>(n));
  X_.middleCols(old, k) = W;
  const auto Xn = X_.leftCols(n);
  const Eigen::MatrixXcd AW = apply(forms_.A, W);
  const Eigen::MatrixXcd AWbar = apply(forms_.A, Eigen::MatrixXcd(W.conjugate()));
  Eigen::MatrixXcd rhs(W.rows(), 5 * k);
  rhs << AW, AWbar.conjugate(), MW, AW.conjugate(), MW.conjugate();
  const Eigen::Index p = F_.cols();
  Eigen::MatrixXcd Z(n + p, 5 * k), XZ;
  blas_product(Xn, true, rhs, XZ);
  Z.topRows(n) = XZ;
  Z.bottomRows(p).leftCols(k) = (W.adjoint() * F_).transpose();
  Z.bottomRows(p).rightCols(4 * k).setZero();
  sum(Z);
  for (Eigen::Index j = 0; j < k; ++j) {
    const Eigen::Index c = old + j;
    Hh_.col(c).head(n) = Z.col(j);
    Hh_.row(c).head(n) = Z.col(k + j).conjugate().transpose();
    Hh_(c, c) = Z(c, j);
    Mh_.col(c).head(n) = Z.col(2 * k + j);
    Mh_.row(c).head(n) = Z.col(2 * k + j).adjoint();
    Mh_(c, c) = Z(c, 2 * k + j).real();
    Ab_.col(c).head(n) = Z.col(3 * k + j).conjugate();
    Ab_.row(c).head(n) = Z.col(3 * k + j).conjugate().transpose();
    Mb_.col(c).head(n) = Z.col(4 * k + j).conjugate();
    Mb_.row(c).head(n) = Z.col(4 * k + j).conjugate().transpose();
    fh_.row(c) = Z.col(j).tail(p).transpose();
  }
  m_ = static_cast<int>(n);
}

GalerkinMatrices KrylovBasis::projection() const {
  GalerkinMatrices g;
  g.gram = Mh_.topLeftCorner(m_, m_);
  g.gram = (0.5 * (g.gram + g.gram.adjoint())).eval();
  g.op = Hh_.topLeftCorner(m_, m_);
  g.viscous = (g.op - g.op.adjoint()) / cd(0, 2);
  g.coupling = fh_.col(0).head(m_);
  if (fh_.cols() > 1) g.offset = fh_.col(1).head(m_);
  return g;
}

// The handles' plain vectors, for the solver's many-column solve.
std::vector<Vec> krylov_plain_vecs(const std::vector<PVec>& v) {
  std::vector<Vec> out;
  for (const PVec& x : v) out.push_back(x.get());
  return out;
}

// The largest entry of |a − b| / scale (entry by entry): how far two response matrices are apart.
double entry_error(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b, const Eigen::MatrixXd& scale) {
  return ((a - b).cwiseAbs().array() / scale.array()).maxCoeff();
}

// The largest entry of |Im(a − b)| against b's own dissipation: R's anti-Hermitian part P = Im R (R is complex
// symmetric) is positive semi-definite on real frequencies (passivity), so |P_ij| ≤ √(P_ii P_jj) is each entry's
// natural size; below `floor` (entry by entry) the floor is the size. A chain root's decay is Im R at its frequency
// times its coupling: this is the relative error of the decays the table gives (docs/viscous.md, "The error of Im R").
double dissipation_error(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b, const Eigen::MatrixXd& floor) {
  const Eigen::VectorXd own = b.diagonal().imag().cwiseMax(0.0);
  const Eigen::MatrixXd size = (own * own.transpose()).cwiseSqrt().cwiseMax(floor);
  return ((a - b).imag().cwiseAbs().array() / size.array()).maxCoeff();
}

// Both errors of an approximation b of a, and what decides: the larger of each against its tolerance.
struct FitError {
  double magnitude = 0, dissipation = 0;
  double against(const KrylovOptions& o) const {
    const double im = o.dissipation_tolerance > 0 ? dissipation / o.dissipation_tolerance : 0.0;
    return std::max(magnitude / o.tolerance, im);
  }
};

// The greedy loop's state: the basis, one solver, the candidates and what has been measured. With p inputs (the
// coupling f, and a free surface's offset coupling g) R is the p × p matrix π yᵢᵀS⁻¹yⱼ, every expansion point adds
// the Krylov vectors of each input, and each entry's error is measured against its own scale (scale_ij = √(scale_ii
// scale_jj) off the diagonal, where R_fg may vanish by symmetry).
class Greedy {
 public:
  Greedy(const ViscousForms& forms, const std::vector<double>& window, const std::vector<double>& beyond,
         const KrylovOptions& options)
      : forms_(forms), basis_(forms), solver_(forms), options_(options), window_(window) {
    candidates_ = window;
    candidates_.insert(candidates_.end(), beyond.begin(), beyond.end());
    inputs_.push_back(forms.coupling);
    if (forms.offset_coupling.get() != nullptr) inputs_.push_back(forms.offset_coupling);
    x_.resize(inputs_.size());
    v_.resize(inputs_.size());
    for (std::size_t c = 0; c < inputs_.size(); ++c) {
      petsc_check(VecDuplicate(forms.coupling, x_[c].out()), "VecDuplicate");
      petsc_check(VecDuplicate(forms.coupling, v_[c].out()), "VecDuplicate");
    }
    petsc_check(PetscObjectGetComm(reinterpret_cast<PetscObject>(forms.coupling.get()), &comm_), "PetscObjectGetComm");
  }

  Eigen::Index inputs() const { return static_cast<Eigen::Index>(inputs_.size()); }

  // R(s) by forced solves (one factorisation, one solve for all inputs); the solutions x(s) = S⁻¹yⱼ into `x` when
  // given (the basis unchanged).
  Eigen::MatrixXcd forced(cd s, std::vector<Eigen::VectorXcd>* x = nullptr) {
    solver_.factor(s);
    solver_.solve(inputs_, krylov_plain_vecs(x_));
    Eigen::MatrixXcd R(inputs(), inputs());
    for (Eigen::Index j = 0; j < inputs(); ++j) {
      const Eigen::VectorXcd xs = local_pairs(x_[static_cast<std::size_t>(j)]);
      R.col(j) = basis_.moments(xs);
      if (x) x->push_back(xs);
    }
    return R;
  }

  // Factors at s, makes each input's Krylov vectors x(s), (S⁻¹𝓜)x(s), … by Arnoldi in 𝓜's inner product (against
  // the point's own vectors), and adds them to the basis as one block; returns R(s) by the first, forced solves. The
  // inputs' sequences advance together, one solve for all of them per step (a free surface's two inputs on a P6
  // mesh: 0.130 s a step against 0.201 s for two solves; docs/benchmarks.md, "Krylov point").
  Eigen::MatrixXcd expand(cd s, int vectors) {
    std::vector<Eigen::VectorXcd> starts;
    const Eigen::MatrixXcd R = forced(s, &starts);
    const Eigen::Index rows = starts.front().size(), total = vectors * inputs();
    Eigen::MatrixXcd W(rows, total), MW(rows, total);
    Eigen::Index k = 0;
    std::vector<Eigen::Index> last(starts.size(), -1);  // each sequence's newest column; −1 once it has ended
    for (int step = 0; step < vectors; ++step) {
      std::vector<std::size_t> live;
      for (std::size_t c = 0; c < starts.size(); ++c)
        if (step == 0 || last[c] >= 0) live.push_back(c);
      if (live.empty()) break;
      if (step > 0) {
        std::vector<Vec> from, to;
        for (const std::size_t c : live) {
          store_pairs(MW.col(last[c]), v_[c]);
          from.push_back(v_[c]);
          to.push_back(x_[c]);
        }
        solver_.solve(from, to);
      }
      for (const std::size_t c : live) {
        Eigen::VectorXcd q = step == 0 ? starts[c] : local_pairs(x_[c]);
        Eigen::VectorXcd mq;
        last[c] = -1;
        if (!normalise_against(q, W.leftCols(k), MW.leftCols(k), mq)) continue;
        W.col(k) = q;
        MW.col(k) = mq;
        last[c] = k++;
      }
    }
    basis_.add(W.leftCols(k), MW.leftCols(k));
    return R;
  }

  // R_G's scales (max over the window, entry by entry: of |R_G| and of Im R_G), the candidate whose estimate
  // (R_B − R_G, both errors against their tolerances) is worst, the errors there, and R_G there (what the forced solve
  // at s is measured against); and the largest of each error over the candidates, which is what the table reports
  // (with Im R's a criterion or not, its largest need not sit where the worst point is). Im R's error counts on the
  // window only: beyond it no chain root is sought.
  struct Worst {
    double s = 0;
    FitError estimate, largest;
    std::vector<double> window_dissipation;  // Im R's estimate at each window frequency
    bool in_window = true;
    Eigen::MatrixXd scale, floor;
    Eigen::MatrixXcd galerkin;
  };
  Worst worst() {
    // Once a model's eigenvectors were too ill-conditioned for its pole–residue form, the larger bases that follow
    // (the same vectors and more) are taken to the Schur form directly: the failed attempt cost as much as the Schur
    // form itself (docs/viscous.md, "Where a partially filled tank's table spends its time").
    const ReducedTransfer G = basis_.galerkin(galerkin_poles_), B = basis_.bilinear(bilinear_poles_);
    galerkin_poles_ = G.pole_residue();
    bilinear_poles_ = B.pole_residue();
    const Eigen::Index p = inputs();
    std::vector<Eigen::MatrixXcd> g(candidates_.size()), b(candidates_.size());
    Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(p), dissipation = Eigen::VectorXd::Zero(p);
    for (std::size_t i = 0; i < candidates_.size(); ++i) {
      g[i] = G.matrix(candidates_[i]);
      b[i] = B.matrix(candidates_[i]);
      if (i >= window_.size()) continue;
      diagonal = diagonal.cwiseMax(g[i].diagonal().cwiseAbs());
      dissipation = dissipation.cwiseMax(g[i].diagonal().imag());
    }
    Worst w;
    w.scale = (diagonal * diagonal.transpose()).cwiseSqrt();
    w.floor = options_.dissipation_floor * (dissipation * dissipation.transpose()).cwiseSqrt();
    std::size_t at = 0;
    double worst_ratio = -1;
    for (std::size_t i = 0; i < candidates_.size(); ++i) {
      const FitError e{entry_error(b[i], g[i], w.scale),
                       i < window_.size() ? dissipation_error(b[i], g[i], w.floor) : 0.0};
      w.largest = {std::max(w.largest.magnitude, e.magnitude), std::max(w.largest.dissipation, e.dissipation)};
      if (i < window_.size()) w.window_dissipation.push_back(e.dissipation);
      if (e.against(options_) > worst_ratio) {
        worst_ratio = e.against(options_);
        w.estimate = e;
        at = i;
      }
    }
    w.s = candidates_[at];
    w.in_window = at < window_.size();
    w.scale *= std::numbers::pi;
    w.floor *= std::numbers::pi;
    w.galerkin = std::numbers::pi * g[at];
    share(w);
    return w;
  }

  // R(s) − R_G(s) by a forced solve, both errors: rank 0's values for every rank (they decide whether to stop).
  FitError measured_error(const Worst& at) {
    const Eigen::MatrixXcd R = forced(at.s);
    double e[2] = {entry_error(R, at.galerkin, at.scale),
                   at.in_window ? dissipation_error(R, at.galerkin, at.floor) : 0.0};
    MPI_Bcast(e, 2, MPI_DOUBLE, 0, comm_);
    return {e[0], e[1]};
  }

  const KrylovBasis& basis() const { return basis_; }

 private:
  // Every rank computed `w` from the same reduced matrices, but the next point is factored collectively: rank 0's
  // choice is everyone's, so that rounding can never send two ranks to different points.
  void share(Worst& w) const {
    const Eigen::Index n = w.scale.size();
    std::vector<double> shared{w.s, w.estimate.magnitude, w.estimate.dissipation, w.largest.magnitude,
                               w.largest.dissipation, w.in_window ? 1.0 : 0.0};
    for (Eigen::Index k = 0; k < n; ++k)
      for (const double v : {w.scale.data()[k], w.floor.data()[k], w.galerkin.data()[k].real(),
                             w.galerkin.data()[k].imag()})
        shared.push_back(v);
    shared.insert(shared.end(), w.window_dissipation.begin(), w.window_dissipation.end());
    MPI_Bcast(shared.data(), static_cast<int>(shared.size()), MPI_DOUBLE, 0, comm_);
    std::copy(shared.end() - static_cast<std::ptrdiff_t>(w.window_dissipation.size()), shared.end(),
              w.window_dissipation.begin());
    w.s = shared[0];
    w.estimate = {shared[1], shared[2]};
    w.largest = {shared[3], shared[4]};
    w.in_window = shared[5] != 0;
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto at = static_cast<std::size_t>(6 + 4 * k);
      w.scale.data()[k] = shared[at];
      w.floor.data()[k] = shared[at + 1];
      w.galerkin.data()[k] = {shared[at + 2], shared[at + 3]};
    }
  }

  // q against the columns of W (𝓜W given), twice, then to unit 𝓜-norm, with 𝓜q into mq; false when nothing is left
  // of it. 𝓜q follows q through the subtractions (𝓜 is linear) and is applied afresh only where most of q cancelled,
  // and with it the rounding's share of what is left.
  bool normalise_against(Eigen::VectorXcd& q, const Eigen::Ref<const Eigen::MatrixXcd>& W,
                         const Eigen::Ref<const Eigen::MatrixXcd>& MW, Eigen::VectorXcd& mq) {
    mq = basis_.apply(forms_.M, q);
    const double before = std::sqrt(std::max(basis_.mdot(q, mq).real(), 0.0));
    for (int pass = 0; pass < 2 && W.cols() > 0; ++pass) {
      Eigen::VectorXcd h = MW.adjoint() * q;  // W̄ᵀ𝓜q = (𝓜W)ᴴq, 𝓜 real symmetric
      MPI_Allreduce(MPI_IN_PLACE, h.data(), 2 * static_cast<int>(h.size()), MPI_DOUBLE, MPI_SUM, comm_);
      q -= W * h;
      mq -= MW * h;
    }
    double norm = std::sqrt(std::max(basis_.mdot(q, mq).real(), 0.0));
    if (norm < 1e-3 * before) {
      mq = basis_.apply(forms_.M, q);
      norm = std::sqrt(std::max(basis_.mdot(q, mq).real(), 0.0));
    }
    if (!(norm > 1e-10 * before)) return false;
    q /= norm;
    mq /= norm;
    return true;
  }

  const ViscousForms& forms_;
  KrylovBasis basis_;
  ShiftedSolver solver_;
  const KrylovOptions& options_;
  MPI_Comm comm_;
  std::vector<double> window_, candidates_;
  std::vector<Vec> inputs_;
  std::vector<PVec> x_, v_;  // one solution and one right-hand side per input
  bool galerkin_poles_ = true, bilinear_poles_ = true;  // whether to try each model's pole–residue form
};

}  // namespace

KrylovReduction krylov_reduction(const ViscousForms& forms, const std::vector<double>& window,
                                 const std::vector<double>& beyond, const KrylovOptions& options,
                                 const std::function<void(const std::string&)>& progress) {
  if (window.size() < 3) throw std::invalid_argument("a Krylov response reduction needs at least 3 window frequencies");
  Greedy greedy(forms, window, beyond, options);
  KrylovReduction out;
  for (const double s : {window.front(), 0.5 * (window.front() + window.back()), window.back()}) {
    greedy.expand(s, options.vectors_per_point);
    out.points.push_back(s);
    out.point_errors.push_back(std::numeric_limits<double>::quiet_NaN());
  }
  for (const cd s : options.exact_at) greedy.expand(s, options.vectors_per_point);
  const auto finish = [&](const auto& worst, const FitError& check) {
    out.estimate = worst.largest.magnitude;
    out.dissipation_estimate = worst.largest.dissipation;
    out.scale = worst.scale(0, 0);
    out.check_point = worst.s;
    out.check_error = check.magnitude;
    out.check_dissipation_error = check.dissipation;
    out.dissipation_profile = worst.window_dissipation;
    const auto at = std::find(window.begin(), window.end(), worst.s);
    if (at != window.end()) {
      double& e = out.dissipation_profile[static_cast<std::size_t>(at - window.begin())];
      e = std::max(e, check.dissipation);
    }
  };
  for (;;) {
    const auto worst = greedy.worst();
    if (worst.estimate.against(options) <= 1) {
      // The estimate says done: a forced solve where it is largest says whether it is right. If not, that point
      // (factored already) is expanded like any other and the search goes on.
      const FitError check = greedy.measured_error(worst);
      if (check.against(options) <= 1) {
        finish(worst, check);
        break;
      }
    }
    if (static_cast<int>(out.points.size()) >= options.max_points) {
      // Out of points: the table is still the best this basis gives, marked by its error (the caller says so).
      out.within_tolerance = false;
      finish(worst, greedy.measured_error(worst));
      break;
    }
    const Eigen::MatrixXcd R = greedy.expand(worst.s, options.vectors_per_point);
    out.points.push_back(worst.s);
    out.point_errors.push_back(entry_error(R, worst.galerkin, worst.scale));
    const double dissipation = worst.in_window ? dissipation_error(R, worst.galerkin, worst.floor) : 0.0;
    if (progress)
      progress(fmt::format("krylov response: point {} at s = {:.6g}: estimated {:.2g} of max|R| and {:.2g} of Im R "
                           "there (Im R's at most {:.2g} on the window), measured {:.2g} and {:.2g}; {} vectors",
                           out.points.size(), worst.s, worst.estimate.magnitude, worst.estimate.dissipation,
                           worst.largest.dissipation, out.point_errors.back(), dissipation, greedy.basis().size()));
  }
  out.projection = greedy.basis().projection();
  out.vectors = greedy.basis().size();
  return out;
}

}  // namespace rc::modes
