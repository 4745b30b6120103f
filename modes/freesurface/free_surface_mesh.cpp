#include "free_surface_mesh.hpp"

#include "complex_eigen.hpp"
#include "free_surface_forms.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::modes {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kGeostrophic = 1e-5;  // |λ| below this is the geostrophic λ = 0 (see below)

// The volume and surface forms of one mesh, as Eigen's.
struct MeshForms {
  Eigen::SparseMatrix<double> Kh, Kz, Gc, M;
  Eigen::VectorXd f1, f2;
  FreeSurfaceForms surface;
};

MeshForms mesh_forms(const FESpace& space, double zc) {
  const PoincareForms pf = assemble_poincare_forms(space, zc);
  MeshForms f;
  f.Kh = to_eigen(pf.Kh);
  f.Kz = to_eigen(pf.Kz);
  f.Gc = to_eigen(pf.Gc);
  f.M = f.Kh + f.Kz;
  f.f1 = to_eigen(pf.f1);
  f.f2 = to_eigen(pf.f2);
  f.surface = assemble_free_surface_forms(space, zc);
  return f;
}

// The companion matrix [0 I; −A2⁻¹A0, −A2⁻¹A1] of the symmetric quadratic (header) in (x, y).
Eigen::MatrixXd companion(const MeshForms& f) {
  const auto& sd = f.surface.surface_dofs;
  const Eigen::Index n = f.M.rows(), ns = static_cast<Eigen::Index>(sd.size()), m = n + ns;
  const Eigen::MatrixXd S = Eigen::MatrixXd(f.surface.S);
  Eigen::MatrixXd A2 = Eigen::MatrixXd::Zero(m, m), A1 = Eigen::MatrixXd::Zero(m, m), A0 = Eigen::MatrixXd::Zero(m, m);
  A2.topLeftCorner(n, n) = Eigen::MatrixXd(f.M) + 4 * S;
  A1.topLeftCorner(n, n) = 2 * Eigen::MatrixXd(f.Gc);
  A0.topLeftCorner(n, n) = -4 * Eigen::MatrixXd(f.Kz);
  for (Eigen::Index k = 0; k < ns; ++k) {
    for (Eigen::Index l = 0; l < ns; ++l) A0(n + k, n + l) = S(sd[k], sd[l]);  // M_s
    A2.col(n + k).head(n) = -S.col(sd[k]);                                      // −PᵀM_s
    A2.row(n + k).head(n) = -S.row(sd[k]);                                      // −M_s P
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A2);
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(2 * m, 2 * m);
  L.topRightCorner(m, m).setIdentity();
  L.bottomLeftCorner(m, m) = -lu.solve(A0);
  L.block(m, m, m, n) = -lu.solve(A1.leftCols(n));  // λx̂'s x part: A1 is zero on y
  return L;
}

// One eigenpair's pressure x (real: the eigenvalue is) and its coupling.
PartialFillPair mesh_pair(const MeshForms& f, double l, const Eigen::VectorXd& x, const double norms[4]) {
  const FreeSurfaceForms& s = f.surface;
  const Eigen::VectorXd Sx = s.S * x, Mx = f.M * x, Gx = f.Gc * x, Kzx = f.Kz * x;
  const Eigen::VectorXd res = -l * l * l * l * Sx + l * l * (Mx + 4 * Sx) + 2 * l * Gx - 4 * Kzx;
  PartialFillPair p;
  p.lambda = l;
  p.residual = res.norm() / ((l * l * l * l * norms[0] + l * l * norms[1] + 2 * std::abs(l) * norms[2] + 4 * norms[3]) *
                             x.norm());
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

// Zhukovsky's potential with the free surface at zero potential: data r = f1 − f2 about the centroid, q = g1 per
// unit offset, solved on the dofs off the surface; J(c) = π (r + cq)ᵀ M⁻¹ (r + cq).
void zhukovsky_dirichlet(const MeshForms& f, PartialFillSpectrum& out) {
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
  out.J_D = kPi * r.dot(Ar);
  out.J_D1 = kPi * q.dot(Ar);
  out.J_D2 = kPi * q.dot(ldlt.solve(q));
}

}  // namespace

PartialFillSpectrum solve_partially_filled_mesh(const FESpace& space, int max_unknowns, bool keep_pressure) {
  PartialFillSpectrum out;
  out.fluid = integrate_fluid(space);
  const MeshForms f = mesh_forms(space, out.fluid.centroid_z);
  const long n = space.ndof(), m = n + static_cast<long>(f.surface.surface_dofs.size());
  if (m > max_unknowns)
    throw std::runtime_error(fmt::format("free surface: {} unknowns (pressure and surface) > {}, the dense solver's "
                                         "limit: take a larger --mesh-size or a lower --order", m, max_unknowns));
  out.surface_radius = f.surface.radius;
  const auto [low, high] = std::minmax_element(space.mesh().nodes.begin(), space.mesh().nodes.end(),
                                               [](const auto& p, const auto& q) { return p[1] < q[1]; });
  out.height = (*high)[1] - (*low)[1];
  out.K0 = f.surface.K0;
  out.K1 = f.surface.K1;
  out.K2 = f.surface.K2;
  out.radial_dofs = static_cast<int>(n);
  out.axial_dofs = 1;
  out.order = space.order();
  zhukovsky_dirichlet(f, out);
  out.sum_rule = out.fluid.A_f + out.K2 - out.J_D;

  const ComplexEigen eig = real_eigen(companion(f), true, "the free surface's companion matrix");
  const double norms[4] = {f.surface.S.norm(), Eigen::SparseMatrix<double>(f.M + 4 * f.surface.S).norm(), f.Gc.norm(),
                           f.Kz.norm()};  // Frobenius norms of the sparse forms, for the residuals' scale
  for (Eigen::Index i = 0; i < eig.values.size(); ++i) {
    const std::complex<double> lc = eig.values(i);
    // λ = 0 is a defective eigenvalue of high multiplicity (the steady geostrophic motions, Kz p = 0): rounding
    // splits it into a cloud of |λ| ~ 1e-7 with complex members (measured: 28 of 1000 on the fill 0.9 cylinder, all
    // |λ| < 2e-7). Those hold no surface displacement and couple to nothing; real small ones are kept (a cone's
    // dense spectrum near 0 carries 3e-8 of its sum rule at 1e-9 < |λ| < 1e-5).
    const bool complex = std::abs(lc.imag()) > 1e-7 * std::max(1.0, std::abs(lc));
    if (complex && std::abs(lc) < kGeostrophic) {
      out.pairs.push_back(PartialFillPair{});
      continue;
    }
    if (complex)
      throw std::runtime_error(fmt::format("free surface: a complex eigenvalue {} + {}i", lc.real(), lc.imag()));
    Eigen::Index big = 0;
    eig.vectors.col(i).head(n).cwiseAbs().maxCoeff(&big);
    const std::complex<double> phase = eig.vectors(big, i) / std::abs(eig.vectors(big, i));
    const Eigen::VectorXd x = (eig.vectors.col(i).head(n) / phase).real();
    out.pairs.push_back(mesh_pair(f, lc.real(), x, norms));
    if (keep_pressure) out.pairs.back().pressure.assign(x.data(), x.data() + x.size());
  }
  std::sort(out.pairs.begin(), out.pairs.end(),
            [](const PartialFillPair& x, const PartialFillPair& y) { return x.coupling.E > y.coupling.E; });
  for (const auto& p : out.pairs) out.sum_E += p.coupling.E;
  return out;
}

}  // namespace rc::modes
