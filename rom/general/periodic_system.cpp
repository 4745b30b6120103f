#include "periodic_system.hpp"

#include "general_system.hpp"

#include <cmath>

namespace rc::rom {
namespace {

Eigen::Matrix2d plane_turn(double theta) { return Eigen::Rotation2Dd(theta).toRotationMatrix(); }

Eigen::Matrix3d vertical_turn(double theta) {
  return Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

const Eigen::Matrix2d kJ = (Eigen::Matrix2d() << 0, -1, 1, 0).finished();  // e_z × on a transverse vector

}  // namespace

GeneralChain turned_chain(const GeneralChain& g, double t) {
  GeneralChain out = g;
  out.period = 0;  // a snapshot: constant
  for (int k = 0; k < g.n; ++k) {
    const double theta = (g.spins[k] - g.spin) * t;
    if (theta == 0) continue;
    const Eigen::Matrix2d R = plane_turn(theta);
    const Eigen::Matrix3d R3 = vertical_turn(theta);
    const Eigen::Matrix2d delta = R * g.anisotropy[k] * R.transpose();
    // M holds −Δ_k and K −ω0²Δ_k (general_chain.hpp): replace Δ_k by its turned self.
    out.M.block<2, 2>(2 * k, 2 * k) += g.anisotropy[k] - delta;
    out.K.block<2, 2>(2 * k, 2 * k) += g.spin * g.spin * (g.anisotropy[k] - delta);
    out.anisotropy[k] = delta;
    out.geostrophic[k] = R3 * g.geostrophic[k] * R3.transpose();
  }
  for (GeneralMode& m : out.modes) {
    const double theta = (g.spins[m.body] - g.spin) * t;
    if (theta == 0) continue;
    const Eigen::Matrix3cd R3 = vertical_turn(theta).cast<std::complex<double>>();
    m.c = R3 * m.c;
    m.c_left = R3 * m.c_left;
  }
  return out;
}

GeneralSystem periodic_system(const GeneralChain& g, double t, double s) {
  const GeneralChain gt = turned_chain(g, t);
  const GeneralSystem frozen = build_general_system(gt, s);
  const FluidMaps f = fluid_maps(gt);
  const int n = g.n, nq = 2 * n, d = g.dim_q(), nz = 2 * g.n_modes(), dim = nq + d + nz;
  // θ̇ J per body on its 3-vectors, and δω = P Q̇ + R Q as a map from the state (q carried as s q).
  Eigen::MatrixXd TJ = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int k = 0; k < n; ++k) TJ.block<2, 2>(3 * k, 3 * k) = (g.spins[k] - g.spin) * kJ;
  Eigen::MatrixXd dw = Eigen::MatrixXd::Zero(3 * n, dim);
  dw.leftCols(nq) = f.R.leftCols(nq) / s;
  dw.middleCols(nq, d) = f.P;
  // The turning's terms of the q-equations (periodic_system.hpp), moved to the right-hand side as a generalised force.
  Eigen::MatrixXd force = Eigen::MatrixXd::Zero(d, dim);
  for (int k = 0; k < n; ++k) {
    const double rate = g.spins[k] - g.spin;
    force.block(2 * k, nq + 2 * k, 2, 2) += 2 * rate * kJ * gt.anisotropy[k];
    force.block(2 * k, 2 * k, 2, 2) += 2 * g.spin * rate * gt.anisotropy[k] / s;
  }
  const Eigen::MatrixXd Pt = f.P.transpose();
  force.rightCols(nz) -= Pt * TJ * f.W;
  force -= Pt * (f.W * f.Chat * TJ - (TJ * f.G - f.G * TJ)) * dw;
  GeneralSystem out;
  out.s = s;
  out.B = frozen.B + frozen.input * force;
  out.B.bottomRows(nz) += f.Chat * TJ * dw;
  if (!out.B.allFinite())
    throw std::runtime_error("the periodic chain's first-order matrix is not finite at t = " + std::to_string(t) + " s");
  out.input = frozen.input;  // an external moment is not turned: it acts on Q in F's axes
  return out;
}

Eigen::MatrixXd periodic_matrix(const GeneralChain& g, double t, double s) { return periodic_system(g, t, s).B; }

}  // namespace rc::rom
