#include "nonlinear_chain.hpp"

#include "rigid_body.hpp"

#include <cmath>
#include <stdexcept>

namespace rc::rom {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

Matrix3d skew(const Vector3d& v) {
  Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// Kinematics of one configuration, in space: axes, centres of mass and next joints relative to O_k, Ω, J.
struct Frames {
  std::vector<Matrix3d> R, J;
  std::vector<Vector3d> n, rho, S, Omega;
};

Frames frames(const NonlinearChain& c, const ChainState& s) {
  Frames f;
  for (auto* v : {&f.R, &f.J}) v->reserve(c.size());
  for (auto* v : {&f.n, &f.rho, &f.S, &f.Omega}) v->reserve(c.size());
  for (int k = 0; k < c.size(); ++k) {
    const ChainBody& b = c.bodies[k];
    const Matrix3d R = s.q[k].toRotationMatrix();
    f.R.push_back(R);
    f.J.push_back(R * Vector3d(b.A, b.B, b.C).asDiagonal() * R.transpose());
    f.n.push_back(R.col(2));
    f.rho.push_back(b.com * R.col(2));
    f.S.push_back(b.next_joint * R.col(2));
    f.Omega.push_back(R * s.omega[k]);
  }
  return f;
}

// Joint torques on every body (space frame): elastic bending, friction on the swing rates and on the spins.
// Each joint acts on its two bodies with opposite moments (the support takes the first one's reaction).
std::vector<Vector3d> joint_torques(const NonlinearChain& c, const Frames& f) {
  const int n = c.size();
  std::vector<Vector3d> tau(n, Vector3d::Zero());
  for (int k = 0; k < n; ++k) {
    const ChainJoint& j = c.joints[k];
    const Vector3d n_prev = k > 0 ? f.n[k - 1] : Vector3d::UnitZ();
    const Vector3d w = f.n[k].cross(f.Omega[k]).cross(f.n[k]);  // n × ṅ = the transverse part of Ω
    const Vector3d w_prev = k > 0 ? Vector3d(f.n[k - 1].cross(f.Omega[k - 1]).cross(f.n[k - 1])) : Vector3d::Zero();
    const double spin = f.Omega[k].dot(f.n[k]), spin_prev = k > 0 ? f.Omega[k - 1].dot(f.n[k - 1]) : 0.0;
    Vector3d t = j.stiffness * f.n[k].cross(n_prev)  // V = κ² (1 − n_{k−1}·n_k): turns n_k towards n_{k−1}
                 - j.friction * (w - w_prev);
    if (j.axial_friction > 0) t -= j.axial_friction * (spin - spin_prev) * (f.n[k] + n_prev).normalized();
    tau[k] += t;
    if (k > 0) tau[k - 1] -= t;
  }
  return tau;
}

// The fluid's moment on a body in its own frame, without the E_total Ṗ part (which the mass matrix carries):
// M_p − i M_q = Σ_l E_l (r − λ_l) ζ_l, r the body's spin (nonlinear_chain.hpp, ChainFluidMode).
Vector3d fluid_moment(const ChainBody& b, double spin, const std::complex<double>* zeta) {
  std::complex<double> X = 0;
  for (std::size_t l = 0; l < b.fluid.size(); ++l)
    X += mode_E(b.fluid[l].E, spin) * (spin - mode_lambda(b.fluid[l], spin)) * zeta[l];
  return {X.real(), -X.imag(), 0.0};
}

// The E_total Ṗ part of the fluid's moment, as a matrix on Ω̇ in space: M_p − i M_q = E Ṗ with E = E_r + i E_i is
// E_r (ṗ, q̇) + E_i (q̇, −ṗ) in the body frame, i.e. E_r (I − n nᵀ) Ω̇ + E_i Ω̇ × n in space.
Matrix3d fluid_inertia(const ChainBody& b, double spin, const Vector3d& n) {
  const std::complex<double> E = mode_E(b.fluid_E_total, spin);
  return E.real() * (Matrix3d::Identity() - n * n.transpose()) - E.imag() * skew(n);
}

// The external moments at time t (space frame).
void add_external_moments(const NonlinearChain& c, const Frames& f, double t, std::vector<Vector3d>& tau) {
  constexpr double two_pi = 6.283185307179586;
  for (int k = 0; k < c.size(); ++k) {
    const ChainBody& b = c.bodies[k];
    tau[k] += b.axial_moment * f.n[k] + b.space_moment + std::sin(two_pi * b.frequency * t) * b.harmonic_moment;
    if (b.static_moment != 0) tau[k] += b.static_moment * Vector3d::UnitZ().cross(f.n[k]);
    if (b.pitch_damping != 0) tau[k] -= b.pitch_damping * (f.Omega[k] - f.Omega[k].dot(f.n[k]) * f.n[k]);
    if (b.magnus != 0)
      tau[k] += b.magnus * f.Omega[k].dot(f.n[k]) * (f.n[k] - f.n[k].z() * Vector3d::UnitZ());
    // A force at the point force_at n_k: its moment about O_k, and the joints below carry it (their reactions).
    const Vector3d F = b.force(t);
    if (F.isZero()) continue;
    tau[k] += (b.force_at * f.n[k]).cross(F);
    for (int j = 0; j < k; ++j) tau[j] += f.S[j].cross(F);
  }
}

// The joints O_k in space, from O_1 up the chain.
std::vector<Vector3d> joint_points(const NonlinearChain& c, const ChainState& s, const Frames& f) {
  std::vector<Vector3d> O;
  Vector3d r = s.r1;
  for (int k = 0; k < c.size(); ++k) {
    O.push_back(r);
    r += f.S[k];
  }
  return O;
}

// The field's gradient part G x on every body (NonlinearChain::field_gradient): its moment about O_k — the force
// m G x_c at the centre, m ρ_k × G O_k, and ∫ r × G r dm = −vee(G J_k) (J_k about O_k: the second moments' isotropic
// part drops out) —, the reactions S_j × F on the bodies below; returns Σ F (the free chain's centre of mass).
Vector3d add_gradient_loads(const NonlinearChain& c, const ChainState& s, const Frames& f, std::vector<Vector3d>& tau) {
  Vector3d total = Vector3d::Zero();
  if (c.field_gradient.isZero()) return total;
  const Matrix3d& G = c.field_gradient;
  const std::vector<Vector3d> O = joint_points(c, s, f);
  for (int k = 0; k < c.size(); ++k) {
    const double m = c.bodies[k].mass;
    const Vector3d F = m * G * (O[k] + f.rho[k]);
    const Matrix3d P = G * f.J[k];
    tau[k] += m * f.rho[k].cross(G * O[k]) - Vector3d(P(2, 1) - P(1, 2), P(0, 2) - P(2, 0), P(1, 0) - P(0, 1));
    for (int j = 0; j < k; ++j) tau[j] += f.S[j].cross(F);
    total += F;
  }
  return total;
}

// Σ_k F_k(t): what the free chain's centre of mass feels besides gravity.
Vector3d total_force(const NonlinearChain& c, double t) {
  Vector3d F = Vector3d::Zero();
  for (const ChainBody& b : c.bodies) F += b.force(t);
  return F;
}

}  // namespace

int NonlinearChain::fluid_modes() const {
  int n = 0;
  for (const auto& b : bodies) n += b.modes();
  return n;
}

std::vector<Vector3d> chain_axes(const ChainState& s) {
  std::vector<Vector3d> n;
  for (const auto& q : s.q) n.push_back(q * Vector3d::UnitZ());
  return n;
}

namespace {

// Solves M x = rhs in place. M is symmetric positive definite for any attitude (a kinetic energy): Cholesky, which also
// says when it is not. A viscous tank without its static correction adds a skew part (fluid_inertia), a damped 3-D
// mode a non-symmetric share (volume_fluid.hpp): then LU.
void solve_mass_system(const NonlinearChain& c, const Eigen::MatrixXd& M, Eigen::VectorXd& rhs) {
  bool symmetric = true;
  for (const auto& b : c.bodies)
    symmetric = symmetric && b.fluid_E_total.imag() == 0 &&
                (b.volume.share - b.volume.share.transpose()).cwiseAbs().maxCoeff() == 0;
  if (symmetric) {
    thread_local Eigen::LLT<Eigen::MatrixXd> llt;
    llt.compute(M);
    if (llt.info() != Eigen::Success)
      throw std::runtime_error("nonlinear chain: the mass matrix is not positive definite (a body without inertia?)");
    llt.solveInPlace(rhs);
  } else {
    thread_local Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    lu.compute(M);
    if (!(std::abs(lu.determinant()) > 0))
      throw std::runtime_error("nonlinear chain: the mass matrix is singular (a body without inertia?)");
    rhs = lu.solve(rhs);
  }
}

// ζ̇ = i λ ζ − i Ṗ, Ṗ = ṗ − i q̇ the body-frame transverse angular acceleration, for every kept mode; then the modes of
// the tanks without axial symmetry (volume_fluid.hpp).
void add_fluid_rates(const NonlinearChain& c, const ChainState& s, const std::vector<int>& first_mode, ChainRates& out) {
  for (int k = 0; k < c.size(); ++k) {
    const ChainBody& b = c.bodies[k];
    const std::complex<double> P_dot(out.omega_dot[k].x(), -out.omega_dot[k].y());
    const double spin = s.omega[k].z();
    for (int l = 0; l < static_cast<int>(b.fluid.size()); ++l) {
      const std::complex<double> lambda = mode_lambda(b.fluid[l], spin);
      out.zeta_dot.push_back(std::complex<double>(0, 1) * (lambda * s.zeta[first_mode[k] + l] - P_dot));
    }
    volume_rates(b.volume, s.omega[k], out.omega_dot[k], s.zeta.data() + first_mode[k] + b.fluid.size(), out.zeta_dot);
  }
}

// Row k of the mass matrix: body k's moment equation about O_k on every body's Ω̇ (the bodies below it through their
// joints, its own inertia less what its fluid does not carry rigidly, those above it) and on a free chain's base.
void add_mass_row(const NonlinearChain& c, const ChainState& s, const Frames& f, const std::vector<double>& mu, int k,
                  const Vector3d& lever, Eigen::MatrixXd& M) {
  const int n = c.size();
  const double above = mu[k + 1];
  for (int i = 0; i < n; ++i) {
    Matrix3d block;
    if (i < k) block = -skew(lever) * skew(f.S[i]);
    else if (i == k)
      block = f.J[k] - above * skew(f.S[k]) * skew(f.S[k]) - fluid_inertia(c.bodies[k], s.omega[k].z(), f.n[k]);
    else block = -skew(f.S[k]) * skew(mu[i + 1] * f.S[i] + c.bodies[i].mass * f.rho[i]);
    M.block<3, 3>(3 * k, 3 * i) = block;
  }
  if (const VolumeFluid& v = c.bodies[k].volume; v.present())  // tanks without axial symmetry (volume_fluid.hpp)
    M.block<3, 3>(3 * k, 3 * k) -= f.R[k] * v.share * f.R[k].transpose();
  if (c.free_chain) {
    M.block<3, 3>(3 * k, 3 * n) = skew(lever);
    M.block<3, 3>(3 * n, 3 * k) = -skew(lever);
  }
}

}  // namespace

ChainRates chain_rates(const NonlinearChain& c, const ChainState& s) {
  const int n = c.size(), dim = 3 * n + (c.free_chain ? 3 : 0);
  const Frames f = frames(c, s);
  const Vector3d g = c.acceleration(s.t);
  std::vector<double> mu(n + 1, 0.0);  // mu[k] = Σ_{j>k} m_j
  for (int k = n - 1; k >= 0; --k) mu[k] = mu[k + 1] + c.bodies[k].mass;
  // Centripetal parts: b[k] = Σ_{i<k} Ω_i × (Ω_i × S_i) of r̈_k, d[k] = b[k] + Ω_k × (Ω_k × ρ_k) of ẍ_k.
  std::vector<Vector3d> b(n, Vector3d::Zero()), d(n);
  for (int k = 1; k < n; ++k) b[k] = b[k - 1] + f.Omega[k - 1].cross(f.Omega[k - 1].cross(f.S[k - 1]));
  for (int k = 0; k < n; ++k) d[k] = b[k] + f.Omega[k].cross(f.Omega[k].cross(f.rho[k]));
  std::vector<Vector3d> tau = joint_torques(c, f);
  add_external_moments(c, f, s.t, tau);
  const Vector3d gradient_force = add_gradient_loads(c, s, f, tau);
  std::vector<int> first_mode(n + 1, 0);  // body k's modes are zeta[first_mode[k] .. first_mode[k + 1])
  for (int k = 0; k < n; ++k) first_mode[k + 1] = first_mode[k] + c.bodies[k].modes();

  // Reused between calls (one set per thread): the stages of a run call this hundreds of thousands of times.
  thread_local Eigen::MatrixXd M;
  thread_local Eigen::VectorXd rhs;
  M.setZero(dim, dim);
  rhs.resize(dim);
  for (int k = 0; k < n; ++k) {
    const double m = c.bodies[k].mass;
    const Vector3d lever = m * f.rho[k] + mu[k + 1] * f.S[k];  // m_k ρ_k + Σ_{j>k} m_j S_k
    add_mass_row(c, s, f, mu, k, lever, M);
    const Vector3d h_liquid = c.bodies[k].liquid_momentum() * f.n[k];  // constant along the axis (ChainBody)
    Vector3d r = lever.cross(g) + tau[k] - f.Omega[k].cross(f.J[k] * f.Omega[k] + h_liquid) -
                 m * f.rho[k].cross(b[k]) +
                 f.R[k] * fluid_moment(c.bodies[k], s.omega[k].z(), s.zeta.data() + first_mode[k]);
    if (const VolumeFluid& v = c.bodies[k].volume; v.present())  // tanks without axial symmetry (volume_fluid.hpp)
      r += f.R[k] * volume_moment(v, s.omega[k], s.zeta.data() + first_mode[k] + c.bodies[k].fluid.size());
    for (int j = k + 1; j < n; ++j) r -= c.bodies[j].mass * f.S[k].cross(d[j]);
    rhs.segment<3>(3 * k) = r;
  }
  if (c.free_chain) {
    M.block<3, 3>(3 * n, 3 * n) = mu[0] * Matrix3d::Identity();
    Vector3d r = mu[0] * g + total_force(c, s.t) + gradient_force;
    for (int j = 0; j < n; ++j) r -= c.bodies[j].mass * d[j];
    rhs.segment<3>(3 * n) = r;
  }
  solve_mass_system(c, M, rhs);
  const Eigen::VectorXd& x = rhs;
  ChainRates out;
  for (int k = 0; k < n; ++k) out.omega_dot.push_back(f.R[k].transpose() * x.segment<3>(3 * k));
  if (c.free_chain) out.a1 = x.segment<3>(3 * n);
  add_fluid_rates(c, s, first_mode, out);
  return out;
}

// Positions and velocities of every centre of mass, from O_1 up the chain.
namespace {
void centres(const NonlinearChain& c, const ChainState& s, const Frames& f, std::vector<Vector3d>& x,
             std::vector<Vector3d>& v) {
  Vector3d r = s.r1, rdot = s.v1;
  for (int k = 0; k < c.size(); ++k) {
    x.push_back(r + f.rho[k]);
    v.push_back(rdot + f.Omega[k].cross(f.rho[k]));
    r += f.S[k];
    rdot += f.Omega[k].cross(f.S[k]);
  }
}
}  // namespace

double chain_energy(const NonlinearChain& c, const ChainState& s) {
  const Frames f = frames(c, s);
  std::vector<Vector3d> x, v;
  centres(c, s, f, x, v);
  double E = 0;
  for (int k = 0; k < c.size(); ++k) {
    const double m = c.bodies[k].mass;
    // About O_k: J_k holds m_k ρ_k²; the kinetic energy is ½ m |v_O|² + m v_O·(Ω × ρ) + ½ Ωᵀ J Ω.
    const Vector3d vO = v[k] - f.Omega[k].cross(f.rho[k]);
    E += 0.5 * m * vO.squaredNorm() + m * vO.dot(f.Omega[k].cross(f.rho[k])) + 0.5 * f.Omega[k].dot(f.J[k] * f.Omega[k]);
    E += 0.5 * c.bodies[k].liquid_axial * c.bodies[k].liquid_spin * c.bodies[k].liquid_spin;  // the liquid's axial spin
    E += m * c.gravity * x[k].z() - m * c.field.dot(x[k]);  // the constant field's potential (a harmonic one does work)
    E += c.bodies[k].static_moment * f.n[k].z();  // the static aerodynamic moment's potential: −n × ∂V/∂n = M_α e_z × n
    const Vector3d n_prev = k > 0 ? f.n[k - 1] : Vector3d::UnitZ();
    E += c.joints[k].stiffness * (1 - f.n[k].dot(n_prev));
  }
  if (!c.field_gradient.isZero()) {  // −½ ∫ xᵀG x dm, x = O_k + r: m O_kᵀGO_k + 2m O_kᵀGρ_k + tr(G I2), I2 = ½ tr J − J
    const Matrix3d& G = c.field_gradient;
    const std::vector<Vector3d> O = joint_points(c, s, f);
    for (int k = 0; k < c.size(); ++k) {
      const double m = c.bodies[k].mass;
      const Matrix3d I2 = 0.5 * f.J[k].trace() * Matrix3d::Identity() - f.J[k];
      E -= 0.5 * (m * O[k].dot(G * O[k]) + 2 * m * O[k].dot(G * f.rho[k]) + (G * I2).trace());
    }
  }
  return E;
}

Vector3d chain_angular_momentum(const NonlinearChain& c, const ChainState& s) {
  const Frames f = frames(c, s);
  std::vector<Vector3d> x, v;
  centres(c, s, f, x, v);
  Vector3d L = Vector3d::Zero();
  for (int k = 0; k < c.size(); ++k) {
    const double m = c.bodies[k].mass;
    // J about the centre of mass = J about O_k − m (ρ² I − ρ ρᵀ).
    const Matrix3d Jc = f.J[k] + m * skew(f.rho[k]) * skew(f.rho[k]);
    L += Jc * f.Omega[k] + m * x[k].cross(v[k]) + c.bodies[k].liquid_momentum() * f.n[k];
  }
  // The liquid's relative angular momentum of the tanks without axial symmetry (the same about any point).
  for (int k = 0, first = 0; k < c.size(); first += c.bodies[k].modes(), ++k) {
    const ChainBody& b = c.bodies[k];
    if (b.volume.present())
      L += f.R[k] * volume_momentum(b.volume, s.omega[k], s.zeta.data() + first + b.fluid.size());
  }
  return L;
}

bool nonconservative(const NonlinearChain& c) {
  for (const ChainJoint& j : c.joints)
    if (j.friction != 0 || j.axial_friction != 0) return true;
  for (const ChainBody& b : c.bodies)
    if (b.loaded()) return true;
  return c.field_frequency > 0 && !c.field_harmonic.isZero();
}

bool external_loads(const NonlinearChain& c) {
  for (const ChainBody& b : c.bodies)
    if (b.loaded() || b.static_moment != 0) return true;
  return c.field.x() != 0 || c.field.y() != 0 || (c.field_frequency > 0 && !c.field_harmonic.isZero()) ||
         !c.field_gradient.isZero();
}

double nonconservative_power(const NonlinearChain& c, const ChainState& s) {
  // The moments the equations of motion take (add_external_moments, joint_torques), without what has a potential in
  // chain_energy: the joints' elastic moments and the static aerodynamic moment. A force's moment about O_k and its
  // reactions S_j × F below make Σ τ_k·Ω_k its power relative to O_1; the free chain's O_1 moves with v1.
  NonlinearChain loads = c;
  for (ChainJoint& j : loads.joints) j.stiffness = 0;
  for (ChainBody& b : loads.bodies) b.static_moment = 0;
  const Frames f = frames(loads, s);
  std::vector<Vector3d> tau = joint_torques(loads, f);
  add_external_moments(loads, f, s.t, tau);
  double P = 0;
  for (int k = 0; k < c.size(); ++k) P += tau[k].dot(f.Omega[k]);
  if (c.free_chain) P += total_force(c, s.t).dot(s.v1);
  const Vector3d harmonic = std::sin(6.283185307179586 * c.field_frequency * s.t) * c.field_harmonic;
  if (!harmonic.isZero()) {
    std::vector<Vector3d> x, v;
    centres(c, s, f, x, v);
    for (int k = 0; k < c.size(); ++k) P += c.bodies[k].mass * harmonic.dot(v[k]);
  }
  return P;
}

namespace {

using Vs = std::vector<Vector3d>;

// The vector-space part of the state (ω, O_1, its velocity, the fluid), advanced by classical RK4 in chain_step; the
// attitudes by rotation vectors θ (RKMK4).
struct Flat {
  Vs omega;
  Vector3d r, v;
  std::vector<std::complex<double>> zeta;
};
struct Stage {
  Vs dtheta;
  Flat d;
};

Flat axpy(const Flat& x, const Flat& dx, double w) {
  Flat y = x;
  for (std::size_t k = 0; k < y.omega.size(); ++k) y.omega[k] += w * dx.omega[k];
  y.r += w * dx.r;
  y.v += w * dx.v;
  for (std::size_t l = 0; l < y.zeta.size(); ++l) y.zeta[l] += w * dx.zeta[l];
  return y;
}

Vs turn(const Vs& a, const Vs& b, double w) {
  Vs out(a);
  for (std::size_t k = 0; k < out.size(); ++k) out[k] += w * b[k];
  return out;
}

}  // namespace

ChainState chain_step(const NonlinearChain& c, const ChainState& s, double h) {
  const int n = c.size();
  const auto stage = [&](double t, const Vs& theta, const Flat& y) {
    ChainState x;
    x.t = t;
    x.r1 = y.r;
    x.v1 = y.v;
    x.omega = y.omega;
    x.zeta = y.zeta;
    Stage st;
    for (int k = 0; k < n; ++k) {
      x.q.push_back(rotated(s.q[k], theta[k]));
      st.dtheta.push_back(dexpinv(theta[k], y.omega[k]));
    }
    ChainRates r = chain_rates(c, x);
    st.d = {std::move(r.omega_dot), y.v, r.a1, std::move(r.zeta_dot)};
    return st;
  };
  const Vs zero(n, Vector3d::Zero());
  const Flat y0{s.omega, s.r1, s.v1, s.zeta};
  const Stage k1 = stage(s.t, zero, y0);
  const Stage k2 = stage(s.t + h / 2, turn(zero, k1.dtheta, h / 2), axpy(y0, k1.d, h / 2));
  const Stage k3 = stage(s.t + h / 2, turn(zero, k2.dtheta, h / 2), axpy(y0, k2.d, h / 2));
  const Stage k4 = stage(s.t + h, turn(zero, k3.dtheta, h), axpy(y0, k3.d, h));
  Flat y = axpy(axpy(axpy(axpy(y0, k1.d, h / 6), k2.d, h / 3), k3.d, h / 3), k4.d, h / 6);
  ChainState next;
  next.t = s.t + h;
  for (int k = 0; k < n; ++k)
    next.q.push_back(rotated(s.q[k], h / 6 * (k1.dtheta[k] + 2 * k2.dtheta[k] + 2 * k3.dtheta[k] + k4.dtheta[k])));
  next.omega = std::move(y.omega);
  next.r1 = y.r;
  next.v1 = y.v;
  next.zeta = std::move(y.zeta);
  return next;
}

namespace {

// dexp⁻¹ to fourth order in θ for RKMK of order 5: ω + ½ θ × ω + (1/12) θ × (θ × ω) − (1/720) θ × (θ × (θ × (θ × ω)))
// (the Bernoulli numbers B2 = 1/6, B4 = −1/30 over k!; the sign of the odd term as in rigid_body.cpp's dexpinv).
Vector3d dexpinv5(const Vector3d& theta, const Vector3d& omega) {
  const Vector3d t1 = theta.cross(omega), t2 = theta.cross(t1), t4 = theta.cross(theta.cross(t2));
  return omega + 0.5 * t1 + t2 / 12.0 - t4 / 720.0;
}

// Dormand–Prince 5(4) tableau.
constexpr double kC[7] = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};
constexpr double kA[7][6] = {{0, 0, 0, 0, 0, 0},
                             {1.0 / 5, 0, 0, 0, 0, 0},
                             {3.0 / 40, 9.0 / 40, 0, 0, 0, 0},
                             {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0},
                             {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0},
                             {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0},
                             {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
constexpr double kB4[7] = {5179.0 / 57600, 0, 7571.0 / 16695, 393.0 / 640, -92097.0 / 339200, 187.0 / 2100, 1.0 / 40};

}  // namespace

namespace {

// One Dormand-Prince stage's derivatives: θ̇ (dexp⁻¹), ω̇, ζ̇, ṙ_1, v̇_1.
struct StageRates {
  std::vector<Vector3d> dtheta, domega;
  std::vector<std::complex<double>> dzeta;
  Vector3d dr, dv;
};

// The state of stage i: s advanced by h Σ_{j<i} a_ij k_j (attitudes on the group by their θ).
void stage_state(const ChainState& s, const std::vector<StageRates>& k, int i, double h, ChainState& x) {
  x.t = s.t + kC[i] * h;
  x.r1 = s.r1;
  x.v1 = s.v1;
  for (int j = 0; j < i; ++j) {
    x.r1 += h * kA[i][j] * k[j].dr;
    x.v1 += h * kA[i][j] * k[j].dv;
  }
  for (std::size_t b = 0; b < s.q.size(); ++b) {
    Vector3d theta = Vector3d::Zero(), omega = s.omega[b];
    for (int j = 0; j < i; ++j) {
      theta += h * kA[i][j] * k[j].dtheta[b];
      omega += h * kA[i][j] * k[j].domega[b];
    }
    x.q[b] = rotated(s.q[b], theta);
    x.omega[b] = omega;
  }
  for (std::size_t l = 0; l < s.zeta.size(); ++l) {
    std::complex<double> z = s.zeta[l];
    for (int j = 0; j < i; ++j) z += h * kA[i][j] * k[j].dzeta[l];
    x.zeta[l] = z;
  }
}

// The embedded order-4 solution's distance from the order-5 one: attitudes, rates and (into the rate error) the
// fluid's amplitudes.
void step_errors(const std::vector<StageRates>& k, int n, std::size_t nz, double h, ChainStepDP& out) {
  for (int b = 0; b < n; ++b) {
    Vector3d dtheta = Vector3d::Zero(), domega = Vector3d::Zero();
    for (int j = 0; j < 7; ++j) {
      const double e = (j < 6 ? kA[6][j] : 0.0) - kB4[j];
      dtheta += h * e * k[j].dtheta[b];
      domega += h * e * k[j].domega[b];
    }
    out.attitude_error = std::max(out.attitude_error, dtheta.norm());
    out.rate_error = std::max(out.rate_error, domega.norm());
  }
  double zeta_error2 = 0;
  for (std::size_t l = 0; l < nz; ++l) {
    std::complex<double> dz = 0;
    for (int j = 0; j < 7; ++j) dz += h * ((j < 6 ? kA[6][j] : 0.0) - kB4[j]) * k[j].dzeta[l];
    zeta_error2 = std::max(zeta_error2, std::norm(dz));
  }
  out.rate_error = std::max(out.rate_error, std::sqrt(zeta_error2));
}

}  // namespace

ChainStepDP chain_step_dp(const NonlinearChain& c, const ChainState& s, const ChainRates& rates0, double h) {
  const int n = c.size();
  std::vector<StageRates> k(7);
  ChainState x = s;
  ChainRates r = rates0;
  for (int i = 0; i < 7; ++i) {
    if (i > 0) {
      stage_state(s, k, i, h, x);
      r = chain_rates(c, x);
    }
    // θ of this stage, for dexp⁻¹.
    StageRates& ki = k[i];
    for (int b = 0; b < n; ++b) {
      Vector3d theta = Vector3d::Zero();
      for (int j = 0; j < i; ++j) theta += h * kA[i][j] * k[j].dtheta[b];
      ki.dtheta.push_back(dexpinv5(theta, x.omega[b]));
    }
    ki.domega = r.omega_dot;
    ki.dzeta = r.zeta_dot;
    ki.dr = x.v1;
    ki.dv = r.a1;
  }
  ChainStepDP out;
  out.next = x;  // stage 7 is the order-5 solution (its row of A is b)
  out.next.t = s.t + h;
  out.next_rates = r;
  step_errors(k, n, s.zeta.size(), h, out);
  return out;
}

}  // namespace rc::rom
