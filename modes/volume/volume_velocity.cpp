#include "volume_velocity.hpp"

namespace rc::modes {

VolumeVelocity::VolumeVelocity(const VolumeSpace& space, const std::array<double, 3>& centroid, MPI_Comm comm)
    : comm_(comm), npe_(space.nodes_per_element()), ndof_(space.ndof()) {
  VolumeQuadrature eq;
  const ElementRange mine = rank_elements(space, comm);
  for (std::size_t e = mine.begin; e < mine.end; ++e) {
    space.quadrature(e, eq);
    const auto dofs = space.element_dofs(e);
    for (std::size_t q = 0; q < eq.w.size(); ++q) {
      omega_.push_back(eq.w[q]);
      rel_.insert(rel_.end(), {eq.x[q] - centroid[0], eq.y[q] - centroid[1], eq.z[q] - centroid[2]});
      dof_.insert(dof_.end(), dofs.begin(), dofs.end());
      gx_.insert(gx_.end(), eq.dNx.begin() + q * npe_, eq.dNx.begin() + (q + 1) * npe_);
      gy_.insert(gy_.end(), eq.dNy.begin() + q * npe_, eq.dNy.begin() + (q + 1) * npe_);
      gz_.insert(gz_.end(), eq.dNz.begin() + q * npe_, eq.dNz.begin() + (q + 1) * npe_);
    }
  }
  weights_.resize(6 * static_cast<Eigen::Index>(omega_.size()));
  for (std::size_t q = 0; q < omega_.size(); ++q) weights_.segment(6 * q, 6).setConstant(omega_[q]);
}

Eigen::VectorXd VolumeVelocity::rotation_field(int k) const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(size());
  for (std::size_t q = 0; q < omega_.size(); ++q) {
    const double* r = &rel_[3 * q];
    double* out = v.data() + 6 * q;
    if (k == 0) { out[1] = -r[2]; out[2] = r[1]; }        // e_x × r = (0, −z, y)
    else if (k == 1) { out[0] = r[2]; out[2] = -r[0]; }   // e_y × r = (z, 0, −x)
    else { out[0] = -r[1]; out[1] = r[0]; }               // e_z × r = (−y, x, 0)
  }
  return v;
}

Eigen::VectorXd VolumeVelocity::uniform_field(int j) const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(size());
  for (std::size_t q = 0; q < omega_.size(); ++q) v(6 * static_cast<Eigen::Index>(q) + j) = 1;
  return v;
}

Eigen::VectorXd VolumeVelocity::times_i(const Eigen::VectorXd& v) {
  Eigen::VectorXd out(v.size());
  for (Eigen::Index q = 0; q < v.size(); q += 6) {
    out.segment(q, 3) = -v.segment(q + 3, 3);
    out.segment(q + 3, 3) = v.segment(q, 3);
  }
  return out;
}

void VolumeVelocity::coriolis(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
  out.resize(v.size());
  for (Eigen::Index q = 0; q < v.size(); q += 6) {
    const double* a = v.data() + q;
    double* o = out.data() + q;
    // 2iẑ × (V_r + iV_i) = −2ẑ × V_i + i 2ẑ × V_r, with ẑ × (x, y, z) = (−y, x, 0).
    o[0] = 2 * a[4]; o[1] = -2 * a[3]; o[2] = 0;
    o[3] = -2 * a[1]; o[4] = 2 * a[0]; o[5] = 0;
  }
}

void VolumeVelocity::divergence(const Eigen::VectorXd& v, std::vector<double>& g) const {
  g.assign(2 * ndof_, 0.0);
  for (std::size_t q = 0; q < omega_.size(); ++q) {
    const double* a = v.data() + 6 * q;
    const double w = omega_[q];
    for (int b = 0; b < npe_; ++b) {
      const std::size_t i = q * npe_ + b;
      const int d = dof_[i];
      if (d < 0) continue;
      g[d] += w * (gx_[i] * a[0] + gy_[i] * a[1] + gz_[i] * a[2]);
      g[ndof_ + d] += w * (gx_[i] * a[3] + gy_[i] * a[4] + gz_[i] * a[5]);
    }
  }
  sum_over_ranks(g.data(), static_cast<int>(g.size()));
}

void VolumeVelocity::sum_over_ranks(double* values, int count) const {
  int ranks = 1;
  MPI_Comm_size(comm_, &ranks);
  if (ranks > 1) MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, comm_);
}

void VolumeVelocity::add_gradient(const std::vector<double>& p, double scale, Eigen::VectorXd& v) const {
  for (std::size_t q = 0; q < omega_.size(); ++q) {
    double* a = v.data() + 6 * q;
    for (int b = 0; b < npe_; ++b) {
      const std::size_t i = q * npe_ + b;
      const int d = dof_[i];
      if (d < 0) continue;
      const double pr = scale * p[d], pi = scale * p[ndof_ + d];
      a[0] += gx_[i] * pr; a[1] += gy_[i] * pr; a[2] += gz_[i] * pr;
      a[3] += gx_[i] * pi; a[4] += gy_[i] * pi; a[5] += gz_[i] * pi;
    }
  }
}

void VolumeVelocity::shifted_coriolis_inverse(double sigma, Eigen::VectorXd& v) {
  const double d = sigma * sigma - 4;
  for (Eigen::Index q = 0; q < v.size(); q += 6) {
    double* a = v.data() + q;
    // h = h_r + i h_i across the axis: (−2iẑ× − σ) h = (2ẑ×h_i − σ h_r) + i (−2ẑ×h_r − σ h_i).
    const double rx = a[0], ry = a[1], ix = a[3], iy = a[4];
    a[0] = (-2 * iy - sigma * rx) / d;
    a[1] = (2 * ix - sigma * ry) / d;
    a[3] = (2 * ry - sigma * ix) / d;
    a[4] = (-2 * rx - sigma * iy) / d;
    a[2] /= -sigma;
    a[5] /= -sigma;
  }
}

void VolumeVelocity::project(const StiffnessSolver& solver, Eigen::VectorXd& v) const {
  std::vector<double> g, half(ndof_), x(ndof_), p(2 * ndof_);
  divergence(v, g);
  for (int part = 0; part < 2; ++part) {
    std::copy(g.begin() + part * ndof_, g.begin() + (part + 1) * ndof_, half.begin());
    solver.solve(half, x);
    std::copy(x.begin(), x.end(), p.begin() + part * ndof_);
  }
  add_gradient(p, -1.0, v);
}

}  // namespace rc::modes
