#include "ultraspherical.hpp"

#include <vector>

namespace rc::modes::spherical {
namespace {

SparseMatrix from_triplets(int n, const std::vector<Eigen::Triplet<double>>& t) {
  SparseMatrix m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

SparseMatrix identity(int n) {
  SparseMatrix m(n, n);
  m.setIdentity();
  return m;
}

}  // namespace

SparseMatrix derivative(int n, int k) {
  // d/dx T_j = j C^(1)_{j−1};  d/dx C^(λ)_j = 2λ C^(λ+1)_{j−1}: so d^k/dx^k T_j = j 2^(k−1) (k−1)! C^(k)_{j−k}.
  double factor = 1;
  for (int lambda = 1; lambda < k; ++lambda) factor *= 2.0 * lambda;
  std::vector<Eigen::Triplet<double>> t;
  for (int j = k; j < n; ++j) t.emplace_back(j - k, j, factor * j);
  return from_triplets(n, t);
}

SparseMatrix conversion(int n, int lambda) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j) {
    if (lambda == 0) {  // T_0 = C_0, T_j = ½ (C_j − C_{j−2}) (C = C^(1), the U polynomials)
      t.emplace_back(j, j, j == 0 ? 1.0 : 0.5);
      if (j >= 2) t.emplace_back(j - 2, j, -0.5);
    } else {  // C^(λ)_j = λ/(j+λ) (C^(λ+1)_j − C^(λ+1)_{j−2})
      const double c = lambda / static_cast<double>(j + lambda);
      t.emplace_back(j, j, c);
      if (j >= 2) t.emplace_back(j - 2, j, -c);
    }
  }
  return from_triplets(n, t);
}

SparseMatrix conversion(int n, int from, int to) {
  SparseMatrix s = identity(n);
  for (int lambda = from; lambda < to; ++lambda) s = SparseMatrix(conversion(n, lambda) * s);
  return s;
}

SparseMatrix multiply_by_x(int n, int lambda) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j) {
    if (lambda == 0) {  // x T_0 = T_1, x T_j = ½ (T_{j+1} + T_{j−1})
      if (j + 1 < n) t.emplace_back(j + 1, j, j == 0 ? 1.0 : 0.5);
      if (j >= 1) t.emplace_back(j - 1, j, 0.5);
    } else {  // x C_j = (j+1)/(2(j+λ)) C_{j+1} + (j+2λ−1)/(2(j+λ)) C_{j−1}
      const double d = 2.0 * (j + lambda);
      if (j + 1 < n) t.emplace_back(j + 1, j, (j + 1) / d);
      if (j >= 1) t.emplace_back(j - 1, j, (j + 2 * lambda - 1) / d);
    }
  }
  return from_triplets(n, t);
}

SparseMatrix multiply_by_r(int n, int lambda, double scale, double shift, int power) {
  const SparseMatrix r = scale * multiply_by_x(n, lambda) + shift * identity(n);
  SparseMatrix m = identity(n);
  for (int p = 0; p < power; ++p) m = SparseMatrix(r * m);
  return m;
}

}  // namespace rc::modes::spherical
