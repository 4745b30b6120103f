#include "free_surface_dynamics.hpp"

#include "free_surface_forms.hpp"  // to_eigen
#include "triplet_matrix.hpp"

#include <Eigen/Geometry>  // cross

#include <stdexcept>

namespace rc::modes {

FreeSurfaceDynamics::FreeSurfaceDynamics(const VolumeSpace& space, const VolumeForms& forms)
    : real_(real_form_pencil(forms)),
      liquid_(integrate_volume(space)),
      surface_(space),
      velocity_(space, liquid_.centroid),
      M_(to_eigen(forms.M)),
      ndof_(space.ndof()) {
  for (int d = 0; d < ndof_; ++d)
    if (surface_.surface_index(d) < 0) interior_.push_back(d);
  Eigen::SparseMatrix<double> select(static_cast<Eigen::Index>(interior_.size()), ndof_);
  for (std::size_t k = 0; k < interior_.size(); ++k) select.insert(static_cast<Eigen::Index>(k), interior_[k]) = 1;
  interior_M_ = std::make_unique<LDLT>(Eigen::SparseMatrix<double>(select * M_ * select.transpose()));
  if (interior_M_->info() != Eigen::Success)
    throw std::runtime_error("free surface: the stiffness off the surface could not be factorised");
  surface_mass_ = std::make_unique<Cholesky>(surface_.mass());
  if (surface_mass_->info() != Eigen::Success)
    throw std::runtime_error("free surface: the surface's mass matrix could not be factorised");
  const Eigen::Index nv = velocity_.size(), ns = static_cast<Eigen::Index>(surface_.dofs().size());
  weights_.resize(nv + 2 * ns);
  weights_.head(nv) = velocity_.weights();
  weights_.tail(2 * ns).setConstant(surface_.radius());
  std::vector<PetscInt> rows, cols;
  std::vector<PetscScalar> values;
  for (Eigen::Index j = 0; j < surface_.mass().outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(surface_.mass(), j); it; ++it)
      for (int h = 0; h < 2; ++h) {
        rows.push_back(h * ndof_ + surface_.dofs()[it.row()]);
        cols.push_back(h * ndof_ + surface_.dofs()[it.col()]);
        values.push_back(it.value());
      }
  surface_block_ = triplet_matrix(PETSC_COMM_SELF, 2 * ndof_, 2 * ndof_, rows, cols, values);
}

FreeSurfaceShiftedInverse::FreeSurfaceShiftedInverse(const FreeSurfaceDynamics& A, double sigma) : A_(A), sigma_(sigma) {
  const double b = A.surface_.radius();
  Q_ = shifted_real_pencil(A.real_, sigma);  // plus the surface's −σ²(σ² − 4) S/b
  petsc_check(MatAXPY(Q_, -sigma * sigma * (sigma * sigma - 4) / b, A.surface_block_, DIFFERENT_NONZERO_PATTERN), "MatAXPY");
  solver_ = std::make_unique<StiffnessSolver>(Q_, "fs_shift_", "the free surface's shifted pencil");
}

void FreeSurfaceShiftedInverse::apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) const {
  const auto& V = A_.velocity_;
  const Eigen::Index nv = V.size(), ns = static_cast<Eigen::Index>(A_.surface_.dofs().size());
  const int n = A_.ndof_;
  const double s = sigma_, c = s * (s * s - 4), b = A_.surface_.radius();
  Eigen::VectorXd y = in.head(nv);
  VolumeVelocity::shifted_coriolis_inverse(s, y);
  std::vector<double> g;
  V.divergence(y, g);
  const auto zeta = A_.displacement(in);
  const Eigen::VectorXd Mr = A_.surface_.mass() * zeta[0], Mi = A_.surface_.mass() * zeta[1];
  for (Eigen::Index k = 0; k < ns; ++k) {  // + i M_s ζ = (−M_s ζ_i, M_s ζ_r)
    g[A_.surface_.dofs()[k]] -= Mi(k);
    g[n + A_.surface_.dofs()[k]] += Mr(k);
  }
  for (double& x : g) x *= -c;
  std::vector<double> Y;
  solver_->solve(g, Y);
  Eigen::VectorXd GY = Eigen::VectorXd::Zero(nv);
  V.add_gradient(Y, 1.0, GY);
  VolumeVelocity::shifted_coriolis_inverse(s, GY);
  out.resize(in.size());
  out.head(nv) = y - GY;
  Eigen::VectorXd er(ns), ei(ns);  // η = i Y_Σ / b
  for (Eigen::Index k = 0; k < ns; ++k) {
    er(k) = -Y[n + A_.surface_.dofs()[k]] / b;
    ei(k) = Y[A_.surface_.dofs()[k]] / b;
  }
  out.segment(nv, ns) = A_.xi_from_eta(er);
  out.segment(nv + ns, ns) = A_.xi_from_eta(ei);
}

Eigen::VectorXd FreeSurfaceDynamics::interior_solve(const Eigen::VectorXd& rhs, const Eigen::VectorXd& surface_values) const {
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(ndof_);
  for (std::size_t k = 0; k < surface_.dofs().size(); ++k) phi(surface_.dofs()[k]) = surface_values(static_cast<Eigen::Index>(k));
  const Eigen::VectorXd Mphi = M_ * phi;
  Eigen::VectorXd b(static_cast<Eigen::Index>(interior_.size()));
  for (std::size_t k = 0; k < interior_.size(); ++k) b(static_cast<Eigen::Index>(k)) = rhs(interior_[k]) - Mphi(interior_[k]);
  const Eigen::VectorXd x = interior_M_->solve(b);
  for (std::size_t k = 0; k < interior_.size(); ++k) phi(interior_[k]) = x(static_cast<Eigen::Index>(k));
  return phi;
}

Eigen::VectorXd FreeSurfaceDynamics::xi_from_eta(const Eigen::VectorXd& eta) const {
  return surface_mass_->matrixU() * (surface_mass_->permutationP() * eta);
}

Eigen::VectorXd FreeSurfaceDynamics::eta_from_xi(const Eigen::VectorXd& xi) const {
  return surface_mass_->permutationPinv() * surface_mass_->matrixU().solve(xi);
}

std::array<Eigen::VectorXd, 2> FreeSurfaceDynamics::displacement(const Eigen::VectorXd& w) const {
  const Eigen::Index nv = velocity_.size(), ns = static_cast<Eigen::Index>(surface_.dofs().size());
  return {eta_from_xi(w.segment(nv, ns)), eta_from_xi(w.segment(nv + ns, ns))};
}

void FreeSurfaceDynamics::apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) const {
  const Eigen::Index nv = velocity_.size(), ns = static_cast<Eigen::Index>(surface_.dofs().size());
  const Eigen::VectorXd V = in.head(nv);  // once: coriolis and divergence take whole vectors
  const auto eta = displacement(in);
  const double b = surface_.radius();
  Eigen::VectorXd SV;
  velocity_.coriolis(V, SV);
  std::vector<double> g;
  velocity_.divergence(SV, g);
  // Y = iP: on the surface i(−b η); inside, Gᵀ Ω (SV + G Y) = 0.
  const std::array<Eigen::VectorXd, 2> Ys = {b * eta[1], -b * eta[0]};
  std::vector<double> Y(2 * ndof_);
  for (int h = 0; h < 2; ++h) {
    const Eigen::VectorXd rhs = -Eigen::Map<const Eigen::VectorXd>(g.data() + h * ndof_, ndof_);
    const Eigen::VectorXd y = interior_solve(rhs, Ys[h]);
    std::copy(y.data(), y.data() + ndof_, Y.begin() + h * ndof_);
  }
  out.resize(in.size());
  Eigen::VectorXd Vout = SV;
  velocity_.add_gradient(Y, 1.0, Vout);
  out.head(nv) = Vout;
  // ξ_out = i L⁻¹ P d_Σ with d = Gᵀ Ω V.
  std::vector<double> d;
  velocity_.divergence(V, d);
  std::array<Eigen::VectorXd, 2> ds = {Eigen::VectorXd(ns), Eigen::VectorXd(ns)};
  for (Eigen::Index k = 0; k < ns; ++k) {
    ds[0](k) = d[surface_.dofs()[k]];
    ds[1](k) = d[ndof_ + surface_.dofs()[k]];
  }
  const Eigen::VectorXd xr = surface_mass_->matrixL().solve(surface_mass_->permutationP() * ds[0]);
  const Eigen::VectorXd xi = surface_mass_->matrixL().solve(surface_mass_->permutationP() * ds[1]);
  out.segment(nv, ns) = -xi;
  out.segment(nv + ns, ns) = xr;
}

Eigen::VectorXd FreeSurfaceDynamics::solenoidal_part(Eigen::VectorXd v) const {
  std::vector<double> g;
  velocity_.divergence(v, g);
  std::vector<double> phi(2 * ndof_);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(surface_.dofs().size()));
  for (int h = 0; h < 2; ++h) {
    const Eigen::VectorXd x = interior_solve(Eigen::Map<const Eigen::VectorXd>(g.data() + h * ndof_, ndof_), zero);
    std::copy(x.data(), x.data() + ndof_, phi.begin() + h * ndof_);
  }
  velocity_.add_gradient(phi, -1.0, v);
  return v;
}

Eigen::VectorXd FreeSurfaceDynamics::surface_potential(const std::function<double(const std::array<double, 3>&)>& chi) const {
  const double mean = surface_.integral(chi) / surface_.area();
  const Eigen::VectorXd load = surface_.load([&](const std::array<double, 3>& x) { return chi(x) - mean; });
  return xi_from_eta(surface_mass_->solve(load) / surface_.radius());
}

std::array<double, 3> FreeSurfaceDynamics::axis_point() const {
  return {surface_.spin_axis()[0], surface_.spin_axis()[1], liquid_.centroid[2]};
}

// e_k × (x − P0) = e_k × (x − C) + e_k × (C − P0): the velocity space's rotation about C plus a uniform field.
Eigen::VectorXd FreeSurfaceDynamics::rotation_velocity(int k) const {
  Eigen::VectorXd v = velocity_.rotation_field(k);
  const auto P0 = axis_point();
  const Eigen::Vector3d d(liquid_.centroid[0] - P0[0], liquid_.centroid[1] - P0[1], 0.0);
  const Eigen::Vector3d u = Eigen::Vector3d::Unit(k).cross(d);
  for (int j = 0; j < 3; ++j)
    if (u(j) != 0) v += u(j) * velocity_.uniform_field(j);
  return v;
}

Eigen::VectorXd FreeSurfaceDynamics::rotation_field(int k) const {
  const Eigen::Index nv = velocity_.size(), ns = static_cast<Eigen::Index>(surface_.dofs().size());
  Eigen::VectorXd w = Eigen::VectorXd::Zero(size());
  w.head(nv) = solenoidal_part(rotation_velocity(k));
  const auto P0 = axis_point();
  // χ_k = −(ẑ × r)·(e_k × r), r = x − P0: x z, y z, −(x² + y²) (the last constant on the surface ρ = b).
  w.segment(nv, ns) = surface_potential([&](const std::array<double, 3>& x) {
    const double rx = x[0] - P0[0], ry = x[1] - P0[1], rz = x[2] - P0[2];
    return k == 0 ? rx * rz : k == 1 ? ry * rz : -(rx * rx + ry * ry);
  });
  return w;
}

// T̂_k = (P_D(e_k × ẑ), (r_k − r̄_k)/b): U about O = P0 − c ẑ is U_k + c T̂_k (k = x, y), since e_k × r_O = e_k × r +
// c e_k × ẑ and χ_O,k = χ_k + c r_k (docs/physics.md §2, "Partially filled tanks: coupling to the body", item 8).
Eigen::VectorXd FreeSurfaceDynamics::offset_field(int k) const {
  const Eigen::Index nv = velocity_.size(), ns = static_cast<Eigen::Index>(surface_.dofs().size());
  Eigen::VectorXd w = Eigen::VectorXd::Zero(size());
  w.head(nv) = solenoidal_part(k == 0 ? Eigen::VectorXd(-velocity_.uniform_field(1)) : velocity_.uniform_field(0));
  const auto P0 = axis_point();
  w.segment(nv, ns) = surface_potential([&](const std::array<double, 3>& x) { return x[k] - P0[k]; });
  return w;
}

Eigen::VectorXd FreeSurfaceDynamics::direction(int j) const {
  return j < 3 ? rotation_field(j) : offset_field(j - 3);
}

Eigen::VectorXd FreeSurfaceDynamics::times_i(const Eigen::VectorXd& w) const {
  const Eigen::Index nv = velocity_.size(), ns = static_cast<Eigen::Index>(surface_.dofs().size());
  Eigen::VectorXd out(w.size());
  out.head(nv) = VolumeVelocity::times_i(w.head(nv));
  out.segment(nv, ns) = -w.segment(nv + ns, ns);
  out.segment(nv + ns, ns) = w.segment(nv, ns);
  return out;
}

}  // namespace rc::modes
