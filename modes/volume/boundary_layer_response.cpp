#include "boundary_layer_response.hpp"

#include "block_pencil.hpp"
#include "complex_lu.hpp"
#include "volume_forms.hpp"
#include "volume_free_surface.hpp"
#include "wall_quadrature.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace rc::modes {
namespace {

using cd = std::complex<double>;
using Vec3 = Eigen::Vector3d;
using SparseReal = Eigen::SparseMatrix<double>;

// One forcing direction: the Euler force's field u and (a partial fill) the surface potential ψ before its mean is
// taken off (viscous_fill_surface.hpp's directions: r from P0, χ_x = xz, χ_y = yz, χ_z = −(x² + y²)).
struct Direction {
  std::function<Vec3(const Vec3&)> u;
  std::function<double(const Vec3&)> psi;
};

std::vector<Direction> directions(const Vec3& origin, bool fill) {
  std::vector<Direction> d;
  for (int k = 0; k < 3; ++k)
    d.push_back({[=](const Vec3& x) { return Vec3(Vec3::Unit(k).cross(x - origin)); },
                 [=](const Vec3& x) {
                   const Vec3 r = x - origin;
                   return k == 0 ? r(0) * r(2) : k == 1 ? r(1) * r(2) : -(r(0) * r(0) + r(1) * r(1));
                 }});
  if (fill) {  // T̂_x, T̂_y: e_x × ẑ = −e_y, e_y × ẑ = e_x
    d.push_back({[](const Vec3&) { return Vec3(0, -1, 0); }, [=](const Vec3& x) { return x(0) - origin(0); }});
    d.push_back({[](const Vec3&) { return Vec3(1, 0, 0); }, [=](const Vec3& x) { return x(1) - origin(1); }});
  }
  return d;
}

// L(σ) = i(iσ + 2ẑ×)⁻¹ = α (horizontal identity) + β (x, y) ↦ (y, −x) + γ ẑẑ: (L F)_x = α F_x + β F_y,
// (L F)_y = α F_y − β F_x, (L F)_z = γ F_z.
struct Coriolis {
  cd alpha, beta, gamma;
  explicit Coriolis(cd s) : alpha(-s / (4.0 - s * s)), beta(cd(0, 2) / (4.0 - s * s)), gamma(1.0 / s) {}
  Eigen::Vector3cd apply(const Eigen::Vector3cd& F) const {
    return {alpha * F(0) + beta * F(1), alpha * F(1) - beta * F(0), gamma * F(2)};
  }
};

// The σ-independent volume integrals: L's three parts in the stiffness, the loads and the moments.
struct InteriorForms {
  SparseReal Mh, G2, Kz;  // ∫ ∇_h q·∇_h p, ∫ (q_x p_y − q_y p_x), ∫ q_z p_z
  // Per direction: h = ∫ ∇_h N·u_h, c = ∫ (u_x N_y − u_y N_x), z = ∫ u_z N_z.
  std::vector<std::array<Eigen::VectorXd, 3>> load;
  Eigen::MatrixXd Uh, Ux, Uz;  // ∫ u_j,h·u_k,h, ∫ (u_j,x u_k,y − u_j,y u_k,x), ∫ u_j,z u_k,z
};

InteriorForms interior_forms(const VolumeSpace& space, const std::vector<Direction>& dirs) {
  const int n = space.ndof(), nd = static_cast<int>(dirs.size());
  InteriorForms f;
  f.load.assign(nd, {Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)});
  f.Uh = f.Ux = f.Uz = Eigen::MatrixXd::Zero(nd, nd);
  std::vector<Eigen::Triplet<double>> th, tg, tz;
  VolumeQuadrature eq;
  const int npe = space.nodes_per_element();
  std::vector<Vec3> u(nd);
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    space.quadrature(e, eq);
    const auto dofs = space.element_dofs(e);
    for (std::size_t q = 0; q < eq.w.size(); ++q) {
      const double w = eq.w[q];
      const Vec3 x(eq.x[q], eq.y[q], eq.z[q]);
      for (int k = 0; k < nd; ++k) u[k] = dirs[k].u(x);
      for (int j = 0; j < nd; ++j)
        for (int k = 0; k < nd; ++k) {
          f.Uh(j, k) += w * (u[j](0) * u[k](0) + u[j](1) * u[k](1));
          f.Ux(j, k) += w * (u[j](0) * u[k](1) - u[j](1) * u[k](0));
          f.Uz(j, k) += w * u[j](2) * u[k](2);
        }
      for (int a = 0; a < npe; ++a) {
        const int i = dofs[a];
        if (i < 0) continue;
        const double ax = eq.dNx[q * npe + a], ay = eq.dNy[q * npe + a], az = eq.dNz[q * npe + a];
        for (int k = 0; k < nd; ++k) {
          f.load[k][0](i) += w * (ax * u[k](0) + ay * u[k](1));
          f.load[k][1](i) += w * (u[k](0) * ay - u[k](1) * ax);
          f.load[k][2](i) += w * u[k](2) * az;
        }
        for (int b = 0; b < npe; ++b) {
          const int jj = dofs[b];
          if (jj < 0) continue;
          const double bx = eq.dNx[q * npe + b], by = eq.dNy[q * npe + b], bz = eq.dNz[q * npe + b];
          th.emplace_back(i, jj, w * (ax * bx + ay * by));
          tg.emplace_back(i, jj, w * (ax * by - ay * bx));
          tz.emplace_back(i, jj, w * az * bz);
        }
      }
    }
  }
  for (auto [M, t] : {std::pair{&f.Mh, &th}, std::pair{&f.G2, &tg}, std::pair{&f.Kz, &tz}}) {
    M->resize(n, n);
    M->setFromTriplets(t->begin(), t->end());
  }
  return f;
}

// A wall point's tangent frame (e1 × e2 = n) and the layer's D(σ) in it: (D U)_1,2 from U_1,2, with a = 1/q+,
// b = 1/q−: D = ½ [[a + b, i(a − b)], [−i(a − b), a + b]] (the circular parts U± = U_1 ± i U_2 take U±/q±).
struct LayerFrame {
  Vec3 e1, e2;
  Eigen::Matrix2cd D;
  LayerFrame(const WallQuadraturePoint& p, cd sigma) {
    const Vec3 n(p.normal[0], p.normal[1], p.normal[2]);
    const Vec3 any = std::abs(n(0)) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
    e1 = (any - any.dot(n) * n).normalized();
    e2 = n.cross(e1);
    const double c = n(2);
    const cd I(0, 1), a = 1.0 / std::sqrt(I * (sigma + 2 * c)), b = 1.0 / std::sqrt(I * (sigma - 2 * c));
    D << 0.5 * (a + b), 0.5 * I * (a - b), -0.5 * I * (a - b), 0.5 * (a + b);
  }
  Eigen::Vector2cd tangential(const Eigen::Vector3cd& v) const {
    return {e1(0) * v(0) + e1(1) * v(1) + e1(2) * v(2), e2(0) * v(0) + e2(1) * v(1) + e2(2) * v(2)};
  }
};

Eigen::Vector3cd gradient_at(const WallQuadraturePoint& p, int a) {
  return {p.grad[a * 3], p.grad[a * 3 + 1], p.grad[a * 3 + 2]};
}

// The free surface's part (a partial fill): its mass over the pressure dofs and each direction's ∫_Σ q ψ.
struct SurfaceForms {
  double b = 0;
  SparseReal S;                       // ∫_Σ q p over all dofs
  std::vector<Eigen::VectorXd> psi;  // per direction, ψ less its mean
};

SurfaceForms surface_forms(const VolumeSpace& space, const std::vector<Direction>& dirs) {
  const VolumeFreeSurface s(space);
  SurfaceForms f;
  f.b = s.radius();
  const int n = space.ndof();
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < s.mass().outerSize(); ++j)
    for (SparseReal::InnerIterator it(s.mass(), j); it; ++it)
      t.emplace_back(s.dofs()[it.row()], s.dofs()[it.col()], it.value());
  f.S.resize(n, n);
  f.S.setFromTriplets(t.begin(), t.end());
  for (const auto& d : dirs) {
    const auto psi = [&](const std::array<double, 3>& x) { return d.psi(Vec3(x[0], x[1], x[2])); };
    const double mean = s.integral(psi) / s.area();
    const Eigen::VectorXd l = s.load([&](const std::array<double, 3>& x) { return psi(x) - mean; });
    Eigen::VectorXd full = Eigen::VectorXd::Zero(n);
    for (std::size_t k = 0; k < s.dofs().size(); ++k) full(s.dofs()[k]) = l(static_cast<Eigen::Index>(k));
    f.psi.push_back(full);
  }
  return f;
}

class ResponseAtSigma {
 public:
  ResponseAtSigma(const VolumeSpace& space, const std::vector<Direction>& dirs, const InteriorForms& in,
                  const std::optional<SurfaceForms>& surface, const std::vector<WallQuadraturePoint>& wall, double ekman)
      : space_(space), dirs_(dirs), in_(in), surface_(surface), wall_(wall), s_(std::sqrt(ekman)) {}

  Eigen::MatrixXcd operator()(cd sigma) const;

 private:
  Eigen::SparseMatrix<cd> stiffness(cd sigma, const Coriolis& L, const std::vector<LayerFrame>& frames) const;
  std::vector<Eigen::VectorXcd> loads(const Coriolis& L, const std::vector<LayerFrame>& frames) const;
  std::vector<Eigen::VectorXcd> solve(const Eigen::SparseMatrix<cd>& K, const std::vector<Eigen::VectorXcd>& rhs) const;
  Eigen::MatrixXcd moments(const Coriolis& L, const std::vector<LayerFrame>& frames,
                           const std::vector<Eigen::VectorXcd>& Pi) const;

  const VolumeSpace& space_;
  const std::vector<Direction>& dirs_;
  const InteriorForms& in_;
  const std::optional<SurfaceForms>& surface_;
  const std::vector<WallQuadraturePoint>& wall_;
  double s_;  // Ek^{1/2}
};

Eigen::SparseMatrix<cd> ResponseAtSigma::stiffness(cd sigma, const Coriolis& L,
                                                   const std::vector<LayerFrame>& frames) const {
  Eigen::SparseMatrix<cd> K = L.alpha * in_.Mh.cast<cd>() + L.beta * in_.G2.cast<cd>() + L.gamma * in_.Kz.cast<cd>();
  if (surface_) K -= (sigma / surface_->b) * surface_->S.cast<cd>();
  if (s_ == 0) return K;
  std::vector<Eigen::Triplet<cd>> t;
  const int npe = space_.nodes_per_element();
  std::vector<Eigen::Vector2d> g(npe);
  for (std::size_t p = 0; p < wall_.size(); ++p) {
    const auto& pt = wall_[p];
    const LayerFrame& f = frames[p];
    const auto dofs = space_.element_dofs(pt.element);
    for (int a = 0; a < npe; ++a) {
      const Eigen::Vector3cd ga = gradient_at(pt, a);
      g[a] = Eigen::Vector2d(f.tangential(ga).real());
    }
    for (int b = 0; b < npe; ++b) {
      if (dofs[b] < 0) continue;
      const Eigen::Vector2cd Dh = f.D * f.tangential(L.apply(gradient_at(pt, b)));
      for (int a = 0; a < npe; ++a)
        if (dofs[a] >= 0) t.emplace_back(dofs[a], dofs[b], -s_ * pt.w * (g[a](0) * Dh(0) + g[a](1) * Dh(1)));
    }
  }
  Eigen::SparseMatrix<cd> W(K.rows(), K.cols());
  W.setFromTriplets(t.begin(), t.end());
  return K + W;
}

std::vector<Eigen::VectorXcd> ResponseAtSigma::loads(const Coriolis& L,
                                                     const std::vector<LayerFrame>& frames) const {
  std::vector<Eigen::VectorXcd> rhs;
  const int npe = space_.nodes_per_element();
  for (std::size_t k = 0; k < dirs_.size(); ++k) {
    const auto& l = in_.load[k];
    Eigen::VectorXcd r = L.alpha * l[0].cast<cd>() - L.beta * l[1].cast<cd>() + L.gamma * l[2].cast<cd>();
    if (surface_) r -= (cd(0, 1) / surface_->b) * surface_->psi[k].cast<cd>();
    for (std::size_t p = 0; s_ > 0 && p < wall_.size(); ++p) {
      const auto& pt = wall_[p];
      const LayerFrame& f = frames[p];
      const Vec3 u = dirs_[k].u(Vec3(pt.x[0], pt.x[1], pt.x[2]));
      const Eigen::Vector2cd Du = f.D * f.tangential(L.apply(u.cast<cd>()));
      const auto dofs = space_.element_dofs(pt.element);
      for (int a = 0; a < npe; ++a)
        if (dofs[a] >= 0) {
          const Eigen::Vector2cd ga = f.tangential(gradient_at(pt, a));
          r(dofs[a]) -= s_ * pt.w * (ga(0) * Du(0) + ga(1) * Du(1));
        }
    }
    rhs.push_back(r);
  }
  return rhs;
}

// K⁻¹ b for every direction: MUMPS on the complex system (complex_lu.hpp), one factorisation.
std::vector<Eigen::VectorXcd> ResponseAtSigma::solve(const Eigen::SparseMatrix<cd>& K,
                                                     const std::vector<Eigen::VectorXcd>& rhs) const {
  const int n = static_cast<int>(K.rows());
  Triplets ar, ai, none;
  for (int j = 0; j < K.outerSize(); ++j)
    for (Eigen::SparseMatrix<cd>::InnerIterator it(K, j); it; ++it) {
      ar.add(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value().real());
      ai.add(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value().imag());
    }
  PMat block = block_operator(PETSC_COMM_SELF, n, ar, ai, none);
  ComplexLu lu(PETSC_COMM_SELF, "boundary_layer_");
  lu.factor(block);
  std::vector<PVec> b, x;
  std::vector<Vec> bv, xv;
  for (const auto& r : rhs) {
    b.push_back(block_vector(block, std::vector<cd>(r.data(), r.data() + r.size())));
    x.push_back(block_vector(block, std::vector<cd>(static_cast<std::size_t>(n))));
    bv.push_back(b.back());
    xv.push_back(x.back());
  }
  lu.solve(bv, xv);
  std::vector<Eigen::VectorXcd> out;
  for (auto& v : x) {
    const PetscScalar* a = nullptr;
    petsc_check(VecGetArrayRead(v, &a), "VecGetArrayRead");
    Eigen::VectorXcd c(n);
    for (int i = 0; i < n; ++i) c(i) = cd(a[2 * i], a[2 * i + 1]);
    petsc_check(VecRestoreArrayRead(v, &a), "VecRestoreArrayRead");
    if (!c.allFinite()) throw std::runtime_error("boundary-layer response: the solve gave no finite solution");
    out.push_back(c);
  }
  return out;
}

Eigen::MatrixXcd ResponseAtSigma::moments(const Coriolis& L, const std::vector<LayerFrame>& frames,
                                          const std::vector<Eigen::VectorXcd>& Pi) const {
  const int nd = static_cast<int>(dirs_.size()), npe = space_.nodes_per_element();
  Eigen::MatrixXcd R = L.alpha * in_.Uh.cast<cd>() + L.beta * in_.Ux.cast<cd>() + L.gamma * in_.Uz.cast<cd>();
  for (int j = 0; j < nd; ++j)
    for (int k = 0; k < nd; ++k) {
      const auto& l = in_.load[j];
      R(j, k) -= L.alpha * l[0].cast<cd>().dot(Pi[k]) + L.beta * l[1].cast<cd>().dot(Pi[k]) +
                 L.gamma * l[2].cast<cd>().dot(Pi[k]);
      if (surface_) R(j, k) -= cd(0, 1) / surface_->b * surface_->psi[j].cast<cd>().dot(Pi[k]);
    }
  for (std::size_t p = 0; s_ > 0 && p < wall_.size(); ++p) {
    const auto& pt = wall_[p];
    const LayerFrame& f = frames[p];
    const Vec3 x(pt.x[0], pt.x[1], pt.x[2]);
    const auto dofs = space_.element_dofs(pt.element);
    for (int k = 0; k < nd; ++k) {
      Eigen::Vector3cd grad = Eigen::Vector3cd::Zero();
      for (int a = 0; a < npe; ++a)
        if (dofs[a] >= 0) grad += Pi[k](dofs[a]) * gradient_at(pt, a);
      const Eigen::Vector2cd DU = f.D * f.tangential(L.apply(dirs_[k].u(x).cast<cd>() - grad));
      for (int j = 0; j < nd; ++j) {
        const Eigen::Vector2cd uj = f.tangential(dirs_[j].u(x).cast<cd>());
        R(j, k) -= s_ * pt.w * (uj(0) * DU(0) + uj(1) * DU(1));
      }
    }
  }
  return R;
}

Eigen::MatrixXcd ResponseAtSigma::operator()(cd sigma) const {
  if (std::abs(sigma) < 1e-12 || std::abs(4.0 - sigma * sigma) < 1e-12)
    throw std::runtime_error("boundary-layer response: sigma must differ from 0 and +-2 (the inertial band's ends)");
  const Coriolis L(sigma);
  std::vector<LayerFrame> frames;
  if (s_ > 0)
    for (const auto& p : wall_) frames.emplace_back(p, sigma);
  const auto Pi = solve(stiffness(sigma, L, frames), loads(L, frames));
  return moments(L, frames, Pi);
}

}  // namespace

BoundaryLayerResponse boundary_layer_response(const VolumeSpace& space, double ekman, const std::vector<cd>& sigmas,
                                              const std::function<void(std::size_t, std::size_t)>& progress) {
  if (!(ekman >= 0 && ekman < 1)) throw std::runtime_error("boundary-layer response: Ek must be in [0, 1)");
  const auto t0 = std::chrono::steady_clock::now();
  const bool fill = space.mesh().free_surface_radius > 0;
  const VolumeIntegrals liquid = integrate_volume(space);
  BoundaryLayerResponse out;
  out.origin = liquid.centroid;
  if (fill) out.origin = {space.mesh().spin_axis[0], space.mesh().spin_axis[1], liquid.centroid[2]};
  const Vec3 origin(out.origin[0], out.origin[1], out.origin[2]);
  const auto dirs = directions(origin, fill);
  const InteriorForms in = interior_forms(space, dirs);
  std::optional<SurfaceForms> surface;
  if (fill) {
    surface = surface_forms(space, dirs);
    out.surface_radius = surface->b;
  }
  const std::vector<WallQuadraturePoint> wall = wall_quadrature(space);
  out.unknowns = space.ndof();
  out.wall_points = wall.size();
  const ResponseAtSigma at(space, dirs, in, surface, wall, ekman);
  for (std::size_t i = 0; i < sigmas.size(); ++i) {
    out.R.push_back(at(sigmas[i]));
    if (progress) progress(i + 1, sigmas.size());
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace rc::modes
