// The nonlinear motion of one rigid body about a fixed point O under gravity: the first brick of the nonlinear chain
// (Kononov (1999) (1)-(11) for one body without fluid; docs/rom.md, "Nonlinear chain"). Euler's equations in the
// body frame,
//   I ω̇ = (I ω) × ω + m c × (Rᵀ g),      g = (0, 0, −gravity) in space,
// with I = diag(A, B, C) the principal moments about O, c the centre of mass in the body frame, and the attitude
// R(q) (body → space) a unit quaternion, q̇ = ½ q ⊗ (0, ω): no Euler-angle singularity at any angle.
//
// Integrator: a Lie-group (Munthe-Kaas) Runge–Kutta of order 4 (RKMK4). The stages advance the attitude by the
// exponential of a body-frame rotation vector, q ← q ⊗ exp(θ/2), so q stays a unit quaternion to rounding
// whatever the step; θ solves the dexp equation θ̇ = ω + ½ θ × ω + (1/12) θ × (θ × ω) truncated at order 4.
// Energy and the angular momentum about the vertical are conserved by the equations; the integrator keeps them to
// its order (tests/rom/test_rigid_body.cpp).
#pragma once

#include "eigen_dense.hpp"
#include <Eigen/Geometry>

namespace rc::rom {

struct RigidBody {
  Eigen::Vector3d inertia = Eigen::Vector3d::Ones();  // A, B, C about O (kg m²), principal body axes
  Eigen::Vector3d com = Eigen::Vector3d::Zero();      // O → centre of mass in the body frame (m)
  double mass = 0;                                    // kg
  double gravity = 0;                                 // m/s², along −z of space
};

struct RigidState {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();  // attitude: body → space
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();        // angular velocity in the body frame (rad/s)
};

// ω̇ from Euler's equations with the gravity moment.
Eigen::Vector3d angular_acceleration(const RigidBody& body, const RigidState& state);

// Kinetic plus potential energy (J): ½ ωᵀ I ω + m gravity (R c)_z.
double energy(const RigidBody& body, const RigidState& state);

// Angular momentum about O in the space frame (kg m²/s): R I ω.
Eigen::Vector3d angular_momentum(const RigidBody& body, const RigidState& state);

// One RKMK4 step of length h.
RigidState rkmk4_step(const RigidBody& body, const RigidState& state, double h);

// The two pieces of RKMK4 on the rotation group that the chain's integrator shares (nonlinear_chain.cpp):
// the attitude turned in the body frame by the rotation vector θ, q ⊗ exp(θ/2), renormalised;
Eigen::Quaterniond rotated(const Eigen::Quaterniond& q, const Eigen::Vector3d& theta);
// and dexp⁻¹ to the order RKMK4 needs for that (right) form: θ̇ = ω + ½ θ × ω + (1/12) θ × (θ × ω).
Eigen::Vector3d dexpinv(const Eigen::Vector3d& theta, const Eigen::Vector3d& omega);

}  // namespace rc::rom
