#include "free_recoil.hpp"

#include "base_translation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rc::rom {
namespace {

const Eigen::Matrix2d kQuarterTurn = (Eigen::Matrix2d() << 0, -1, 1, 0).finished();  // e_z × in F's plane

// The tanks that recoil: their horizontal place and mass, to test the layout's symmetry.
struct RecoilTank {
  Eigen::Vector2d at;
  double mass, scale;
};

std::vector<RecoilTank> recoil_tanks(const std::vector<GeneralBody>& bodies) {
  std::vector<RecoilTank> out;
  for (const GeneralBody& b : bodies)
    for (const GeneralTank& t : b.tanks)
      if (t.recoil) out.push_back({t.centroid.head<2>(), t.mass, t.scale});
  return out;
}

// True when turning the tanks by `angle` about the spin axis maps each onto one of equal mass, to `tol` (m).
bool maps_onto_itself(const std::vector<RecoilTank>& tanks, double angle, double tol) {
  const Eigen::Rotation2Dd turn(angle);
  for (const RecoilTank& a : tanks) {
    const Eigen::Vector2d image = turn * a.at;
    const bool found = std::any_of(tanks.begin(), tanks.end(), [&](const RecoilTank& b) {
      return (b.at - image).norm() <= tol && std::abs(b.mass - a.mass) <= 1e-3 * a.mass;
    });
    if (!found) return false;
  }
  return true;
}

}  // namespace

void require_symmetric_layout(const Scene& scene, const std::vector<GeneralBody>& bodies) {
  const std::vector<RecoilTank> tanks = recoil_tanks(bodies);
  // A meshed liquid's centroid errs by ~1e-6 of its tank (docs/volume.md §8): places compared to 1e-3 of the tank.
  double tol = 0;
  for (const RecoilTank& t : tanks) tol = std::max(tol, 1e-3 * t.scale);
  for (std::size_t N = 2; N <= std::max<std::size_t>(tanks.size(), 2); ++N)
    if (maps_onto_itself(tanks, 2 * M_PI / static_cast<double>(N), tol)) return;
  fail(scene, "body[1].cavity", "a free chain's partially filled tanks off the axis must sit in a layout that a turn "
                                "about the spin axis maps onto itself (two equal tanks opposite, three at 120 degrees, "
                                "four at 90): the liquid's axial recoil, which such a layout decouples from the tilts, "
                                "is not modelled; on a fixed chain any balanced layout is taken (docs/volume.md "
                                "section 8, \"The free chain\")");
}

namespace {

// The tanks' surface forms over the base's τ, in the extended chain's velocities (3 per body, the base's last): the
// blocks against the base only (the bodies' own blocks are in their inertia already).
Eigen::MatrixXd base_surface_form(const std::vector<GeneralBody>& bodies, int n_ext) {
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(3 * n_ext, 3 * n_ext);
  const int b = 3 * (n_ext - 1);
  for (int k = 0; k < static_cast<int>(bodies.size()); ++k)
    for (const GeneralTank& t : bodies[k].tanks) {
      if (!t.recoil) continue;
      S.block<3, 2>(3 * k, b) += t.surface_form.topRightCorner<3, 2>();
      S.block<2, 3>(b, 3 * k) += t.surface_form.bottomLeftCorner<2, 3>();
      S.block<2, 2>(b, b) += t.surface_form.bottomRightCorner<2, 2>();
    }
  return S;
}

// A kinetic form ½ wᵀ S w over the velocities w = P Q̇ + R Q (general_system.hpp's maps) adds, by Lagrange's equations,
// PᵀSP Q̈ + (PᵀSR − RᵀSP) Q̇ − RᵀSR Q (for a tilt's P = J, R = −ω0: (26)'s M, −2ω0 M's gyroscopic block, −ω0² M).
void add_kinetic_form(const Eigen::MatrixXd& S, GeneralChain& e) {
  const FluidMaps f = fluid_maps(e);
  const Eigen::MatrixXd &P = f.P, &R = f.R;
  e.M += P.transpose() * S * P;
  e.C += P.transpose() * S * R - R.transpose() * S * P;
  e.K -= R.transpose() * S * R;
}

}  // namespace

GeneralChain extend_with_recoil(const Scene& scene, const GeneralChain& g, const ChainModel& cm,
                                const std::vector<GeneralBody>& bodies) {
  require_symmetric_layout(scene, bodies);
  const int n = g.n;
  double mass = 0;
  for (const GeneralBody& b : bodies) mass += b.mass;
  // (26)'s extended chain (base_translation.hpp): the fixed chain's inertia (a free chain's is M − a aᵀ/m), a, m.
  const Eigen::MatrixXd M_fixed = cm.M + cm.a * cm.a.transpose() / mass;
  const ChainModel cm_ext = extend_with_base(cm, M_fixed, cm.a, mass);
  GeneralChain e;
  e.n = n + 1;
  e.base = true;
  e.spin = g.spin;
  e.spins = Eigen::VectorXd::Zero(n + 1);
  e.spins.head(n) = g.spins;
  e.axial = g.axial;
  e.free_chain = true;
  e.modes = g.modes;
  e.dissipative = g.dissipative;
  e.axial_inertia = g.axial_inertia;
  std::vector<Eigen::Matrix3d> inertia;
  for (const GeneralBody& b : bodies) inertia.push_back(b.inertia);
  set_turning_frame_matrices(cm_ext, cm, inertia, e);
  const Eigen::MatrixXd S = base_surface_form(bodies, n + 1);
  e.geostrophic = g.geostrophic;
  e.geostrophic.push_back(Eigen::Matrix3d::Zero());
  e.base_geostrophic = Eigen::MatrixXd::Zero(3, 3 * n);
  for (int k = 0; k < n; ++k)
    for (const GeneralTank& t : bodies[k].tanks) {
      if (!t.recoil) continue;
      e.base_geostrophic.block<2, 3>(0, 3 * k) += t.geostrophic_form.bottomLeftCorner<2, 3>();
      e.geostrophic[n].topLeftCorner<2, 2>() += t.geostrophic_form.bottomRightCorner<2, 2>();
    }
  add_kinetic_form(S, e);
  // The base's rows of the whole kinetic form: the rigid chain's (each body's first moment a_k on its tilt, the total
  // mass on X: the extended M's X row, isotropic in F) and the tanks' surface parts.
  e.base_form = Eigen::MatrixXd::Zero(3, 3 * (n + 1));
  for (int k = 0; k <= n; ++k) e.base_form.block<2, 2>(0, 3 * k) = cm_ext.M(n, k) * Eigen::Matrix2d::Identity();
  e.base_form += S.middleRows(3 * n, 3);
  return e;
}

Eigen::MatrixXd base_momentum(const GeneralChain& e, double s) {
  const FluidMaps f = fluid_maps(e);
  const int n = e.n, nq = 2 * n, d = e.dim_q(), nz = 2 * e.n_modes();
  // π = (S − G) w + h_X over the base's rows, w = P Q̇ + R Q, h_X = W Z (the modes' share; G the liquid at rest).
  const Eigen::MatrixXd S = (e.base_form - f.G.middleRows(3 * (n - 1), 3)).topRows(2);
  Eigen::MatrixXd L(2, nq + d + nz);
  L.leftCols(nq) = S * f.R.leftCols(nq) / s;
  L.middleCols(nq, d) = S * f.P;
  L.rightCols(nz) = f.W.middleRows(3 * (n - 1), 2);
  return L;
}

GeneralSystem reduce_on_recoil(const GeneralChain& g, const GeneralChain& e, const GeneralSystem& ext) {
  const int n = g.n, nq = 2 * n, d = g.dim_q(), nz = 2 * g.n_modes(), dim = nq + d + nz;
  const int nqe = nq + 2, de = e.dim_q(), sX = nq, Xdot = nqe + nq;
  const double w = g.spin, s = ext.s;
  // The reduced state's place in the extended one: s q, then q̇ and ψ̇ around Ẋ, then Z.
  std::vector<int> kept(dim);
  for (int i = 0; i < nq; ++i) kept[i] = i;
  for (int i = 0; i < d; ++i) kept[nq + i] = nqe + (i < nq ? i : i + 2);
  for (int i = 0; i < nz; ++i) kept[nq + d + i] = nqe + de + i;
  // π = 0 with X = 0 gives Ẋ (X enters only through τ = J Ẋ − ω0 X, so any X with its Ẋ gives the same motion).
  const Eigen::MatrixXd L = base_momentum(e, s);
  Eigen::MatrixXd Lr(2, dim);
  for (int j = 0; j < dim; ++j) Lr.col(j) = L.col(kept[j]);
  const Eigen::MatrixXd Xdot_of = -L.middleCols(Xdot, 2).fullPivLu().solve(Lr);
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(nqe + de + nz, dim);
  for (int j = 0; j < dim; ++j) T(kept[j], j) = 1;
  T.middleRows(Xdot, 2) = Xdot_of;
  GeneralSystem sys;
  sys.s = s;
  Eigen::MatrixXd Bk(dim, ext.B.cols());
  for (int i = 0; i < dim; ++i) Bk.row(i) = ext.B.row(kept[i]);
  sys.B = Bk * T;
  sys.input.resize(dim, d);
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < d; ++j) sys.input(i, j) = ext.input(kept[i], j < nq ? j : j + 2);
  // The two properties the reduction rests on, measured: the kept rows see X only through τ (their s X columns are
  // ω0 times their Ẋ columns turned by J), and π̇ = −ω0 J π along the extended motion.
  const Eigen::MatrixXd on_X = Bk.middleCols(sX, 2) * s, through_tau = w * Bk.middleCols(Xdot, 2) * kQuarterTurn;
  const double invariance = (on_X - through_tau).norm() / std::max(on_X.norm() + through_tau.norm(), 1e-300);
  const Eigen::MatrixXd LB = L * ext.B, rotation = -w * kQuarterTurn * L;
  const double conserved = (LB - rotation).norm() / std::max(LB.norm() + rotation.norm(), 1e-300);
  sys.recoil_residual = std::max(invariance, conserved);
  return sys;
}

}  // namespace rc::rom
