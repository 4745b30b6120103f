// A one-dimensional continuous Lagrange finite-element space on a partitioned interval: the factor spaces
// of the tensor-product discretisation of the cylinder (separable_cylinder.hpp). Nodes are the
// Gauss–Lobatto–Legendre points of each element (well conditioned at high order); dofs are numbered left
// to right. The left end's dof can be left out (p = 0 on the axis for m = 1, docs/physics.md §2).
#pragma once

#include "eigen_dense.hpp"

#include <vector>

namespace rc::modes {

class LineSpace {
 public:
  // breaks: strictly increasing element end points (at least two); order >= 1.
  LineSpace(std::vector<double> breaks, int order, bool drop_left_dof);

  int ndof() const { return ndof_; }
  int num_elements() const { return static_cast<int>(breaks_.size()) - 1; }

  // ∫ f(x, φ_i, φ_i′, φ_j, φ_j′) dx over the interval, for every pair of dofs (a symmetric f gives a
  // symmetric matrix). Quadrature: Gauss–Legendre with 3P + 8 points per element, exact for polynomial
  // integrands of degree 6P + 15 and to rounding for the smooth 1/r weights met away from the axis.
  template <class F>
  Eigen::MatrixXd bilinear(F f) const {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(ndof_, ndof_);
    for_each_point([&](double x, double w, const double* N, const double* dN, const int* dofs) {
      for (int a = 0; a <= order_; ++a) {
        if (dofs[a] < 0) continue;
        for (int b = 0; b <= order_; ++b)
          if (dofs[b] >= 0) A(dofs[a], dofs[b]) += w * f(x, N[a], dN[a], N[b], dN[b]);
      }
    });
    return A;
  }

  // ∫ f(x, φ_i, φ_i′) dx for every dof.
  template <class F>
  Eigen::VectorXd linear(F f) const {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(ndof_);
    for_each_point([&](double x, double w, const double* N, const double* dN, const int* dofs) {
      for (int a = 0; a <= order_; ++a)
        if (dofs[a] >= 0) v(dofs[a]) += w * f(x, N[a], dN[a]);
    });
    return v;
  }

  // ∫ f(x) dx by the same quadrature.
  template <class F>
  double integral(F f) const {
    double s = 0;
    for_each_point([&](double x, double w, const double*, const double*, const int*) { s += w * f(x); });
    return s;
  }

 private:
  // Calls g(x, w, N, dN, dofs) at every quadrature point (dN = d/dx); dofs[a] = −1 for a left-out dof.
  template <class G>
  void for_each_point(G g) const {
    std::vector<int> dofs(order_ + 1);
    std::vector<double> dNx(order_ + 1);
    for (int e = 0; e < num_elements(); ++e) {
      element_dofs(e, dofs.data());
      const double x0 = breaks_[e], h = breaks_[e + 1] - x0;
      for (std::size_t q = 0; q < qx_.size(); ++q) {
        const double* dN = &dN_[q * (order_ + 1)];
        for (int a = 0; a <= order_; ++a) dNx[a] = dN[a] / h;
        g(x0 + h * qx_[q], h * qw_[q], &N_[q * (order_ + 1)], dNx.data(), dofs.data());
      }
    }
  }
  void element_dofs(int e, int* dofs) const;
  // Lagrange basis on the reference element [0, 1] at t: values and d/dt.
  void basis(double t, double* N, double* dN) const;

  std::vector<double> breaks_;
  int order_;
  bool drop_left_;
  int ndof_;
  std::vector<double> nodes_;   // reference GLL nodes on [0, 1]
  std::vector<double> qx_, qw_;  // reference quadrature on [0, 1]
  std::vector<double> N_, dN_;   // basis at the quadrature points; dN_ is d/dt (divided by h when used)
};

// n uniform elements on [x0, x1]; at each graded end the element touching it is further cut into `layers` + 1
// pieces that halve towards the end (sizes h/2, h/4, …, h/2^layers, h/2^layers): geometric refinement for
// the corner singularity of the Zhukovsky potential (docs/modes.md, "Separable cylinder solver").
std::vector<double> graded_breaks(double x0, double x1, int n, int layers, bool grade_left, bool grade_right);

// The partition with every two neighbouring elements merged, from the left (an odd count leaves the last one
// alone): every element at least doubles, grading kept. An even count of a partition symmetric about its
// middle stays symmetric. One element stays as it is.
std::vector<double> merged_pairs(const std::vector<double>& breaks);

// The longest element.
double longest_element(const std::vector<double>& breaks);

}  // namespace rc::modes
