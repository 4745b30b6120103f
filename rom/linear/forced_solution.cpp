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

Eigen::VectorXcd ForcedSolution::at(double t) const {
  Eigen::VectorXcd y = constant;
  for (const Harmonic& h : harmonics) y += h.plus * std::exp(cd(0, h.omega * t)) + h.minus * std::exp(cd(0, -h.omega * t));
  return y;
}

Eigen::VectorXcd constant_moments(const Scene& scene) {
  Eigen::VectorXcd F = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(scene.size()));
  for (std::size_t k = 0; k < scene.size(); ++k)
    if (scene.bodies[k].moment) F[static_cast<Eigen::Index>(k)] = complex_moment(scene.bodies[k].moment->space);
  return F;
}

ForcedSolution forced_solution(const ChainModel& m, const FirstOrderSystem& f, const Scene& scene) {
  ForcedSolution s;
  s.constant = Eigen::VectorXcd::Zero(f.dim());
  const Eigen::VectorXcd Fc = constant_moments(scene);
  if (Fc.cwiseAbs().maxCoeff() > 0) {
    s.present = true;
    s.constant = resolvent(f, 0.0, forcing(m, f, Fc), "a constant moment (body.moment.space)");  // (0 − B) y_c = f_c
  }
  for (std::size_t k = 0; k < scene.size(); ++k) {
    const auto& spec = scene.bodies[k].moment;
    if (!spec) continue;
    const cd Fh = complex_moment(spec->harmonic);
    if (Fh == cd(0) || spec->frequency == 0) continue;  // sin(0 t) = 0
    s.present = true;
    Eigen::VectorXcd F = Eigen::VectorXcd::Zero(m.n);
    F[static_cast<Eigen::Index>(k)] = Fh;
    const Eigen::VectorXcd fh = forcing(m, f, F) / cd(0, 2);
    const double omega = 2 * std::numbers::pi * spec->frequency;
    const std::string what = "body[" + std::to_string(k + 1) + "].moment.harmonic";
    s.harmonics.push_back({omega, resolvent(f, omega, fh, what), resolvent(f, -omega, -fh, what)});
  }
  return s;
}

}  // namespace rc::rom
