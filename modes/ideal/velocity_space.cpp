#include "velocity_space.hpp"

namespace rc::modes {

VelocitySpace::VelocitySpace(const FESpace& space, double centroid_z)
    : npe_(space.nodes_per_element()), ndof_(space.ndof()) {
  ElementQuadrature eq;
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    space.quadrature(e, eq);
    auto dofs = space.element_dofs(e);
    for (std::size_t q = 0; q < eq.w.size(); ++q) {
      const double r = eq.r[q];
      omega_.push_back(eq.w[q] * r);
      W_.insert(W_.end(), {eq.z[q] - centroid_z, -(eq.z[q] - centroid_z), -r});  // e1 × r, docs/physics.md §2
      for (int i = 0; i < npe_; ++i) {
        dof_.push_back(dofs[i]);
        ga_.push_back(eq.dNr[q * npe_ + i]);
        gb_.push_back(-eq.N[q * npe_ + i] / r);
        gc_.push_back(eq.dNz[q * npe_ + i]);
      }
    }
  }
  weights_.resize(static_cast<Eigen::Index>(W_.size()));
  for (std::size_t g = 0; g < omega_.size(); ++g) weights_.segment<3>(3 * g).setConstant(omega_[g]);
}

Eigen::VectorXd VelocitySpace::coupling_vector() const {
  return Eigen::Map<const Eigen::VectorXd>(W_.data(), size());
}

void VelocitySpace::coriolis(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
  out.resize(v.size());
  for (std::size_t g = 0; g < omega_.size(); ++g) {
    out[3 * g] = -2 * v[3 * g + 1];
    out[3 * g + 1] = -2 * v[3 * g];
    out[3 * g + 2] = 0;
  }
}

void VelocitySpace::shifted_coriolis_inverse(double sigma, Eigen::VectorXd& v) const {
  // (S − σ) on (a, b) is [[−σ, −2], [−2, −σ]], whose inverse is [[−σ, 2], [2, −σ]] / (σ² − 4); on c it is −σ.
  const double d = 1 / (sigma * sigma - 4);
  for (std::size_t g = 0; g < omega_.size(); ++g) {
    const double a = v[3 * g], b = v[3 * g + 1];
    v[3 * g] = d * (-sigma * a + 2 * b);
    v[3 * g + 1] = d * (2 * a - sigma * b);
    v[3 * g + 2] /= -sigma;
  }
}

void VelocitySpace::divergence(const Eigen::VectorXd& v, std::vector<double>& g) const {
  g.assign(ndof_, 0.0);
  for (std::size_t q = 0; q < omega_.size(); ++q)
    for (int i = 0; i < npe_; ++i) {
      const std::size_t k = q * npe_ + i;
      if (dof_[k] < 0) continue;
      g[dof_[k]] += omega_[q] * (ga_[k] * v[3 * q] + gb_[k] * v[3 * q + 1] + gc_[k] * v[3 * q + 2]);
    }
}

void VelocitySpace::add_gradient(const std::vector<double>& p, double scale, Eigen::VectorXd& v) const {
  for (std::size_t q = 0; q < omega_.size(); ++q)
    for (int i = 0; i < npe_; ++i) {
      const std::size_t k = q * npe_ + i;
      if (dof_[k] < 0) continue;
      const double pi = scale * p[dof_[k]];
      v[3 * q] += ga_[k] * pi;
      v[3 * q + 1] += gb_[k] * pi;
      v[3 * q + 2] += gc_[k] * pi;
    }
}

}  // namespace rc::modes
