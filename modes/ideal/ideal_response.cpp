#include "ideal_response.hpp"

#include "stiffness_solver.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::modes {
namespace {

// u = e1 × r split by the pointwise blocks of (S − σ)⁻¹: u_ab = (a, b, 0), u_ba = (b, a, 0), u_c = (0, 0, c).
struct CouplingParts {
  double ab_ab = 0, ab_ba = 0, c_c = 0;  // uᵀΩu_ab, uᵀΩu_ba, uᵀΩu_c
  Eigen::VectorXd g_ab, g_ba, g_c;       // GᵀΩ of each
};

CouplingParts coupling_parts(const VelocitySpace& V) {
  const Eigen::VectorXd u = V.coupling_vector();
  Eigen::VectorXd ab = Eigen::VectorXd::Zero(u.size()), ba = ab, c = ab;
  for (Eigen::Index g = 0; 3 * g < u.size(); ++g) {
    ab[3 * g] = u[3 * g];
    ab[3 * g + 1] = u[3 * g + 1];
    ba[3 * g] = u[3 * g + 1];
    ba[3 * g + 1] = u[3 * g];
    c[3 * g + 2] = u[3 * g + 2];
  }
  CouplingParts p{V.dot(u, ab), V.dot(u, ba), V.dot(u, c), {}, {}, {}};
  std::vector<double> g;
  V.divergence(ab, g);
  p.g_ab = Eigen::Map<Eigen::VectorXd>(g.data(), static_cast<Eigen::Index>(g.size()));
  V.divergence(ba, g);
  p.g_ba = Eigen::Map<Eigen::VectorXd>(g.data(), static_cast<Eigen::Index>(g.size()));
  V.divergence(c, g);
  p.g_c = Eigen::Map<Eigen::VectorXd>(g.data(), static_cast<Eigen::Index>(g.size()));
  return p;
}

// α Q1 + β Q2 as a new matrix (Q1, Q2 of one pattern family: M, Gc, Kz).
PMat combination(Mat first, double a, Mat second, double b) {
  PMat out;
  petsc_check(MatDuplicate(first, MAT_COPY_VALUES, out.out()), "MatDuplicate");
  petsc_check(MatScale(out, a), "MatScale");
  petsc_check(MatAXPY(out, b, second, DIFFERENT_NONZERO_PATTERN), "MatAXPY");
  return out;
}

// The real symmetric block [[Re Q, Im Q], [Im Q, −Re Q]] of Q(σ) = σ² M + 2σ Gc − 4 Kz.
PMat block_quadratic(const PoincareForms& f, std::complex<double> sigma) {
  const std::complex<double> s2 = sigma * sigma;
  PMat re = combination(f.M, s2.real(), f.Gc, 2 * sigma.real());
  petsc_check(MatAXPY(re, -4.0, f.Kz, DIFFERENT_NONZERO_PATTERN), "MatAXPY");
  PMat im = combination(f.M, s2.imag(), f.Gc, 2 * sigma.imag());
  PMat minus_re;
  petsc_check(MatDuplicate(re, MAT_COPY_VALUES, minus_re.out()), "MatDuplicate");
  petsc_check(MatScale(minus_re, -1.0), "MatScale");
  Mat blocks[4] = {re.get(), im.get(), im.get(), minus_re.get()};
  PMat nest, out;
  petsc_check(MatCreateNest(PETSC_COMM_SELF, 2, nullptr, 2, nullptr, blocks, nest.out()), "MatCreateNest");
  petsc_check(MatConvert(nest, MATAIJ, MAT_INITIAL_MATRIX, out.out()), "MatConvert");
  petsc_check(MatSetOption(out, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  return out;
}

std::complex<double> response_at(const CouplingParts& u, const PoincareForms& forms, std::complex<double> sigma) {
  using C = std::complex<double>;
  // (S − σ)⁻¹ u = α u_ab + β u_ba + γ u_c (velocity_space.cpp).
  const C alpha = -sigma / (sigma * sigma - 4.0), beta = 2.0 / (sigma * sigma - 4.0), gamma = -1.0 / sigma;
  const C uy = alpha * u.ab_ab + beta * u.ab_ba + gamma * u.c_c;
  const Eigen::Index n = u.g_ab.size();
  std::vector<double> rhs(2 * n), sol;
  for (Eigen::Index i = 0; i < n; ++i) {
    const C g = alpha * u.g_ab[i] + beta * u.g_ba[i] + gamma * u.g_c[i];
    rhs[i] = g.real();
    rhs[n + i] = g.imag();
  }
  const PMat Q = block_quadratic(forms, sigma);
  const StiffnessSolver solver(Q, "response_", fmt::format("Q(sigma) at sigma = {:.9g}{:+.9g}i", sigma.real(),
                                                           sigma.imag()));
  solver.solve(rhs, sol);
  // p = sol_re − i sol_im; gᵀp with g = rhs_re + i rhs_im.
  C gp = 0;
  for (Eigen::Index i = 0; i < n; ++i) gp += C(rhs[i], rhs[n + i]) * C(sol[i], -sol[n + i]);
  const C c = sigma * (sigma * sigma - 4.0);
  return -std::numbers::pi * (uy + c * gp);
}

}  // namespace

std::vector<std::complex<double>> ideal_response(const VelocitySpace& V, const PoincareForms& forms,
                                                 const std::vector<std::complex<double>>& sigmas) {
  for (const auto s : sigmas) {
    if (!std::isfinite(s.real()) || !std::isfinite(s.imag()))
      throw std::invalid_argument("the ideal response needs finite frequencies sigma");
    if (s.imag() == 0 && std::abs(s.real()) < 2)
      throw std::invalid_argument(fmt::format("the ideal response at real sigma = {:g} inside (-2, 2) lies on the "
                                              "spectrum; give sigma an imaginary part (--sigma-imag)", s.real()));
    if (s.imag() == 0 && std::abs(s.real()) == 2)
      throw std::invalid_argument("the ideal response is singular at sigma = +-2");
  }
  const CouplingParts u = coupling_parts(V);
  std::vector<std::complex<double>> out;
  out.reserve(sigmas.size());
  for (const auto s : sigmas) out.push_back(response_at(u, forms, s));
  return out;
}

}  // namespace rc::modes
