#include "forced_solution.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rc::rom {

using cd = std::complex<double>;

namespace {

// F = M_y + i M_x of a moment vector (space frame).
cd complex_moment(const std::array<double, 3>& v) { return {v[1], v[0]}; }

// The first-order forcing (0, M_eff⁻¹ F, 0) of a moment vector over the bodies (balanced state: the u̇ block).
Eigen::VectorXcd forcing(const ChainModel& m, const FirstOrderSystem& f, const Eigen::VectorXcd& F) {
  // A free chain with a partially filled tank: the extended chain's ü (no moment acts on its base's translation).
  const ChainModel& e = m.extended ? *m.extended : m;
  const Eigen::MatrixXcd Meff = e.M_eff.cast<cd>() + cd(0, 1) * e.M_eff_imag.cast<cd>();
  Eigen::VectorXcd Fe = Eigen::VectorXcd::Zero(e.n);
  Fe.head(m.n) = F;
  Eigen::VectorXcd y = Eigen::VectorXcd::Zero(f.dim());
  y.segment(m.n, m.n) = Meff.partialPivLu().solve(Fe).head(m.n);
  return y;
}

// (iΩ − B)⁻¹ rhs, refused where the matrix is singular to working precision (an unbounded response).
Eigen::VectorXcd resolvent(const FirstOrderSystem& f, double omega, const Eigen::VectorXcd& rhs, const std::string& what) {
  const Eigen::MatrixXcd A = cd(0, omega) * Eigen::MatrixXcd::Identity(f.dim(), f.dim()) - f.B;
  const Eigen::FullPivLU<Eigen::MatrixXcd> lu(A);
  const double scale = std::max(A.cwiseAbs().maxCoeff(), 1e-300);
  const double smallest = lu.matrixLU().diagonal().cwiseAbs().minCoeff();
  if (!(smallest > 1e-13 * scale))
    throw std::runtime_error(what + ": the chain answers it without bound (a root at its frequency, sigma = " +
                             std::to_string(omega) + " rad/s: a resonance of an undamped chain, or a constant moment "
                             "with no restoring torque to hold it); the linear model's forced motion has no closed "
                             "form there");
  return lu.solve(rhs);
}

}  // namespace

Eigen::VectorXcd ForcedSolution::moments_at(double t) const {
  Eigen::VectorXcd F = moments;
  for (const auto& [omega, amplitude] : moment_harmonics) F += std::sin(omega * t) * amplitude;
  return F;
}

Eigen::VectorXcd ForcedSolution::at(double t) const {
  Eigen::VectorXcd y = constant;
  for (const Harmonic& h : harmonics) y += h.plus * std::exp(cd(0, h.omega * t)) + h.minus * std::exp(cd(0, -h.omega * t));
  return y;
}

namespace {

// A transverse force f (space frame) on body k at `at` along its axis, as the moments it puts on the tilts: ℓ e_z × f
// with ℓ = at on body k and s_j on each body j below it (its joint carries the force), M_y + i M_x = ℓ (f_x − i f_y).
void add_force_moments(const Scene& scene, std::size_t k, const std::array<double, 3>& f, double at,
                       Eigen::VectorXcd& F) {
  const cd transverse(f[0], -f[1]);
  F[static_cast<Eigen::Index>(k)] += at * transverse;
  for (std::size_t j = 0; j < k; ++j) F[static_cast<Eigen::Index>(j)] += scene.bodies[j].next_joint * transverse;
}

}  // namespace

namespace {
// A uniform transverse field f (m/s²) on a fixed chain: every mass m at its lever, Σ = a_k (f_x − i f_y) on tilt k
// (Kononov's a_k, the fluid's mass included: a filled cavity's liquid feels a uniform field as a gradient only).
Eigen::VectorXcd field_moments(const ChainModel& m, const std::array<double, 3>& f) {
  return m.a.cast<cd>() * cd(f[0], -f[1]);
}
}  // namespace

Eigen::VectorXcd constant_moments(const Scene& scene) {
  Eigen::VectorXcd F = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(scene.size()));
  for (std::size_t k = 0; k < scene.size(); ++k) {
    if (scene.bodies[k].moment) F[static_cast<Eigen::Index>(k)] = complex_moment(scene.bodies[k].moment->space);
    if (scene.bodies[k].force) add_force_moments(scene, k, scene.bodies[k].force->space, scene.bodies[k].force->at, F);
  }
  return F;
}

namespace {

// The particular solution of the moments F sin(2π frequency t) on the tilts, added to s (nothing when F is 0).
void add_harmonic(const ChainModel& m, const FirstOrderSystem& f, const Eigen::VectorXcd& F, double frequency,
                  const std::string& what, ForcedSolution& s) {
  if (F.cwiseAbs().maxCoeff() == 0) return;
  s.present = true;
  const Eigen::VectorXcd fh = forcing(m, f, F) / cd(0, 2);
  const double omega = 2 * std::numbers::pi * frequency;
  s.harmonics.push_back({omega, resolvent(f, omega, fh, what), resolvent(f, -omega, -fh, what)});
  s.moment_harmonics.emplace_back(omega, F);
}

}  // namespace

ForcedSolution forced_solution(const ChainModel& m, const FirstOrderSystem& f, const Scene& scene) {
  ForcedSolution s;
  s.constant = Eigen::VectorXcd::Zero(f.dim());
  Eigen::VectorXcd Fc = constant_moments(scene);
  if (scene.field && !scene.free_chain) Fc += field_moments(m, scene.field->space);
  s.moments = Fc;
  if (Fc.cwiseAbs().maxCoeff() > 0) {
    s.present = true;
    s.constant = resolvent(f, 0.0, forcing(m, f, Fc), "a constant moment or force (body.moment.space, body.force.space)");  // (0 − B) y_c = f_c
  }
  if (scene.field && !scene.free_chain && scene.field->frequency > 0)
    add_harmonic(m, f, field_moments(m, scene.field->harmonic), scene.field->frequency, "field.harmonic", s);
  for (std::size_t k = 0; k < scene.size(); ++k) {
    Eigen::VectorXcd F = Eigen::VectorXcd::Zero(m.n);
    if (const auto& spec = scene.bodies[k].moment; spec && spec->frequency > 0) {  // sin(0 t) = 0
      F[static_cast<Eigen::Index>(k)] = complex_moment(spec->harmonic);
      add_harmonic(m, f, F, spec->frequency, "body[" + std::to_string(k + 1) + "].moment.harmonic", s);
    }
    if (const auto& force = scene.bodies[k].force; force && force->frequency > 0) {
      F.setZero();
      add_force_moments(scene, k, force->harmonic, force->at, F);
      add_harmonic(m, f, F, force->frequency, "body[" + std::to_string(k + 1) + "].force.harmonic", s);
    }
  }
  return s;
}

}  // namespace rc::rom
