#include "response_row_pruning.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>

namespace rc::rom {
namespace {

using cd = std::complex<double>;
constexpr int kGrid = 2001;  // window frequencies the contributions are bounded at

// Row l's couplings to the table's inputs: c_f (and a free surface's c_g), complex for a viscous table.
std::vector<cd> couplings(const rc::ModeTable& t, int l) {
  const auto at = static_cast<std::size_t>(l);
  std::vector<cd> c{{t.a[at], t.a_imag.empty() ? 0.0 : t.a_imag[at]}};
  if (t.free_surface.present())
    c.emplace_back(t.free_surface.t[at], t.free_surface.t_imag.empty() ? 0.0 : t.free_surface.t_imag[at]);
  return c;
}

cd pole(const rc::ModeTable& t, int l) {
  const auto at = static_cast<std::size_t>(l);
  return {t.lambda[at], t.decay.empty() ? 0.0 : t.decay[at]};
}

double grid_point(const rc::ModeTable& t, int g) { return t.fit_lo + (t.fit_hi - t.fit_lo) * g / (kGrid - 1); }

// What each entry (i, j) of the table's R may lose on the window, at each grid frequency: `magnitude` × max|R|'s scale
// √(max|R_ii| max|R_jj|), and `dissipation` × Im R's own size √(Im R_ii Im R_jj) (floor 1e-4 of its largest, as the
// Krylov search measures Im R's error: modes/viscous/krylov_response.hpp), the smaller of the two. A grid coarser than a
// resonance's width can miss its peak; a size too small only keeps more rows.
std::vector<std::vector<double>> allowances(const rc::ModeTable& t, std::size_t inputs, double magnitude,
                                            double dissipation) {
  std::vector<std::vector<cd>> R(inputs, std::vector<cd>(kGrid));
  for (int l = 0; l < static_cast<int>(t.size()); ++l) {
    const std::vector<cd> c = couplings(t, l);
    const cd p = pole(t, l);
    const double n2 = t.N2[static_cast<std::size_t>(l)];
    for (int g = 0; g < kGrid; ++g) {
      const cd w = 2.0 / (n2 * (grid_point(t, g) - p));
      for (std::size_t i = 0; i < inputs; ++i) R[i][static_cast<std::size_t>(g)] += w * c[i] * c[i];
    }
  }
  std::vector<double> scale(inputs, 0.0), largest_im(inputs, 0.0);
  for (std::size_t i = 0; i < inputs; ++i)
    for (const cd r : R[i]) {
      scale[i] = std::max(scale[i], std::abs(r));
      largest_im[i] = std::max(largest_im[i], r.imag());
    }
  std::vector<std::vector<double>> out(inputs * inputs, std::vector<double>(kGrid));
  for (std::size_t i = 0; i < inputs; ++i)
    for (std::size_t j = 0; j < inputs; ++j)
      for (std::size_t g = 0; g < static_cast<std::size_t>(kGrid); ++g) {
        const double own = std::sqrt(std::max(R[i][g].imag(), 0.0) * std::max(R[j][g].imag(), 0.0));
        const double size = std::max(own, 1e-4 * std::sqrt(largest_im[i] * largest_im[j]));
        out[i * inputs + j][g] = std::min(magnitude * std::sqrt(scale[i] * scale[j]), dissipation * size);
      }
  return out;
}

// Row l's bound at every grid frequency and entry, |2 c_i c_j / N²| / |s − p|, against the allowance there: into
// `out` (entries × grid, row-major), and its largest.
double shares(const rc::ModeTable& t, int l, const std::vector<std::vector<double>>& allow, std::size_t inputs,
              std::vector<double>& out) {
  const std::vector<cd> c = couplings(t, l);
  const cd p = pole(t, l);
  const double n2 = std::abs(t.N2[static_cast<std::size_t>(l)]);
  out.assign(inputs * inputs * kGrid, 0.0);
  std::vector<double> top(inputs * inputs);
  for (std::size_t e = 0; e < top.size(); ++e) top[e] = std::abs(2.0 * c[e / inputs] * c[e % inputs]) / n2;
  double worst = 0;
  for (std::size_t g = 0; g < static_cast<std::size_t>(kGrid); ++g) {
    const double far = std::sqrt(std::norm(grid_point(t, static_cast<int>(g)) - p));
    for (std::size_t e = 0; e < top.size(); ++e) {
      const double a = allow[e][g];
      const double v = a > 0 ? top[e] / far / a : HUGE_VAL;
      out[e * kGrid + g] = v;
      worst = std::max(worst, v);
    }
  }
  return worst;
}

}  // namespace

bool prunable(const rc::ModeTable& t, const CavitySpec& cav) {
  // The Krylov table's solver line names its --exact-at frequencies (modes/app/galerkin_response_table.cpp).
  const bool exact = t.solver.find("(--exact-at)") != std::string::npos;
  return t.response_fit() && cav.prune && !cav.modes && !cav.coverage && !cav.galerkin && !exact &&
         !t.volume_cavity.present() && !t.volume_free_surface.present();
}

PrunedRows prune_response_rows(const rc::ModeTable& t, const std::vector<int>& rows, double magnitude,
                               double dissipation) {
  PrunedRows out;
  out.kept = rows;
  if (!t.response_fit() || !(t.fit_error > 0) || rows.empty()) return out;
  const std::size_t inputs = t.free_surface.present() ? 2 : 1;
  const auto allow = allowances(t, inputs, magnitude * t.fit_error, dissipation);
  // Each row's largest share first (its whole profile is made again when it comes to be left out: rows × grid
  // doubles would be tens of MB for a thousand rows).
  std::vector<double> worst(rows.size()), share;
  for (std::size_t r = 0; r < rows.size(); ++r) worst[r] = shares(t, rows[r], allow, inputs, share);
  // The smallest first, while every entry's sum stays within its allowance at every grid frequency.
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return worst[a] < worst[b]; });
  std::vector<double> used(inputs * inputs * kGrid, 0.0);
  std::vector<bool> drop(rows.size(), false);
  for (const std::size_t r : order) {
    if (!(worst[r] <= 1)) break;
    shares(t, rows[r], allow, inputs, share);
    bool fits = true;
    for (std::size_t k = 0; k < used.size() && fits; ++k) fits = used[k] + share[k] <= 1.0;
    if (!fits) break;
    for (std::size_t k = 0; k < used.size(); ++k) used[k] += share[k];
    drop[r] = true;
  }
  out.kept.clear();
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (drop[r]) ++out.dropped;
    else out.kept.push_back(rows[r]);
  return out;
}

}  // namespace rc::rom
