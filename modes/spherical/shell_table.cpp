#include "shell_table.hpp"

#include "petsc_handles.hpp"
#include "shell_response.hpp"
#include "window_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace rc::modes::spherical {
namespace {

// R at every s. Under mpirun each rank holds the whole (small) pencil and solves every ranks-th frequency, and the
// answers are summed over the ranks: a table solves hundreds of frequencies, which a factorisation distributed over
// 2 cores does not speed up (the finite elements' response fits share them out the same way).
std::vector<std::complex<double>> sample(ShellResponse& R, const std::vector<double>& s) {
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  const auto ranks = static_cast<std::size_t>(world_ranks());
  std::vector<double> mine(2 * s.size(), 0.0), all(2 * s.size(), 0.0);
  for (std::size_t k = static_cast<std::size_t>(rank); k < s.size(); k += ranks) {
    const std::complex<double> r = R(s[k]);
    mine[2 * k] = r.real();
    mine[2 * k + 1] = r.imag();
  }
  MPI_Allreduce(mine.data(), all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  std::vector<std::complex<double>> out;
  for (std::size_t k = 0; k < s.size(); ++k) out.emplace_back(all[2 * k], all[2 * k + 1]);
  return out;
}

// The truncation check's frequencies: every 4th of the window given and its last, a quarter of the solves (measured at
// Ek = 1e-6 on -2.5:2:181: the largest change 8.3e-9 of max|R| on all 181 samples and on these 46).
std::vector<double> check_frequencies(const std::vector<double>& w) {
  std::vector<double> out;
  for (std::size_t k = 0; k < w.size(); k += 4) out.push_back(w[k]);
  if (out.back() != w.back()) out.push_back(w.back());
  return out;
}

void check_window(const std::vector<double>& w) {
  if (w.size() < 9) throw std::invalid_argument("a response table needs at least 9 frequencies (--sigma FROM:TO:N)");
  for (std::size_t k = 1; k < w.size(); ++k)
    if (!(w[k] > w[k - 1])) throw std::invalid_argument("a response table needs increasing real frequencies");
}

std::string truncation_text(const ShellSettings& s) {
  return fmt::format("{} Chebyshev coefficients per scalar, lmax {}", s.radial, s.lmax);
}

}  // namespace

ModeTable shell_table_start(const ShellSettings& s) {
  const double ri = s.inner_radius, pi = std::numbers::pi;
  ModeTable t;
  t.shape = ri > 0 ? "shell" : "sphere";
  t.dimensions = ri > 0 ? std::map<std::string, double>{{"radius", 1.0}, {"inner_radius", ri}}
                        : std::map<std::string, double>{{"radius", 1.0}};
  t.m = 1;
  t.volume = 4 * pi / 3 * (1 - std::pow(ri, 3));
  t.centroid_z = 0;
  t.A_f = t.C_f = 8 * pi / 15 * (1 - std::pow(ri, 5));
  t.J_zh = 0;
  t.sum_rule = t.A_f;
  t.ekman = s.ekman;
  return t;
}

ShellTable shell_response_table(const ShellTableRequest& req, const std::function<void(const std::string&)>& note) {
  const auto start = std::chrono::steady_clock::now();
  check_window(req.window);
  ShellResponse fine(req.fine, PETSC_COMM_SELF);
  const ResponseSampler sampler = [&](const std::vector<double>& s, const std::string& round) {
    note(fmt::format("spectral response: {}, {} frequencies", round, s.size()));
    return sample(fine, s);
  };
  const std::vector<double> tail = response_tail(req.window.front(), req.window.back());
  const WindowedFit w = fit_on_window(sampler, req.window, tail, req.max_fit_error, note);
  const double lo = req.window.front(), hi = req.window.back();
  if (!(w.error <= req.max_fit_error))
    throw std::runtime_error(fmt::format("the rational fit of R(s) on [{:g}, {:g}] errs by {:.2g} between its samples "
                                         "after {} refinements ({} samples; allowed {:.2g}): give more frequencies N "
                                         "or a larger --max-fit-error (at least {:.2g})", lo, hi, w.error,
                                         w.refinements, w.samples, req.max_fit_error, w.error));
  // The truncation's error: R on the window given, solved again at the coarser truncation.
  const std::vector<double> checked = check_frequencies(req.window);
  note(fmt::format("spectral response: truncation check ({}), {} frequencies", truncation_text(req.check),
                   checked.size()));
  ShellResponse coarse(req.check, PETSC_COMM_SELF);
  const auto R_fine = sample(fine, checked), R_coarse = sample(coarse, checked);
  double scale = 0, change = 0;
  for (std::size_t k = 0; k < R_fine.size(); ++k) {
    scale = std::max(scale, std::abs(R_fine[k]));
    change = std::max(change, std::abs(R_fine[k] - R_coarse[k]));
  }
  ShellTable out;
  out.truncation_change = change / scale;
  ModeTable& t = out.table;
  t = shell_table_start(req.fine);
  t.ndof = 2L * fine.complex_unknowns();
  t.fit_lo = lo;
  t.fit_hi = hi;
  // The table's R is off the exact one by its fit's error and its truncation's: the larger stands for both.
  t.fit_error = std::max(w.error, out.truncation_change);
  const std::complex<double> sum = add_pseudo_modes(t, w.fit, t.fit_error);
  t.coverage = sum.real() / t.sum_rule;
  t.normalisation = "pseudo-modes of a rational fit: lambda + i decay a pole of R(s), E + i E_imag its residue, "
                    "a + i a_imag = sqrt((E + i E_imag)/2), N2 = 1 (docs/viscous.md, \"Response fit\")";
  t.solver = fmt::format(
      "AAA rational fit of R(s) (degree {}, {} poles kept, {} dropped) on every other of {} real samples in [{:g}, "
      "{:g}] ({} given, {} refinements) and {} beyond it up to |s| = {:.3g}, max error between the window's samples "
      "{:.2g}; {}; sum of residues {:.9g}{:+.9g}i, A_f = {:.9g}; R by spectral forced solves ({}, {} complex "
      "unknowns; docs/spherical.md), changed by {:.2g} of max|R| on {} of the window's samples against {}",
      w.fit.aaa_degree, w.fit.poles.size(), w.fit.dropped_poles, w.samples, lo, hi, req.window.size(), w.refinements,
      tail.size(), std::abs(tail.back()), w.error, passivity_phrase(w.fit, lo, hi), sum.real(), sum.imag(), t.sum_rule,
      truncation_text(req.fine), fine.complex_unknowns(), out.truncation_change, checked.size(),
      truncation_text(req.check));
  t.tolerance = 1e-10;
  t.sort_by_energy();
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace rc::modes::spherical
