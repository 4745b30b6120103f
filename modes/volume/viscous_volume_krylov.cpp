#include "viscous_volume_krylov.hpp"

#include "block_arrays.hpp"
#include "dense_blas.hpp"
#include "shifted_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rc::modes {
namespace {

using cd = std::complex<double>;

// The operators a basis is multiplied by: A, Aᴴ, Aᵀ, Ā and 𝓜. PETSc holds A in its real block form Â, whose transpose
// is the block form of Aᴴ; Aᵀx = conj(Aᴴ x̄) and Āx = conj(A x̄).
enum class Op { A, AH, AT, Abar, M };

// The pencil's operators on local rows (block vectors' pairs as complex numbers), the reductions over the ranks, and
// the J-symmetric part of a vector.
class LocalOperators {
 public:
  LocalOperators(const ViscousForms& forms, Vec velocity_slots) : forms_(forms) {
    petsc_check(PetscObjectGetComm(reinterpret_cast<PetscObject>(forms.A.get()), &comm_), "PetscObjectGetComm");
    petsc_check(VecDuplicate(forms.coupling, in_.out()), "VecDuplicate");
    petsc_check(VecDuplicate(forms.coupling, out_.out()), "VecDuplicate");
    velocity_ = local_pairs(velocity_slots).real().array() > 0;
  }

  Eigen::Index rows() const { return velocity_.size(); }
  MPI_Comm comm() const { return comm_; }

  Eigen::VectorXcd apply(Op op, const Eigen::VectorXcd& x) {
    const bool conjugate = op == Op::AT || op == Op::Abar;
    store_pairs(conjugate ? Eigen::VectorXcd(x.conjugate()) : x, in_);
    const Mat m = op == Op::M ? forms_.M.get() : forms_.A.get();
    if (op == Op::AH || op == Op::AT)
      petsc_check(MatMultTranspose(m, in_, out_), "MatMultTranspose");
    else
      petsc_check(MatMult(m, in_, out_), "MatMult");
    const Eigen::VectorXcd y = local_pairs(out_);
    return conjugate ? Eigen::VectorXcd(y.conjugate()) : y;
  }

  Eigen::MatrixXcd apply(Op op, const Eigen::MatrixXcd& W) {
    Eigen::MatrixXcd out(W.rows(), W.cols());
    for (Eigen::Index j = 0; j < W.cols(); ++j) out.col(j) = apply(op, Eigen::VectorXcd(W.col(j)));
    return out;
  }

  // (x + Jx)/2: the velocity's real part, and the pressure's and a free surface's η̃'s imaginary part.
  Eigen::VectorXcd symmetric(const Eigen::VectorXcd& x) const {
    Eigen::VectorXcd out(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) out[i] = velocity_[i] ? cd(x[i].real(), 0.0) : cd(0.0, x[i].imag());
    return out;
  }

  // U ᴴ V (or Uᵀ V) summed over the ranks.
  Eigen::MatrixXcd inner(const Eigen::MatrixXcd& U, const Eigen::MatrixXcd& V, bool conjugate = true) const {
    Eigen::MatrixXcd h;
    if (conjugate)
      blas_product(U, true, V, h);
    else
      blas_product(U.conjugate(), true, V, h);  // Uᵀ V = (Ū)ᴴ V
    MPI_Allreduce(MPI_IN_PLACE, h.data(), 2 * static_cast<int>(h.size()), MPI_DOUBLE, MPI_SUM, comm_);
    return h;
  }

 private:
  const ViscousForms& forms_;
  MPI_Comm comm_;
  PVec in_, out_;
  Eigen::Array<bool, Eigen::Dynamic, 1> velocity_;
};

// J-symmetric columns, orthonormal in 𝓜's inner product. That product is real on J-symmetric vectors, so the
// Gram–Schmidt coefficients are taken real and the columns stay J-symmetric to the last bit.
class SymmetricBasis {
 public:
  explicit SymmetricBasis(LocalOperators& ops) : ops_(ops) {}
  Eigen::Index size() const { return m_; }
  Eigen::Ref<const Eigen::MatrixXcd> vectors() const { return X_.leftCols(m_); }

  // Orthonormalises the J-symmetric columns of W against the basis (two passes) and among themselves, appends what is
  // new (directions with more than 1e-7 of a column's norm left) and returns the appended block.
  Eigen::MatrixXcd add(Eigen::MatrixXcd W) {
    const Eigen::MatrixXd g = ops_.inner(W, ops_.apply(Op::M, W)).real();
    for (Eigen::Index j = 0; j < W.cols(); ++j) W.col(j) *= g(j, j) > 0 ? 1 / std::sqrt(g(j, j)) : 0.0;
    for (int pass = 0; pass < 2 && m_ > 0; ++pass) {
      const Eigen::MatrixXcd h = ops_.inner(X_.leftCols(m_), ops_.apply(Op::M, W)).real().cast<cd>();
      blas_subtract_product(X_.leftCols(m_), h, W);
    }
    const Eigen::MatrixXd G = ops_.inner(W, ops_.apply(Op::M, W)).real();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (G + G.transpose()));
    Eigen::Index first = 0;
    while (first < G.rows() && !(es.eigenvalues()[first] > 1e-14)) ++first;
    const Eigen::Index r = G.rows() - first;
    const Eigen::MatrixXd T =
        es.eigenvectors().rightCols(r) * es.eigenvalues().tail(r).cwiseSqrt().cwiseInverse().asDiagonal();
    const Eigen::MatrixXcd Q = W * T.cast<cd>();
    if (m_ + r > X_.cols()) X_.conservativeResize(W.rows(), std::max(m_ + r, 2 * X_.cols() + 32));
    X_.middleCols(m_, r) = Q;
    m_ += r;
    return Q;
  }

 private:
  LocalOperators& ops_;
  Eigen::MatrixXcd X_;
  Eigen::Index m_ = 0;
};

// (s − H)⁻¹ B for many s: from H's eigen-decomposition, O(m²) per s, or by an LU where the eigenvectors are too
// ill-conditioned for that (the two disagree by more than 1e-9 at a probe frequency).
class ShiftedSmall {
 public:
  ShiftedSmall(const Eigen::MatrixXcd& H, const Eigen::MatrixXcd& B, cd probe) : H_(H), B_(B) {
    const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(H);
    if (es.info() == Eigen::Success) {
      V_ = es.eigenvectors();
      poles_ = es.eigenvalues();
      beta_ = V_.partialPivLu().solve(B);
      const Eigen::MatrixXcd direct = lu(probe), modal = (*this)(probe);
      if ((modal - direct).norm() <= 1e-9 * direct.norm()) return;
    }
    poles_.resize(0);
  }

  Eigen::MatrixXcd operator()(cd s) const {
    if (poles_.size() == 0) return lu(s);
    return V_ * ((Eigen::VectorXcd::Constant(poles_.size(), s) - poles_).cwiseInverse().asDiagonal() * beta_);
  }

 private:
  Eigen::MatrixXcd lu(cd s) const {
    Eigen::MatrixXcd S = -H_;
    S.diagonal().array() += s;
    return S.partialPivLu().solve(B_);
  }
  Eigen::MatrixXcd H_, B_, V_, beta_;
  Eigen::VectorXcd poles_;
};

// The greedy search's state: the solver, the primal and dual bases and the small matrices of both projections,
//   Hx = XᴴAX, fx = XᴴF (the Galerkin model c = (s − Hx)⁻¹fx, R_G = GᵀXc = fxᴴc: X is 𝓜-orthonormal and G = F̄),
//   Hy = YᴴAᵀY, fy = YᴴG (the dual model d = (s − Hy)⁻¹fy), P = Yᵀ𝓜X, Q = YᵀAX (the residual's dual weight),
// so that the estimate R − R_G ≈ dᵀ(YᵀF − (sP − Q)c) = dᵀ(f̄y − (sP − Q)c) costs O(m²) per frequency. The inputs F
// are a full cavity's three real f_k (G = F) or a partially filled tank's five directions (G = F̄: their η̃ parts are
// imaginary, viscous_fill_surface.hpp); either way every column is J-symmetric and XᴴF is real.
class VolumeGreedy {
 public:
  explicit VolumeGreedy(const ViscousVolumeForms& forms)
      : ops_(forms.forms, forms.velocity_slots), solver_(forms.forms), X_(ops_), Y_(ops_) {
    const bool fill = !forms.fill_inputs.empty();
    const int n = fill ? static_cast<int>(forms.fill_inputs.size()) : 3;
    F_.resize(ops_.rows(), n);
    G_.resize(ops_.rows(), n);
    for (int k = 0; k < n; ++k) {
      inputs_.push_back(fill ? forms.fill_inputs[k].get() : forms.couplings[k].get());
      outputs_.push_back(fill ? forms.fill_outputs[k].get() : forms.couplings[k].get());
      F_.col(k) = local_pairs(inputs_[k]);
      G_.col(k) = local_pairs(outputs_[k]);
    }
    petsc_check(VecDuplicate(forms.forms.coupling, x_.out()), "VecDuplicate");
    petsc_check(VecDuplicate(forms.forms.coupling, v_.out()), "VecDuplicate");
  }

  int directions() const { return static_cast<int>(inputs_.size()); }

  Eigen::Index primal_size() const { return X_.size(); }
  Eigen::Index dual_size() const { return Y_.size(); }

  // R(s) by forced solves: R_jk = g_jᵀ S(s)⁻¹ f_k.
  Eigen::MatrixXcd forced(cd s) {
    solver_.factor(s);
    Eigen::MatrixXcd R(directions(), directions());
    for (int k = 0; k < directions(); ++k) {
      solver_.solve(inputs_[k], x_);
      R.col(k) = ops_.inner(G_, local_pairs(x_), false);
    }
    return R;
  }

  // Factors at s, makes each input's primal and each output's dual Krylov vectors and adds their J-symmetric parts to
  // the bases; returns R(s) from the first, forced solves.
  Eigen::MatrixXcd expand(cd s, int vectors) {
    solver_.factor(s);
    Eigen::MatrixXcd R(directions(), directions());
    std::vector<Eigen::VectorXcd> primal, dual;
    for (int k = 0; k < directions(); ++k) {
      Eigen::VectorXcd first;
      add_symmetric_parts(krylov_vectors(inputs_[k], vectors, false, &first), primal);
      R.col(k) = ops_.inner(G_, first, false);
      add_symmetric_parts(krylov_vectors(outputs_[k], vectors, true, nullptr), dual);
    }
    add_primal(X_.add(columns(primal)));
    add_dual(Y_.add(columns(dual)));
    return R;
  }

  struct Worst {
    double s = 0, estimate = 0;
    Eigen::MatrixXd scale;
    Eigen::MatrixXcd galerkin;  // R_G(s)
  };

  // The estimate's worst candidate, relative to each entry's scale over the first `window` candidates. Rank 0's
  // choice is everyone's (the next point is factored collectively).
  Worst worst(const std::vector<double>& candidates, std::size_t window) const {
    const cd probe(candidates[window / 2], 1e-2);
    const ShiftedSmall primal(Hx_, fx_, probe), dual(Hy_, fy_, probe);
    std::vector<Eigen::MatrixXcd> g(candidates.size()), e(candidates.size());
    Eigen::VectorXd top = Eigen::VectorXd::Zero(directions());
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const double s = candidates[i];
      const Eigen::MatrixXcd c = primal(s), d = dual(s);
      g[i] = fx_.adjoint() * c;
      e[i] = d.transpose() * (fy_.conjugate() - s * (P_ * c) + Q_ * c);
      if (i < window) top = top.cwiseMax(g[i].diagonal().cwiseAbs());
    }
    top = top.cwiseMax(1e-8 * top.maxCoeff());  // an entry that vanishes by symmetry is measured against the others
    Worst w;
    w.scale = (top * top.transpose()).cwiseSqrt();
    std::size_t at = 0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const double r = (e[i].cwiseAbs().array() / w.scale.array()).maxCoeff();
      if (r > w.estimate) {
        w.estimate = r;
        at = i;
      }
    }
    w.s = candidates[at];
    w.galerkin = g[at];
    share_from_root(w);
    return w;
  }

  // max_jk |R − R_G| / scale_jk at s by a forced solve: rank 0's value for every rank.
  double measured_error(double s, const Worst& w) {
    const Eigen::MatrixXcd R = forced(s);
    double e = ((R - w.galerkin).cwiseAbs().array() / w.scale.array()).maxCoeff();
    MPI_Bcast(&e, 1, MPI_DOUBLE, 0, ops_.comm());
    return e;
  }

  // The Galerkin model: Hx = iK exactly but for rounding (J-symmetric basis), fx real.
  ReducedVolumeResponse model() const { return {Hx_.imag(), fx_.real()}; }

 private:
  // x = S⁻¹f (S⁻ᵀf when `transposed`), then (S⁻¹𝓜)x, …: each orthogonalised against the point's own vectors in 𝓜's
  // inner product (twice) and normalised; `first` gets the raw x when given.
  std::vector<Eigen::VectorXcd> krylov_vectors(Vec input, int vectors, bool transposed, Eigen::VectorXcd* first) {
    std::vector<Eigen::VectorXcd> out, mout;
    solver_.solve(input, x_, transposed);
    Eigen::VectorXcd q = local_pairs(x_);
    if (first) *first = q;
    for (int j = 0; j < vectors; ++j) {
      if (j > 0) {
        store_pairs(mout.back(), v_);
        solver_.solve(v_, x_, transposed);
        q = local_pairs(x_);
      }
      const double before = std::sqrt(std::max(ops_.inner(q, ops_.apply(Op::M, q))(0, 0).real(), 0.0));
      for (int pass = 0; pass < 2; ++pass)
        for (std::size_t i = 0; i < out.size(); ++i) q -= ops_.inner(mout[i], q)(0, 0) * out[i];
      Eigen::VectorXcd mq = ops_.apply(Op::M, q);
      const double norm = std::sqrt(std::max(ops_.inner(q, mq)(0, 0).real(), 0.0));
      if (!(norm > 1e-10 * before)) break;
      out.push_back(q / norm);
      mout.push_back(mq / norm);
    }
    return out;
  }

  // x and −ix give the J-symmetric pair (x + Jx)/2, (−ix + J(−ix))/2, which span x and Jx (= −x(−s̄)).
  void add_symmetric_parts(const std::vector<Eigen::VectorXcd>& xs, std::vector<Eigen::VectorXcd>& out) const {
    for (const Eigen::VectorXcd& x : xs) {
      out.push_back(ops_.symmetric(x));
      out.push_back(ops_.symmetric(cd(0, -1) * x));
    }
  }

  static Eigen::MatrixXcd columns(const std::vector<Eigen::VectorXcd>& v) {
    Eigen::MatrixXcd W(v.empty() ? 0 : v.front().size(), static_cast<Eigen::Index>(v.size()));
    for (std::size_t j = 0; j < v.size(); ++j) W.col(static_cast<Eigen::Index>(j)) = v[j];
    return W;
  }

  // A block W just appended to a basis Z: the projection's new columns Zᴴ(op W) and rows Wᴴ op Z = (Zᴴ op' W)ᴴ
  // (op' the adjoint of op), and the inputs' new rows Wᴴ in (F for the primal basis, G for the dual). Returns op W.
  Eigen::MatrixXcd grow(const SymmetricBasis& Z, const Eigen::MatrixXcd& W, Op op, Op adjoint, const Eigen::MatrixXcd& in,
                        Eigen::MatrixXcd& H, Eigen::MatrixXcd& f) {
    const Eigen::Index n = Z.size(), k = W.cols(), old = n - k;
    const Eigen::MatrixXcd OW = ops_.apply(op, W), cols = ops_.inner(Z.vectors(), OW);
    const Eigen::MatrixXcd rows = ops_.inner(Z.vectors().leftCols(old), ops_.apply(adjoint, W));
    H.conservativeResize(n, n);
    H.rightCols(k) = cols;
    H.bottomLeftCorner(k, old) = rows.adjoint();
    f.conservativeResize(n, in.cols());
    f.bottomRows(k) = ops_.inner(W, in);
    return OW;
  }

  // W was just appended to X: Hx and fx grow, and P = Yᵀ𝓜X, Q = YᵀAX by their columns.
  void add_primal(const Eigen::MatrixXcd& W) {
    const Eigen::MatrixXcd AW = grow(X_, W, Op::A, Op::AH, F_, Hx_, fx_);
    const Eigen::Index my = Y_.size(), n = X_.size(), k = W.cols();
    P_.conservativeResize(my, n);
    Q_.conservativeResize(my, n);
    if (my == 0) return;
    P_.rightCols(k) = ops_.inner(Y_.vectors(), ops_.apply(Op::M, W), false);
    Q_.rightCols(k) = ops_.inner(Y_.vectors(), AW, false);
  }

  // V was just appended to Y: Hy (YᴴAᵀY; the adjoint of Aᵀ is Ā) and fy grow, and P, Q by their rows Vᵀ𝓜X = (𝓜V)ᵀX
  // and VᵀAX = (AᵀV)ᵀX.
  void add_dual(const Eigen::MatrixXcd& V) {
    const Eigen::MatrixXcd AtV = grow(Y_, V, Op::AT, Op::Abar, G_, Hy_, fy_);
    const Eigen::Index n = Y_.size(), k = V.cols();
    P_.conservativeResize(n, X_.size());
    Q_.conservativeResize(n, X_.size());
    P_.bottomRows(k) = ops_.inner(ops_.apply(Op::M, V), X_.vectors(), false);
    Q_.bottomRows(k) = ops_.inner(AtV, X_.vectors(), false);
  }

  void share_from_root(Worst& w) const {
    std::vector<double> shared{w.s, w.estimate};
    const int entries = directions() * directions();
    for (int k = 0; k < entries; ++k) {
      shared.push_back(w.scale.data()[k]);
      shared.push_back(w.galerkin.data()[k].real());
      shared.push_back(w.galerkin.data()[k].imag());
    }
    MPI_Bcast(shared.data(), static_cast<int>(shared.size()), MPI_DOUBLE, 0, ops_.comm());
    w.s = shared[0];
    w.estimate = shared[1];
    for (int k = 0; k < entries; ++k) {
      w.scale.data()[k] = shared[2 + 3 * k];
      w.galerkin.data()[k] = {shared[3 + 3 * k], shared[4 + 3 * k]};
    }
  }

  LocalOperators ops_;
  ShiftedSolver solver_;
  SymmetricBasis X_, Y_;
  Eigen::MatrixXcd F_, G_;
  std::vector<Vec> inputs_, outputs_;
  PVec x_, v_;
  Eigen::MatrixXcd Hx_, fx_, Hy_, fy_, P_, Q_;
};

}  // namespace

Eigen::MatrixXcd ReducedVolumeResponse::operator()(std::complex<double> s) const {
  Eigen::MatrixXcd S = cd(0, -1) * K.cast<cd>();
  S.diagonal().array() += s;
  const Eigen::MatrixXcd bc = b.cast<cd>();
  return bc.transpose() * S.partialPivLu().solve(bc);
}

std::vector<VolumePole> volume_poles(const ReducedVolumeResponse& model) {
  // iK = V (iμ) V⁻¹: R_G(s) = Σ_l (bᵀV)_l (V⁻¹b)_l / (s − iμ_l). K is real, so its eigenvalues are real or come in
  // conjugate pairs: λ = iμ with Im μ < 0 (Re λ > 0) is kept, its partner −λ̄ = iμ̄ left to pole_sum; a real μ is a
  // purely damped pole, its own partner, kept with half its (real) residue.
  const Eigen::EigenSolver<Eigen::MatrixXd> es(model.K);
  if (es.info() != Eigen::Success) throw std::runtime_error("the reduced response's eigen-decomposition failed");
  const Eigen::MatrixXcd V = es.eigenvectors(), bc = model.b.cast<cd>();
  const Eigen::MatrixXcd left = V.transpose() * bc, right = V.partialPivLu().solve(bc);
  std::vector<VolumePole> out;
  for (Eigen::Index l = 0; l < V.cols(); ++l) {
    const cd mu = es.eigenvalues()[l];
    if (mu.imag() > 0) continue;
    const double share = mu.imag() == 0 ? 0.5 : 1.0;
    out.push_back({cd(0, 1) * mu, share * left.row(l).transpose() * right.row(l)});
    if (mu.imag() == 0) out.back().lambda = cd(0, mu.real());  // exactly no frequency
  }
  return out;
}

Eigen::MatrixXcd pole_sum(const std::vector<VolumePole>& poles, std::complex<double> s) {
  if (poles.empty()) throw std::invalid_argument("pole_sum of no poles (its size is unknown)");
  Eigen::MatrixXcd R = Eigen::MatrixXcd::Zero(poles.front().H.rows(), poles.front().H.cols());
  for (const VolumePole& p : poles) R += p.H / (s - p.lambda) + p.H.conjugate() / (s + std::conj(p.lambda));
  return R;
}

VolumeKrylovReduction volume_krylov_reduction(const ViscousVolumeForms& forms, const std::vector<double>& window,
                                              const std::vector<double>& beyond, const VolumeKrylovOptions& options,
                                              const std::function<void(const std::string&)>& progress) {
  if (window.size() < 3) throw std::invalid_argument("a 3-D Krylov response reduction needs at least 3 window frequencies");
  if (!(window.front() >= 0)) throw std::invalid_argument("the 3-D response window must start at sigma >= 0");
  VolumeGreedy greedy(forms);
  std::vector<double> candidates = window;
  candidates.insert(candidates.end(), beyond.begin(), beyond.end());
  VolumeKrylovReduction out;
  const auto say = [&](const std::string& line) { if (progress) progress(line); };
  std::vector<double> first{0.0, 0.5 * (window.front() + window.back()), window.back()};
  if (window.front() > 0) first.insert(first.begin() + 1, window.front());
  for (const double s : first) {
    greedy.expand(s, options.vectors_per_point);
    out.points.push_back(s);
    out.point_errors.push_back(std::numeric_limits<double>::quiet_NaN());
    say(fmt::format("3-D krylov response: point {} at s = {:.6g}; {} + {} vectors", out.points.size(), s,
                    greedy.primal_size(), greedy.dual_size()));
  }
  for (const cd s : options.exact_at) {
    greedy.expand(s, options.vectors_per_point);
    say(fmt::format("3-D krylov response: exact at s = {:.6g}{:+.6g}i; {} + {} vectors", s.real(), s.imag(),
                    greedy.primal_size(), greedy.dual_size()));
  }
  for (;;) {
    const auto worst = greedy.worst(candidates, window.size());
    out.scale = worst.scale;
    out.estimate = worst.estimate;
    const bool last = static_cast<int>(out.points.size()) >= options.max_points;
    if (worst.estimate <= options.tolerance || last) {
      // The estimate says done (or the points are used up): a forced solve where it is largest says how far the
      // table is. If it is not done after all, that point (factored already) is expanded and the search goes on.
      out.check_point = worst.s;
      say(fmt::format("3-D krylov response: estimated {:.2g}; a forced solve at its worst, s = {:.6g}", worst.estimate,
                      worst.s));
      out.check_error = greedy.measured_error(worst.s, worst);
      say(fmt::format("3-D krylov response: measured {:.2g} there", out.check_error));
      if (out.check_error <= options.tolerance && worst.estimate <= options.tolerance) break;
      if (last) {
        out.within_tolerance = false;
        break;
      }
    }
    const Eigen::MatrixXcd R = greedy.expand(worst.s, options.vectors_per_point);
    out.points.push_back(worst.s);
    out.point_errors.push_back(((R - worst.galerkin).cwiseAbs().array() / worst.scale.array()).maxCoeff());
    say(fmt::format("3-D krylov response: point {} at s = {:.6g}: estimated {:.2g}, measured {:.2g}; {} + {} vectors",
                    out.points.size(), worst.s, worst.estimate, out.point_errors.back(), greedy.primal_size(),
                    greedy.dual_size()));
  }
  out.model = greedy.model();
  out.primal_vectors = static_cast<int>(greedy.primal_size());
  out.dual_vectors = static_cast<int>(greedy.dual_size());
  return out;
}

}  // namespace rc::modes
