#include "line_space.hpp"

#include "gauss_rules.hpp"

#include <algorithm>
#include <stdexcept>

namespace rc::modes {

LineSpace::LineSpace(std::vector<double> breaks, int order, bool drop_left_dof)
    : breaks_(std::move(breaks)), order_(order), drop_left_(drop_left_dof) {
  if (breaks_.size() < 2 || order_ < 1) throw std::invalid_argument("LineSpace: need two breaks and order >= 1");
  for (std::size_t i = 1; i < breaks_.size(); ++i)
    if (!(breaks_[i] > breaks_[i - 1])) throw std::invalid_argument("LineSpace: breaks must increase");
  ndof_ = num_elements() * order_ + 1 - (drop_left_ ? 1 : 0);
  for (double t : gauss_lobatto_points(order_)) nodes_.push_back(0.5 * (t + 1));
  std::vector<double> x, w;
  gauss_legendre(3 * order_ + 8, x, w);
  for (std::size_t q = 0; q < x.size(); ++q) {
    qx_.push_back(0.5 * (x[q] + 1));
    qw_.push_back(0.5 * w[q]);
  }
  N_.resize(qx_.size() * (order_ + 1));
  dN_.resize(N_.size());
  for (std::size_t q = 0; q < qx_.size(); ++q) basis(qx_[q], &N_[q * (order_ + 1)], &dN_[q * (order_ + 1)]);
}

void LineSpace::element_dofs(int e, int* dofs) const {
  const int shift = drop_left_ ? 1 : 0;
  for (int a = 0; a <= order_; ++a) dofs[a] = e * order_ + a - shift;  // −1 only for the left-out dof
}

void LineSpace::basis(double t, double* N, double* dN) const {
  // Lagrange polynomials ℓ_a(t) = Π_{b≠a} (t − t_b)/(t_a − t_b) and their derivatives (product rule).
  for (int a = 0; a <= order_; ++a) {
    double value = 1, derivative = 0;
    for (int b = 0; b <= order_; ++b) {
      if (b == a) continue;
      const double d = nodes_[a] - nodes_[b];
      derivative = (derivative * (t - nodes_[b]) + value) / d;
      value *= (t - nodes_[b]) / d;
    }
    N[a] = value;
    dN[a] = derivative;
  }
}

std::vector<double> graded_breaks(double x0, double x1, int n, int layers, bool grade_left, bool grade_right) {
  if (n < (grade_left && grade_right && layers > 0 ? 2 : 1))
    throw std::invalid_argument("graded_breaks: too few elements for the grading");
  const double h = (x1 - x0) / n;
  std::vector<double> b;
  // Left end: x0, x0 + h/2^layers, …, x0 + h/2, then the uniform breaks.
  b.push_back(x0);
  if (grade_left)
    for (int l = layers; l >= 1; --l) b.push_back(x0 + h / (1 << l));
  for (int i = 1; i < n; ++i) b.push_back(x0 + i * h);
  if (grade_right)
    for (int l = 1; l <= layers; ++l) b.push_back(x1 - h / (1 << l));
  b.push_back(x1);
  return b;
}

std::vector<double> merged_pairs(const std::vector<double>& breaks) {
  std::vector<double> b;
  for (std::size_t i = 0; i + 1 < breaks.size(); i += 2) b.push_back(breaks[i]);
  b.push_back(breaks.back());
  return b;
}

double longest_element(const std::vector<double>& breaks) {
  double h = 0;
  for (std::size_t i = 1; i < breaks.size(); ++i) h = std::max(h, breaks[i] - breaks[i - 1]);
  return h;
}

}  // namespace rc::modes
