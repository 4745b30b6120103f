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

  double dot(const std::vector<double>& u, const std::vector<double>& v) const {
    double s = 0;
    for (std::size_t g = 0; g < omega_.size(); ++g)
      s += omega_[g] * (u[3 * g] * v[3 * g] + u[3 * g + 1] * v[3 * g + 1] + u[3 * g + 2] * v[3 * g + 2]);
    return s;
  }
  // Coriolis term S = 2iẑ× in the (a, b, c) representation.
  void coriolis(const std::vector<double>& v, std::vector<double>& out) const {
    out.resize(v.size());
    for (std::size_t g = 0; g < omega_.size(); ++g) {
      out[3 * g] = -2 * v[3 * g + 1];
      out[3 * g + 1] = -2 * v[3 * g];
      out[3 * g + 2] = 0;
    }
  }
  // v <- P_H v = v − G M⁻¹ Gᵀ Ω v.
  void project(std::vector<double>& v, const StiffnessSolver& solver) const {
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

// Largest relative move of the heavy nodes (weight > 1e-8 of the mass) between two rules.
double rule_change(const std::vector<GaussNode>& now, const std::vector<GaussNode>& before, double mass) {
  double change = 0;
  for (const auto& n : now) {
    if (n.E < 1e-8 * mass) continue;
    double best = std::numeric_limits<double>::infinity(), dE = 0;
    for (const auto& b : before)
      if (std::abs(b.lambda - n.lambda) < best) { best = std::abs(b.lambda - n.lambda); dE = std::abs(b.E - n.E); }
    change = std::max({change, best / std::max(std::abs(n.lambda), 1e-3), dE / mass});
  }
  return change;
}

}  // namespace

SpectralSurvey survey_spectral_measure(const FESpace& space, double centroid_z, const StiffnessSolver& solver,
                                       const SurveySettings& settings) {
  VelocitySpace V(space, centroid_z);
  std::vector<double> q = V.coupling_vector();
  V.project(q, solver);
  const double norm0 = std::sqrt(V.dot(q, q));
  SpectralSurvey survey;
  if (!(norm0 > 0)) { survey.exhausted = true; return survey; }  // no solenoidal coupling at all
  const double mass = std::numbers::pi * norm0 * norm0;  // = A_f − J_zh
  for (double& x : q) x /= norm0;

  std::vector<std::vector<double>> basis{q};
  std::vector<double> alpha, beta, v;
  std::vector<GaussNode> previous;
  for (int j = 0; j < settings.max_steps; ++j) {
    V.coriolis(basis.back(), v);
    V.project(v, solver);
    alpha.push_back(V.dot(basis.back(), v));
    // Full re-orthogonalisation, twice (the spectrum is dense: plain Lanczos would lose orthogonality).
    for (int pass = 0; pass < 2; ++pass)
      for (const auto& b : basis) {
        const double c = V.dot(b, v);
        for (std::size_t i = 0; i < v.size(); ++i) v[i] -= c * b[i];
      }
    const double bnorm = std::sqrt(V.dot(v, v));
    survey.steps = j + 1;
    if (bnorm < 1e-12 * 2) { survey.exhausted = true; break; }  // ‖A‖ <= 2: invariant subspace found
    if ((j + 1) % 10 == 0) {
      auto rule = gauss_rule(alpha, beta, mass);
      const bool settled = !previous.empty() && rule_change(rule, previous, mass) < settings.tolerance;
      previous = std::move(rule);
      if (settled) break;
    }
    beta.push_back(bnorm);
    for (double& x : v) x /= bnorm;
    basis.push_back(v);
  }
  if (beta.size() >= alpha.size()) beta.resize(alpha.size() - 1);
  survey.nodes = gauss_rule(alpha, beta, mass);
  return survey;
}

}  // namespace rc::modes
