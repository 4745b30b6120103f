#include "free_surface_quadratic.hpp"

#include "poincare_forms.hpp"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace rc::modes {

namespace {


// Zhukovsky's potential with the free surface at zero potential: data r = f1 − f2 about the centroid, q = g1 per
// unit offset, solved on the dofs off the surface; J(c) = π (r + cq)ᵀ M⁻¹ (r + cq).
void zhukovsky_dirichlet(const FreeSurfaceQuadratic& f, PartialFillSpectrum& out) {
  const Eigen::Index n = f.M.rows();
  std::vector<char> on_surface(n, 0);
  for (int d : f.surface.surface_dofs) on_surface[d] = 1;
  std::vector<int> keep;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!on_surface[i]) keep.push_back(static_cast<int>(i));
  Eigen::SparseMatrix<double> select(static_cast<Eigen::Index>(keep.size()), n);
  for (std::size_t k = 0; k < keep.size(); ++k) select.insert(static_cast<Eigen::Index>(k), keep[k]) = 1;
  const Eigen::SparseMatrix<double> A = select * f.M * select.transpose();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
  if (ldlt.info() != Eigen::Success) throw std::runtime_error("free surface: Zhukovsky's factorisation failed");
  const Eigen::VectorXd r = select * (f.f1 - f.f2), q = select * f.surface.g1;
  const Eigen::VectorXd Ar = ldlt.solve(r);
  out.J_D = std::numbers::pi * r.dot(Ar);
  out.J_D1 = std::numbers::pi * q.dot(Ar);
  out.J_D2 = std::numbers::pi * q.dot(ldlt.solve(q));
}

}  // namespace

FreeSurfaceQuadratic free_surface_quadratic(const FESpace& space) {
  FreeSurfaceQuadratic f;
  f.fluid = integrate_fluid(space);
  const PoincareForms pf = assemble_poincare_forms(space, f.fluid.centroid_z);
  f.Kh = to_eigen(pf.Kh);
  f.Kz = to_eigen(pf.Kz);
  f.Gc = to_eigen(pf.Gc);
  f.M = f.Kh + f.Kz;
  f.f1 = to_eigen(pf.f1);
  f.f2 = to_eigen(pf.f2);
  f.surface = assemble_free_surface_forms(space, f.fluid.centroid_z);
  f.norms = {f.surface.S.norm(), Eigen::SparseMatrix<double>(f.M + 4 * f.surface.S).norm(), f.Gc.norm(), f.Kz.norm()};
  return f;
}

// A2 = [M + 4S, −PᵀM_s; −M_sP, 0], A1 = [2Gc, 0; 0, 0], A0 = [−4Kz, 0; 0, M_s] with M_s = P S Pᵀ.
std::array<Eigen::SparseMatrix<double>, 3> FreeSurfaceQuadratic::coefficients() const {
  const Eigen::Index n = M.rows(), m = unknowns();
  std::vector<Eigen::Index> surface_index(n, -1);
  for (std::size_t k = 0; k < surface.surface_dofs.size(); ++k) surface_index[surface.surface_dofs[k]] = n + Eigen::Index(k);
  std::vector<Eigen::Triplet<double>> t2, t0;
  const auto add = [](std::vector<Eigen::Triplet<double>>& t, const Eigen::SparseMatrix<double>& A, double scale) {
    for (Eigen::Index j = 0; j < A.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) t.emplace_back(it.row(), it.col(), scale * it.value());
  };
  add(t2, M, 1.0);
  add(t0, Kz, -4.0);
  for (Eigen::Index j = 0; j < surface.S.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(surface.S, j); it; ++it) {
      const Eigen::Index i = it.row(), c = it.col(), yi = surface_index[i], yc = surface_index[c];
      t2.emplace_back(i, c, 4 * it.value());
      if (yc >= 0) t2.emplace_back(i, yc, -it.value());
      if (yi >= 0) t2.emplace_back(yi, c, -it.value());
      if (yi >= 0 && yc >= 0) t0.emplace_back(yi, yc, it.value());
    }
  std::array<Eigen::SparseMatrix<double>, 3> A{Eigen::SparseMatrix<double>(m, m), Eigen::SparseMatrix<double>(m, m),
                                               Eigen::SparseMatrix<double>(m, m)};
  A[0].setFromTriplets(t0.begin(), t0.end());
  std::vector<Eigen::Triplet<double>> t1;
  add(t1, Gc, 2.0);
  A[1].setFromTriplets(t1.begin(), t1.end());
  A[2].setFromTriplets(t2.begin(), t2.end());
  return A;
}

PartialFillPair free_surface_pair(const FreeSurfaceQuadratic& f, double l, const Eigen::VectorXd& x) {
  const FreeSurfaceForms& s = f.surface;
  const Eigen::VectorXd Sx = s.S * x, Mx = f.M * x, Gx = f.Gc * x, Kzx = f.Kz * x;
  const Eigen::VectorXd res = -l * l * l * l * Sx + l * l * (Mx + 4 * Sx) + 2 * l * Gx - 4 * Kzx;
  const auto& nm = f.norms;
  PartialFillPair p;
  p.lambda = l;
  p.residual = res.norm() / ((l * l * l * l * nm[0] + l * l * nm[1] + 2 * std::abs(l) * nm[2] + 4 * nm[3]) * x.norm());
  FreeSurfaceFormValues v;
  v.f1p = f.f1.dot(x);
  v.f2p = f.f2.dot(x);
  v.f3p = s.f3.dot(x);
  v.g1p = s.g1.dot(x);
  v.e1p = s.e1.dot(x);
  v.kh = x.dot(f.Kh * x);
  v.gc = x.dot(Gx);
  v.kz = x.dot(Kzx);
  v.ss = x.dot(Sx);
  // λ = 0: steady geostrophic motions, no surface displacement, no coupling (partial_fill_cylinder.cpp says why).
  if (std::abs(l) > 1e-8) p.coupling = free_surface_coupling(l, v);
  return p;
}

PartialFillSpectrum spectrum_integrals(const FESpace& space, const FreeSurfaceQuadratic& f) {
  PartialFillSpectrum out;
  out.fluid = f.fluid;
  out.surface_radius = f.surface.radius;
  const auto [low, high] = std::minmax_element(space.mesh().nodes.begin(), space.mesh().nodes.end(),
                                               [](const auto& p, const auto& q) { return p[1] < q[1]; });
  out.height = (*high)[1] - (*low)[1];
  out.K0 = f.surface.K0;
  out.K1 = f.surface.K1;
  out.K2 = f.surface.K2;
  out.radial_dofs = static_cast<int>(f.pressure_dofs());
  out.axial_dofs = 1;
  out.order = space.order();
  zhukovsky_dirichlet(f, out);
  out.sum_rule = out.fluid.A_f + out.K2 - out.J_D;
  return out;
}

}  // namespace rc::modes
