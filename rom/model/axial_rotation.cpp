#include "axial_rotation.hpp"

#include <cmath>

namespace rc::rom {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kZeroRate = 1e-12;  // μ_j below this × max(1, max μ) is a zero (no friction in that direction)

// The symmetric system's modes: K = C^{-1/2} D C^{-1/2} = V diag(μ) Vᵀ.
struct AxialModes {
  Eigen::VectorXd mu, c_half;  // μ ascending; C^{1/2}
  Eigen::MatrixXd V;
};

AxialModes modes_of(const AxialChain& a) {
  AxialModes m;
  m.c_half = a.C.cwiseSqrt();
  // Without friction every rate is zero, whatever the inertias (a shell of none among them: its liquid does not follow
  // its spin, docs/physics.md §3, "Axial rotations"; the model refuses it where a friction or a moment would act).
  if (a.D.cwiseAbs().maxCoeff() == 0) {
    m.mu = Eigen::VectorXd::Zero(a.C.size());
    m.V = Eigen::MatrixXd::Identity(a.C.size(), a.C.size());
    return m;
  }
  const Eigen::VectorXd inv = m.c_half.cwiseInverse();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(inv.asDiagonal() * a.D * inv.asDiagonal());
  m.mu = es.eigenvalues();
  m.V = es.eigenvectors();
  const double floor = kZeroRate * std::max(1.0, m.mu.cwiseAbs().maxCoeff());
  for (Eigen::Index j = 0; j < m.mu.size(); ++j)
    if (std::abs(m.mu[j]) <= floor) m.mu[j] = 0;
  return m;
}

// One modal coordinate y' = −μ y + g + h sin(Ωt), y(0) = y0: the value and its integral from 0 to t.
struct Modal {
  double y = 0, integral = 0;
};

Modal constant_part(double mu, double y0, double g, double t) {
  if (mu == 0) return {y0 + g * t, y0 * t + 0.5 * g * t * t};
  const double e = std::exp(-mu * t), rest = g / mu;
  return {rest + (y0 - rest) * e, rest * t + (y0 - rest) * (1 - e) / mu};
}

Modal harmonic_part(double mu, double h, double w, double t) {
  if (h == 0 || w == 0) return {};
  if (mu == 0) return {h * (1 - std::cos(w * t)) / w, h * (t - std::sin(w * t) / w) / w};
  const double d = mu * mu + w * w, p0 = -h * w / d, e = std::exp(-mu * t);  // particular part at t = 0: p0
  const double y = h * (mu * std::sin(w * t) - w * std::cos(w * t)) / d - p0 * e;
  const double integral = h * (mu * (1 - std::cos(w * t)) / w - std::sin(w * t)) / d - p0 * (1 - e) / mu;
  return {y, integral};
}

}  // namespace

bool AxialChain::moves() const {
  return D.cwiseAbs().maxCoeff() > 0 || moment.cwiseAbs().maxCoeff() > 0 || harmonic.cwiseAbs().maxCoeff() > 0 ||
         start.cwiseAbs().maxCoeff() > 0;
}

AxialChain axial_chain(const Scene& scene, const std::vector<double>& inertia) {
  const int n = static_cast<int>(scene.size());
  AxialChain a;
  a.C = Eigen::Map<const Eigen::VectorXd>(inertia.data(), n);
  a.D = Eigen::MatrixXd::Zero(n, n);
  a.spin0 = a.start = a.moment = a.harmonic = a.frequency = Eigen::VectorXd::Zero(n);
  // Joint k (0-based) between bodies k and k+1; the support acts on body 0 alone.
  if (!scene.free_chain) a.D(0, 0) += scene.support_axial_friction;
  for (std::size_t k = 0; k < scene.joints.size() && k + 1 < scene.size(); ++k) {
    const double beta = scene.joints[k].axial_friction;
    a.D(k, k) += beta;
    a.D(k + 1, k + 1) += beta;
    a.D(k, k + 1) -= beta;
    a.D(k + 1, k) -= beta;
  }
  for (int k = 0; k < n; ++k) {
    const BodySpec& b = scene.bodies[k];
    a.spin0[k] = b.spin;
    if (scene.axial_rate.size() == static_cast<std::size_t>(n)) a.start[k] = scene.axial_rate[k];
    if (!b.moment) continue;
    a.moment[k] = b.moment->axial + b.moment->space[2];
    a.harmonic[k] = b.moment->harmonic[2];
    a.frequency[k] = b.moment->frequency;
  }
  return a;
}

AxialSpectrum axial_spectrum(const AxialChain& a) {
  const AxialModes m = modes_of(a);
  const int n = static_cast<int>(a.C.size());
  AxialSpectrum s;
  s.decay = m.mu;
  s.zero_eigenvectors = n;
  s.zeros = n;
  for (int j = 0; j < n; ++j) s.zeros += m.mu[j] == 0;
  for (int j = 0; j < s.zeros; ++j) s.roots.push_back(0.0);
  for (int j = 0; j < n; ++j)
    if (m.mu[j] > 0) s.roots.push_back({0.0, m.mu[j]});
  return s;
}

AxialHistory axial_history(const AxialChain& a, const std::vector<double>& t) {
  const AxialModes m = modes_of(a);
  const int n = static_cast<int>(a.C.size());
  const Eigen::VectorXd inv = m.c_half.cwiseInverse();
  const Eigen::VectorXd y0 = m.V.transpose() * m.c_half.cwiseProduct(a.spin0 + a.start);
  const Eigen::VectorXd g = m.V.transpose() * inv.cwiseProduct(a.moment);
  AxialHistory h;
  h.spin.resize(static_cast<Eigen::Index>(t.size()), n);
  h.angle.resize(static_cast<Eigen::Index>(t.size()), n);
  for (std::size_t i = 0; i < t.size(); ++i) {
    Eigen::VectorXd y(n), integral(n);
    for (int j = 0; j < n; ++j) {
      const Modal c = constant_part(m.mu[j], y0[j], g[j], t[i]);
      y[j] = c.y;
      integral[j] = c.integral;
    }
    // Each body's harmonic moment with its own frequency: one forcing direction C^{-1/2} e_k per body.
    for (int k = 0; k < n; ++k) {
      if (a.harmonic[k] == 0) continue;
      const Eigen::VectorXd hk = m.V.row(k).transpose() * (inv[k] * a.harmonic[k]);
      for (int j = 0; j < n; ++j) {
        const Modal p = harmonic_part(m.mu[j], hk[j], kTwoPi * a.frequency[k], t[i]);
        y[j] += p.y;
        integral[j] += p.integral;
      }
    }
    const auto row = static_cast<Eigen::Index>(i);
    h.spin.row(row) = inv.cwiseProduct(m.V * y).transpose();
    h.angle.row(row) = (inv.cwiseProduct(m.V * integral) - a.spin0 * t[i]).transpose();
  }
  return h;
}

}  // namespace rc::rom
