#include "spectral_survey.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::modes {
namespace {

// The quadrature-point velocity space of spectral_survey.hpp: per point its weight ω = w r, the fields
// (a, b, c), and the rows of G (p -> (p_r, −p/r, p_z)) as basis coefficients of the element's dofs.
class VelocitySpace {
 public:
  VelocitySpace(const FESpace& space, double centroid_z) : npe_(space.nodes_per_element()), ndof_(space.ndof()) {
    ElementQuadrature eq;
    for (std::size_t e = 0; e < space.num_elements(); ++e) {
      space.quadrature(e, eq);
      auto dofs = space.element_dofs(e);
      for (std::size_t q = 0; q < eq.w.size(); ++q) {
        const double r = eq.r[q];
        omega_.push_back(eq.w[q] * r);
        W_.insert(W_.end(), {eq.z[q] - centroid_z, -(eq.z[q] - centroid_z), -r});  // e1 × r, SPEC §2
        for (int i = 0; i < npe_; ++i) {
          dof_.push_back(dofs[i]);
          ga_.push_back(eq.dNr[q * npe_ + i]);
          gb_.push_back(-eq.N[q * npe_ + i] / r);
          gc_.push_back(eq.dNz[q * npe_ + i]);
        }
      }
    }
  }
  std::size_t size() const { return W_.size(); }
  const std::vector<double>& coupling_vector() const { return W_; }

  // ω repeated for the three components: ⟨u, v⟩ = Σ weights ∘ u ∘ v.
  Eigen::VectorXd component_weights() const {
    Eigen::VectorXd w(W_.size());
    for (std::size_t g = 0; g < omega_.size(); ++g) w.segment<3>(3 * g).setConstant(omega_[g]);
    return w;
  }
  // Coriolis term S = 2iẑ× in the (a, b, c) representation.
  void coriolis(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
    out.resize(v.size());
    for (std::size_t g = 0; g < omega_.size(); ++g) {
      out[3 * g] = -2 * v[3 * g + 1];
      out[3 * g + 1] = -2 * v[3 * g];
      out[3 * g + 2] = 0;
    }
  }
  // v <- P_H v = v − G M⁻¹ Gᵀ Ω v.
  void project(Eigen::VectorXd& v, const StiffnessSolver& solver) const {
    std::vector<double> g(ndof_, 0.0), p;
    for (std::size_t q = 0; q < omega_.size(); ++q)
      for (int i = 0; i < npe_; ++i) {
        const std::size_t k = q * npe_ + i;
        if (dof_[k] < 0) continue;
        g[dof_[k]] += omega_[q] * (ga_[k] * v[3 * q] + gb_[k] * v[3 * q + 1] + gc_[k] * v[3 * q + 2]);
      }
    solver.solve(g, p);
    for (std::size_t q = 0; q < omega_.size(); ++q)
      for (int i = 0; i < npe_; ++i) {
        const std::size_t k = q * npe_ + i;
        if (dof_[k] < 0) continue;
        const double pi = p[dof_[k]];
        v[3 * q] -= ga_[k] * pi;
        v[3 * q + 1] -= gb_[k] * pi;
        v[3 * q + 2] -= gc_[k] * pi;
      }
  }

 private:
  int npe_, ndof_;
  std::vector<double> omega_, W_;
  std::vector<int> dof_;
  std::vector<double> ga_, gb_, gc_;
};

// Gauss rule from the Lanczos tridiagonal matrix: nodes = its eigenvalues, weights = mass · (first
// component of each eigenvector)² (Golub–Welsch).
std::vector<GaussNode> gauss_rule(const std::vector<double>& alpha, const std::vector<double>& beta, double mass) {
  const int k = static_cast<int>(alpha.size());
  Eigen::VectorXd d = Eigen::Map<const Eigen::VectorXd>(alpha.data(), k);
  Eigen::VectorXd e = Eigen::Map<const Eigen::VectorXd>(beta.data(), std::max(k - 1, 0));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es;
  es.computeFromTridiagonal(d, e, Eigen::ComputeEigenvectors);
  if (es.info() != Eigen::Success) throw std::runtime_error("spectral survey: tridiagonal eigen-solve failed");
  std::vector<GaussNode> nodes(k);
  for (int i = 0; i < k; ++i) {
    nodes[i].lambda = es.eigenvalues()[i];
    nodes[i].E = mass * es.eigenvectors()(0, i) * es.eigenvectors()(0, i);
  }
  return nodes;
}

// Largest move of the heavy nodes between two rules, relative to the slice scale max(|λ|, 0.1) used when
// they are refined. Weights are not compared: a cluster's E comes from the eigen-solve, not from the rule.
double rule_change(const std::vector<GaussNode>& now, const std::vector<GaussNode>& before, double mass,
                   const SurveySettings& settings) {
  double change = 0;
  for (const auto& n : now) {
    if (n.E < settings.weight_floor * mass || std::abs(n.lambda) < settings.lambda_floor) continue;
    double best = std::numeric_limits<double>::infinity();
    for (const auto& b : before) best = std::min(best, std::abs(b.lambda - n.lambda));
    change = std::max(change, best / std::max(std::abs(n.lambda), 0.1));
  }
  return change;
}

}  // namespace

SpectralSurvey survey_spectral_measure(const FESpace& space, double centroid_z, const StiffnessSolver& solver,
                                       const SurveySettings& settings) {
  const VelocitySpace V(space, centroid_z);
  const Eigen::VectorXd weights = V.component_weights();
  auto dot = [&](const Eigen::VectorXd& u, const Eigen::VectorXd& v) { return u.dot(weights.cwiseProduct(v)); };
  Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(V.coupling_vector().data(), V.size());
  V.project(q, solver);
  const double norm0 = std::sqrt(dot(q, q));
  SpectralSurvey survey;
  if (!(norm0 > 0)) { survey.exhausted = true; return survey; }  // no solenoidal coupling at all
  const double mass = std::numbers::pi * norm0 * norm0;  // = A_f − J_zh
  const int kmax = std::max(settings.max_steps, 1);
  Eigen::MatrixXd basis(V.size(), kmax);  // Lanczos vectors, one per column
  basis.col(0) = q / norm0;
  std::vector<double> alpha, beta;
  std::vector<GaussNode> previous;
  Eigen::VectorXd v, h;
  for (int j = 0; j < kmax; ++j) {
    V.coriolis(basis.col(j), v);
    V.project(v, solver);
    alpha.push_back(dot(basis.col(j), v));
    // Full re-orthogonalisation, twice (the spectrum is dense: plain Lanczos would lose orthogonality).
    const auto Q = basis.leftCols(j + 1);
    for (int pass = 0; pass < 2; ++pass) {
      h.noalias() = Q.transpose() * weights.cwiseProduct(v);
      v.noalias() -= Q * h;
    }
    const double bnorm = std::sqrt(dot(v, v));
    survey.steps = j + 1;
    if (bnorm < 1e-12 * 2) { survey.exhausted = true; break; }  // ‖A‖ <= 2: invariant subspace found
    if ((j + 1) % 10 == 0) {
      auto rule = gauss_rule(alpha, beta, mass);
      const bool settled =
          !previous.empty() && rule_change(rule, previous, mass, settings) < settings.tolerance;
      previous = std::move(rule);
      if (settled) break;
    }
    if (j + 1 == kmax) break;
    beta.push_back(bnorm);
    basis.col(j + 1) = v / bnorm;
  }
  beta.resize(alpha.size() - 1);
  survey.nodes = gauss_rule(alpha, beta, mass);
  return survey;
}

}  // namespace rc::modes
