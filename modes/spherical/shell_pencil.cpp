#include "shell_pencil.hpp"

#include "ultraspherical.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rc::modes::spherical {
namespace {

// The radial operators of one run, built once at `full` coefficients (a few above those kept: the products with
// r^k raise the degree, and the cut is the tau truncation).
struct Radial {
  int full = 0;
  double scale = 1, shift = 0;  // r = scale x + shift
  SparseMatrix D[5];            // d^k/dr^k: T → C^(k)
  SparseMatrix S[5][5];         // S[a][b]: C^(a) → C^(b)

  Radial(int n, double ri) : full(n) {
    scale = ri > 0 ? (1 - ri) / 2 : 1.0;
    shift = ri > 0 ? (1 + ri) / 2 : 0.0;
    for (int k = 1; k <= 4; ++k) D[k] = derivative(n, k) / std::pow(scale, k);
    for (int a = 0; a <= 4; ++a)
      for (int b = a; b <= 4; ++b) S[a][b] = conversion(n, a, b);
  }
  // r^p (multiplied in C^(λ)) applied after the k-th derivative, the result converted up to C^(top).
  SparseMatrix term(int top, int k, int p) const {
    SparseMatrix product = multiply_by_r(full, k, scale, shift, p);
    if (k > 0) product = SparseMatrix(product * D[k]);
    return SparseMatrix(S[k][top] * product);
  }
};

struct Layout {
  const ShellSettings& s;
  bool sphere() const { return s.inner_radius == 0; }
  // The Chebyshev degree of local coefficient j of a scalar of harmonic degree l.
  int degree(int l, int j) const { return sphere() ? 2 * j + l % 2 : j; }
  int full() const { return (sphere() ? 2 * s.radial : s.radial) + 12; }
};

// Adds rows 0 … rows − 1 of the equation of block `row_block` (harmonic degree lr), columns of the scalar in block
// `col_block` (degree lc), of `op` × factor into `out`. They go below the block's wall rows: equation row i, whose
// highest derivative sits in coefficient i + (its order), lands near the diagonal there.
void add_block(Triplets& out, const Layout& layout, const SparseMatrix& op, double factor, int rows, int row_block,
               int lr, int col_block, int lc) {
  const int n = layout.s.radial, walls = n - rows;
  for (int i = 0; i < rows; ++i) {
    const int di = layout.degree(lr, i);
    for (SparseMatrix::InnerIterator it(op, di); it; ++it) {
      const int dj = static_cast<int>(it.col());
      const int j = layout.sphere() ? (dj - lc % 2) / 2 : dj;
      if (j < 0 || j >= n || layout.degree(lc, j) != dj) continue;  // the other parity (zero) or beyond the cut
      out.add(row_block * n + walls + i, col_block * n + j, factor * it.value());
    }
  }
}

// The wall rows of block b (degree l), which replace its equation's last rows (the tau method) and are placed first
// in the block: T = 0 (toroidal) or P = P′ = 0 at r = 1 and, in a shell, at r = r_i.
void add_walls(Triplets& out, const Layout& layout, const Radial& radial, int b, int l, bool toroidal) {
  const int n = layout.s.radial;
  std::vector<std::pair<double, int>> conditions;  // (x of the wall, derivative order)
  for (double x : layout.sphere() ? std::vector<double>{1.0} : std::vector<double>{1.0, -1.0}) {
    conditions.emplace_back(x, 0);
    if (!toroidal) conditions.emplace_back(x, 1);
  }
  int row = b * n;
  for (auto [x, order] : conditions) {
    for (int j = 0; j < n; ++j) {
      const int d = layout.degree(l, j);
      const double sign = x > 0 ? 1.0 : ((d + order) % 2 == 0 ? 1.0 : -1.0);  // T_d(−1) = (−1)^d, T_d′(−1) = (−1)^{d+1} d²
      const double value = order == 0 ? sign : sign * d * d / radial.scale;
      out.add(row, b * n + j, value);
    }
    ++row;
  }
}

// Divides each row of A and 𝓜 by its largest entry in A (the eigenproblem is unchanged): the derivative terms grow as
// k⁴ at degree k and the walls' rows as k², and without it MUMPS's factors of A − τ𝓜 lose the target's mode at high
// truncations (measured: the shell at Ek = 1e-4, twice the default truncation, found modes at the target itself).
void equilibrate_rows(ShellPencil& p) {
  std::vector<double> largest(p.size, 0.0);
  for (const Triplets* t : {&p.a_real, &p.a_imag})
    for (std::size_t k = 0; k < t->v.size(); ++k) largest[t->i[k]] = std::max(largest[t->i[k]], std::abs(t->v[k]));
  for (Triplets* t : {&p.a_real, &p.a_imag, &p.mass})
    for (std::size_t k = 0; k < t->v.size(); ++k) t->v[k] /= largest[t->i[k]];
}

// The radial operators of both equations (shell_pencil.hpp), times r² and r⁴ (term(top, derivative, power of r)).
struct EquationTerms {
  SparseMatrix viscous_t, t0, t_r2, t_dp, t_p, p4, p_d2, p0, p_lap, p_r2, p_dt, p_t;
  explicit EquationTerms(const Radial& radial)
      : viscous_t(radial.term(2, 2, 2) + 2 * radial.term(2, 1, 1)),  // r²T″ + 2rT′ (− L T in the equation)
        t0(radial.term(2, 0, 0)), t_r2(radial.term(2, 0, 2)),
        t_dp(radial.term(2, 1, 2)), t_p(radial.term(2, 0, 1)),       // r²P′, rP
        p4(radial.term(4, 4, 4) + 4 * radial.term(4, 3, 3)),         // r⁴D_l² = p4 − 2L r²P″ + L(L−2)P
        p_d2(radial.term(4, 2, 2)), p0(radial.term(4, 0, 0)),
        p_lap(radial.term(4, 2, 4) + 2 * radial.term(4, 1, 3)),      // r⁴D_l = p_lap − L r²P
        p_r2(radial.term(4, 0, 2)),
        p_dt(radial.term(4, 1, 4)), p_t(radial.term(4, 0, 3)) {}     // r⁴T′, r³T
};

void check_settings(const ShellSettings& s) {
  if (!(s.ekman > 0)) throw std::invalid_argument("the Ekman number must be positive");
  if (!(s.inner_radius >= 0 && s.inner_radius < 1)) throw std::invalid_argument("the inner radius must be in [0, 1)");
  if (s.m < 0) throw std::invalid_argument("the azimuthal wavenumber m must be >= 0");
  if (s.radial < 8) throw std::invalid_argument("at least 8 Chebyshev coefficients per scalar are needed");
  if (s.lmax < std::max(s.m, 1) + 1) throw std::invalid_argument("lmax must exceed max(m, 1)");
}

// The blocks' harmonic degrees l = max(m, 1) … lmax (l = 0 carries no flow), toroidal and poloidal alternating.
void set_blocks(const ShellSettings& s, ShellPencil& out) {
  const int l0 = std::max(s.m, 1);
  for (int l = l0; l <= s.lmax; ++l) {
    out.degree.push_back(l);
    out.toroidal.push_back(((l - l0) % 2 == 0) == s.toroidal_first);
  }
}

}  // namespace

ShellPencil assemble_shell_pencil(const ShellSettings& s) {
  check_settings(s);
  const Layout layout{s};
  const Radial radial(layout.full(), s.inner_radius);
  const int n = s.radial;
  ShellPencil out;
  set_blocks(s, out);
  const int blocks = static_cast<int>(out.degree.size());
  out.size = blocks * n;
  const double m = s.m, E = s.ekman;
  auto c = [&](int l) { return l > s.m ? std::sqrt((double(l) * l - m * m) / (4.0 * l * l - 1)) : 0.0; };
  const auto& [viscous_t, t0, t_r2, t_dp, t_p, p4, p_d2, p0, p_lap, p_r2, p_dt, p_t] = EquationTerms(radial);
  for (int b = 0; b < blocks; ++b) {
    const int l = out.degree[b];
    const double L = double(l) * (l + 1);
    const bool tor = out.toroidal[b];
    const int rows = n - (tor ? 1 : 2) * (layout.sphere() ? 1 : 2);  // the rest are wall rows
    // A = −i (right-hand side): the 2im terms go to Re A as 2m, the others to Im A negated.
    auto lhs = [&](const SparseMatrix& op, double f) { add_block(out.mass, layout, op, f, rows, b, l, b, l); };
    auto rhs_real = [&](const SparseMatrix& op, double f, int cb) {  // a real right-hand-side term of block cb
      add_block(out.a_imag, layout, op, -f, rows, b, l, cb, out.degree[cb]);
    };
    auto rhs_coriolis = [&](const SparseMatrix& op, double f) {  // 2im × op
      add_block(out.a_real, layout, op, 2 * m * f, rows, b, l, b, l);
    };
    const int sign = tor ? 1 : -1;  // the couplings' sign in each equation
    if (tor) {
      lhs(t_r2, L);
      rhs_real(viscous_t, E * L, b);
      rhs_real(t0, -E * L * L, b);
      rhs_coriolis(t_r2, 1);
    } else {
      lhs(p_lap, L);
      lhs(p_r2, -L * L);
      rhs_real(p4, E * L, b);
      rhs_real(p_d2, -2 * E * L * L, b);
      rhs_real(p0, E * L * L * (L - 2), b);
      rhs_coriolis(p_lap, 1);
      rhs_coriolis(p_r2, -L);
    }
    const SparseMatrix& d_other = tor ? t_dp : p_dt;  // r^k X′ of the other scalar
    const SparseMatrix& x_other = tor ? t_p : p_t;    // r^(k−1) X
    if (b > 0) {  // X_{l−1}: 2c_l (l−1)(l+1) [X′ − (l−1) X/r]
      const double f = sign * 2 * c(l) * (l - 1) * (l + 1);
      rhs_real(d_other, f, b - 1);
      rhs_real(x_other, -f * (l - 1), b - 1);
    }
    if (b + 1 < blocks) {  // X_{l+1}: 2c_{l+1} l(l+2) [X′ + (l+2) X/r]
      const double f = sign * 2 * c(l + 1) * l * (l + 2);
      rhs_real(d_other, f, b + 1);
      rhs_real(x_other, f * (l + 2), b + 1);
    }
    add_walls(out.a_real, layout, radial, b, l, tor);
  }
  equilibrate_rows(out);
  return out;
}

}  // namespace rc::modes::spherical
