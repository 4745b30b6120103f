#include "rigid_body.hpp"

#include <cmath>

namespace rc::rom {

// The attitude rotated in the body frame by the rotation vector θ: q ⊗ exp(θ/2).
Eigen::Quaterniond rotated(const Eigen::Quaterniond& q, const Eigen::Vector3d& theta) {
  const double angle = theta.norm();
  if (angle == 0) return q;
  return (q * Eigen::Quaterniond(Eigen::AngleAxisd(angle, theta / angle))).normalized();
}

// dexp⁻¹ to the order RKMK4 needs, for the body-frame (right) form q = q0 ⊗ exp(θ/2), q̇ = ½ q ⊗ ω:
// θ̇ = dexp⁻¹_{−θ}(ω) = ω + ½ θ × ω + (1/12) θ × (θ × ω). (With the other sign the method falls to order 2: measured.)
Eigen::Vector3d dexpinv(const Eigen::Vector3d& theta, const Eigen::Vector3d& omega) {
  return omega + 0.5 * theta.cross(omega) + theta.cross(theta.cross(omega)) / 12.0;
}

Eigen::Vector3d angular_acceleration(const RigidBody& b, const RigidState& s) {
  const Eigen::Vector3d I_omega = b.inertia.cwiseProduct(s.omega);
  const Eigen::Vector3d g_body = s.q.conjugate() * Eigen::Vector3d(0, 0, -b.gravity);
  const Eigen::Vector3d torque = b.mass * b.com.cross(g_body);
  return (I_omega.cross(s.omega) + torque).cwiseQuotient(b.inertia);
}

double energy(const RigidBody& b, const RigidState& s) {
  const double kinetic = 0.5 * s.omega.dot(b.inertia.cwiseProduct(s.omega));
  return kinetic + b.mass * b.gravity * (s.q * b.com).z();
}

Eigen::Vector3d angular_momentum(const RigidBody& b, const RigidState& s) {
  return s.q * b.inertia.cwiseProduct(s.omega);
}

RigidState rkmk4_step(const RigidBody& b, const RigidState& s, double h) {
  // Stages of classical RK4 on (θ, ω) with θ(0) = 0, the attitude at each stage q ⊗ exp(θ_stage/2).
  const auto stage = [&](const Eigen::Vector3d& theta, const Eigen::Vector3d& omega, Eigen::Vector3d& dtheta) {
    RigidState x{rotated(s.q, theta), omega};
    dtheta = dexpinv(theta, omega);
    return angular_acceleration(b, x);
  };
  Eigen::Vector3d t1, t2, t3, t4;
  const Eigen::Vector3d w1 = stage(Eigen::Vector3d::Zero(), s.omega, t1);
  const Eigen::Vector3d w2 = stage(0.5 * h * t1, s.omega + 0.5 * h * w1, t2);
  const Eigen::Vector3d w3 = stage(0.5 * h * t2, s.omega + 0.5 * h * w2, t3);
  const Eigen::Vector3d w4 = stage(h * t3, s.omega + h * w3, t4);
  RigidState next;
  next.q = rotated(s.q, h / 6 * (t1 + 2 * t2 + 2 * t3 + t4));
  next.omega = s.omega + h / 6 * (w1 + 2 * w2 + 2 * w3 + w4);
  return next;
}

}  // namespace rc::rom
