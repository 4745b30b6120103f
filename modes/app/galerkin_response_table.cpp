#include "galerkin_response_table.hpp"

#include "free_surface.hpp"
#include "galerkin_projection.hpp"
#include "galerkin_response.hpp"
#include "krylov_response.hpp"
#include "machine_memory.hpp"
#include "offset_rows.hpp"
#include "passivity_scan.hpp"
#include "petsc_handles.hpp"
#include "progress.hpp"
#include "viscous_response.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <limits>
#include <stdexcept>

namespace rc::modes {
namespace {

using cd = std::complex<double>;

// R's largest values on the window, entry by entry: each entry's error is measured against its own (R_fg's against
// √(scale_ff scale_gg): it may vanish by symmetry), as the Krylov reduction measures it (krylov_response.hpp).
struct EntryScales {
  double ff = 0, gg = 0;
};

EntryScales window_scales(const std::vector<OffsetResponse>& R, std::size_t window) {
  EntryScales s;
  for (std::size_t k = 0; k < window; ++k) {
    s.ff = std::max(s.ff, std::abs(R[k].ff));
    s.gg = std::max(s.gg, std::abs(R[k].gg));
  }
  return s;
}

// max over (s, R) pairs and entries of |R_G − R| / scale.
double relative_error(const GalerkinReduction& g, const std::vector<cd>& s, const std::vector<OffsetResponse>& R,
                      const EntryScales& scale) {
  double worst = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const OffsetResponse r = g.entries(s[k]);
    worst = std::max(worst, std::abs(r.ff - R[k].ff) / scale.ff);
    if (scale.gg > 0)
      worst = std::max({worst, std::abs(r.fg - R[k].fg) / std::sqrt(scale.ff * scale.gg),
                        std::abs(r.gg - R[k].gg) / scale.gg});
  }
  return worst;
}

// R at the samples from the projection itself: R_xy = π yᵀx_x = π conj(x̄ᵀy), the solutions in the order
// forced_solutions made them (with a free surface x_f(s_k), x_g(s_k) for each sample).
std::vector<OffsetResponse> sample_entries(const GalerkinMatrices& g, std::size_t samples) {
  const bool offset = g.offset.size() > 0;
  std::vector<OffsetResponse> R;
  const auto at = [&](const Eigen::VectorXcd& v, std::size_t k) { return std::numbers::pi * std::conj(v[static_cast<Eigen::Index>(k)]); };
  for (std::size_t k = 0; k < samples; ++k)
    R.push_back(offset ? OffsetResponse{at(g.coupling, 2 * k), at(g.offset, 2 * k), at(g.offset, 2 * k + 1)}
                       : OffsetResponse{at(g.coupling, k), 0.0, 0.0});
  return R;
}

// R at frequencies by forced solves the basis never saw (its entries with a free surface).
std::vector<OffsetResponse> forced_entries(const ViscousForms& forms, const std::vector<cd>& s,
                                           const ResponseProgress& progress) {
  ForcedResponse response(forms);
  std::vector<OffsetResponse> R;
  for (const cd x : s) {
    R.push_back(forms.offset_coupling ? response.with_offset(x) : OffsetResponse{response(x), 0.0, 0.0});
    if (progress) progress(R.size(), s.size());
  }
  return R;
}

// The forced solutions are all kept until projected: refuse, with one line, a table whose solutions would take more
// than half of this machine's memory (per rank; a crash by the out-of-memory killer is no answer).
void check_basis_memory(const ViscousForms& forms, std::size_t samples) {
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  const double bytes = 2.0 * forms.complex_size * sizeof(double) * static_cast<double>(samples) / ranks;
  const double memory = machine_memory_bytes();
  if (memory > 0 && bytes > 0.5 * memory)
    throw std::runtime_error(fmt::format("a Galerkin response table keeps its {} forced solutions until it projects "
                                         "them: {:.1f} GB per rank, more than half of this machine's {:.1f} GB; give "
                                         "fewer samples N, a coarser mesh, or mpirun over more machines", samples,
                                         bytes / 1e9, memory / 1e9));
}

// The projection on the forced solutions at `samples` (freed once projected).
GalerkinMatrices project_on_forced_solutions(const ViscousForms& forms, const std::vector<cd>& samples,
                                             const ResponseProgress& progress) {
  const auto solutions = forced_solutions(forms, samples, progress, forms.offset_coupling.get() != nullptr);
  std::vector<Vec> basis;
  for (const auto& x : solutions) basis.push_back(*x);
  return project_on_modes(forms, basis);
}

// The Ritz pairs as the table's rows (E + i E_imag their Galerkin residues, a + i a_imag = √(E/2), N2 = 1), and the
// /galerkin block: their Gram and viscous matrices and couplings. Returns the residues' sum.
cd add_ritz_rows(ModeTable& t, const GalerkinReduction& red, double residual) {
  cd sum = 0;
  for (std::size_t l = 0; l < red.lambda.size(); ++l) {
    const cd p = red.lambda[l], r = red.residue[l], a = std::sqrt(r / 2.0);
    t.lambda.push_back(p.real());
    t.kappa.push_back(2 / p.real());
    t.decay.push_back(std::max(p.imag(), 0.0));  // ≥ 0 up to rounding (reduce_on_span refuses a growing one)
    t.E.push_back(r.real());
    t.E_imag.push_back(r.imag());
    t.a.push_back(a.real());
    t.a_imag.push_back(a.imag());
    t.N2.push_back(1.0);
    t.residual.push_back(std::max(residual, std::numeric_limits<double>::epsilon()));
    t.galerkin.coupling_re.push_back(red.coupling[static_cast<Eigen::Index>(l)].real());
    t.galerkin.coupling_im.push_back(red.coupling[static_cast<Eigen::Index>(l)].imag());
    sum += r;
  }
  for (Eigen::Index l = 0; l < red.gram.rows(); ++l)
    for (Eigen::Index k = 0; k < red.gram.cols(); ++k) {
      t.galerkin.gram_re.push_back(red.gram(l, k).real());
      t.galerkin.gram_im.push_back(red.gram(l, k).imag());
      t.galerkin.viscous_re.push_back(red.viscous(l, k).real());
      t.galerkin.viscous_im.push_back(red.viscous(l, k).imag());
    }
  GalerkinMatrices ritz;
  ritz.gram = red.gram;
  ritz.viscous = red.viscous;
  t.galerkin.dissipation_mismatch = dissipation_mismatch(ritz, red.lambda);
  return sum;
}

// A partially filled tank's Ritz pairs as rows: two per Ritz value (offset_rows), their t in /free_surface; no
// /galerkin block (its Ritz vectors would need both rows' couplings; chain-rom's reduction = "galerkin" refuses a
// partially filled tank). Returns the residues' sum about the centroid.
cd add_offset_ritz_rows(ModeTable& t, const GalerkinReduction& red, double residual) {
  cd sum = 0;
  for (std::size_t l = 0; l < red.lambda.size(); ++l) {
    add_offset_rows(t, red.lambda[l], red.residue[l], red.residue_fg[l], red.residue_gg[l], residual);
    sum += red.residue[l];
  }
  return sum;
}

// The rows of either reduction: a filled cavity's one per Ritz pair with /galerkin, a partially filled tank's two.
cd add_rows(ModeTable& t, const GalerkinReduction& red, double residual) {
  return red.residue_fg.empty() ? add_ritz_rows(t, red, residual) : add_offset_ritz_rows(t, red, residual);
}

// The sum rule's terms, as the table's report names them.
const char* sum_rule_name(const ModeTable& t) { return t.free_surface.present() ? "A_f + K2 - J_zh" : "A_f - J_zh"; }

// What a partially filled tank's rows are, for the table's normalisation line.
std::string offset_rows_note(const GalerkinReduction& red) {
  if (red.residue_fg.empty()) return {};
  return "; partially filled: each Ritz value's residues of R, R_fg, R_gg about the liquid's centroid form a symmetric "
         "2x2 matrix, written as two rows with its pole, 2 (a + c t)^2 each about a point at height -c below the "
         "centroid (docs/viscous.md, \"Response tables of a partially filled tank\"); no /galerkin block";
}

// The cavity the forms are assembled on: the liquid's part for a partially filled tank.
geometry::ShapeSpec liquid_of(const ResponseRequest& req) {
  return req.fill < 1 ? geometry::partially_filled(req.shape, req.fill) : req.shape;
}

// The passivity scan of R about the centroid and, with a free surface, of R_gg (the diagonal of the response matrix:
// each must have Im ≥ 0 on the real axis): the smaller minimum, relative to each one's largest value.
PassivityScan scan_rows(const GalerkinReduction& red, double lo, double hi) {
  PassivityScan scan = scan_passivity(red.lambda, red.residue, lo, hi);
  if (!red.residue_gg.empty()) {
    const PassivityScan gg = scan_passivity(red.lambda, red.residue_gg, lo, hi);
    if (gg.min_im < scan.min_im) scan = gg;
  }
  return scan;
}

}  // namespace

ModeTable galerkin_response_table(const ResponseRequest& req, double max_error) {
  const auto start = std::chrono::steady_clock::now();
  check_response_window(req, "a Galerkin response table");
  const double lo = req.sigmas.front().real(), hi = req.sigmas.back().real();
  std::vector<cd> samples = req.sigmas;
  for (const double t : response_tail(lo, hi)) samples.emplace_back(t, 0.0);
  std::vector<cd> midpoints;
  for (std::size_t k = 0; k + 1 < req.sigmas.size(); ++k)
    midpoints.emplace_back(0.5 * (req.sigmas[k].real() + req.sigmas[k + 1].real()), 0.0);

  const ViscousForms forms = assemble_cavity_forms(liquid_of(req), req.mesh, req.ekman);
  check_basis_memory(forms, samples.size() * (forms.offset_coupling ? 2 : 1));
  Progress lines([](const std::string& line) { if (is_root_rank()) std::cerr << line << "\n"; });
  const auto progress = [&](const char* what) {
    return [&lines, what](std::size_t done, std::size_t total) {
      lines.step(fmt::format("{} {}/{}", what, done, total), done, total);
    };
  };
  const GalerkinMatrices g =
      project_on_forced_solutions(forms, samples, progress("galerkin response: forced solve"));
  const GalerkinReduction red = reduce_on_span(g);

  // R at the samples from the projection; at the midpoints, by forced solves the basis never saw.
  const std::vector<OffsetResponse> R_samples = sample_entries(g, samples.size());
  const std::vector<OffsetResponse> mid_R = forced_entries(forms, midpoints, progress("galerkin response: check"));
  const EntryScales scale = window_scales(R_samples, req.sigmas.size());
  const double at_samples = relative_error(red, samples, R_samples, scale);
  const double between = relative_error(red, midpoints, mid_R, scale);
  if (!(between <= max_error))
    throw std::runtime_error(fmt::format("the Galerkin response errs by {:.2g} of max|R| between its samples on [{:g}, "
                                         "{:g}] (allowed {:.2g}): give more frequencies N or a larger --max-fit-error",
                                         between, lo, hi, max_error));

  ModeTable t = response_table_start(req, 2L * forms.complex_size);
  t.fit_error = between;
  const std::size_t n = red.lambda.size();
  const cd sum = add_rows(t, red, at_samples);
  t.coverage = t.sum_rule > 0 ? sum.real() / t.sum_rule : 1.0;
  const PassivityScan passivity = scan_rows(red, lo, hi);
  t.normalisation = "pseudo-modes of a Galerkin projection on forced solutions: lambda + i decay a Ritz value, E + "
                    "i E_imag the reduced response's residue there, a + i a_imag = sqrt((E + i E_imag)/2), N2 = 1; "
                    "/galerkin holds the Ritz vectors' Gram and viscous matrices and couplings f^T x (docs/viscous.md, "
                    "\"Galerkin response table\")" +
                    offset_rows_note(red);
  t.solver = fmt::format("Galerkin (Hermitian) projection on the forced solutions at {} real samples in [{:g}, {:g}] "
                         "and {} beyond it up to |s| = {:.3g} ({} directions dropped as dependent), {} Ritz pairs; R "
                         "matched at the samples to {:.2g} and between them (forced solves at the {} midpoints) to "
                         "{:.2g} of max|R|; min Im R on the window {:.2g} max|R|; sum of residues {:.9g}{:+.3g}i, "
                         "{} = {:.9g}; forced solves on Taylor-Hood P{}/P{}, {} real unknowns",
                         req.sigmas.size(), lo, hi, samples.size() - req.sigmas.size(), std::abs(samples.back()),
                         red.dropped, n, at_samples, midpoints.size(), between, passivity.min_im, sum.real(),
                         sum.imag(), sum_rule_name(t), t.sum_rule, req.mesh.order, req.mesh.order - 1,
                         2L * forms.complex_size);
  t.tolerance = 1e-10;
  t.sort_by_energy();
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

namespace {

// The window's frequencies and `per_gap` − 1 more between each two: where the reduction's estimate is scanned.
std::vector<double> refined_window(const std::vector<cd>& sigmas, int per_gap) {
  std::vector<double> out;
  for (std::size_t k = 0; k < sigmas.size(); ++k) {
    if (k > 0)
      for (int j = 1; j < per_gap; ++j)
        out.push_back(sigmas[k - 1].real() + (sigmas[k].real() - sigmas[k - 1].real()) * j / per_gap);
    out.push_back(sigmas[k].real());
  }
  return out;
}

// The tolerances a Krylov table was asked for, as the user gave them (Im R's only where it was a criterion).
std::string krylov_tolerances(double max_error, double max_decay_error) {
  return max_decay_error > 0 ? fmt::format("--max-fit-error {:.2g} or --max-decay-fit-error {:.2g}", max_error,
                                           max_decay_error)
                             : fmt::format("--max-fit-error {:.2g}", max_error);
}

}  // namespace

ModeTable krylov_response_table(const ResponseRequest& req, double max_error, double max_decay_error) {
  const auto start = std::chrono::steady_clock::now();
  check_response_window(req, "a Krylov response table");
  const double lo = req.sigmas.front().real(), hi = req.sigmas.back().real();
  const ViscousForms forms = assemble_cavity_forms(liquid_of(req), req.mesh, req.ekman);
  KrylovOptions options;
  options.tolerance = max_error;
  options.dissipation_tolerance = max_decay_error;
  options.exact_at = req.exact_at;
  const std::vector<double> window = refined_window(req.sigmas, 8), beyond = response_tail(lo, hi);
  const KrylovReduction k = krylov_reduction(forms, window, beyond, options, [](const std::string& line) {
    if (is_root_rank()) std::cerr << line << "\n";
  });
  const GalerkinReduction red = reduce_on_span(k.projection);

  ModeTable t = response_table_start(req, 2L * forms.complex_size);
  t.fit_error = std::max(k.estimate, k.check_error);
  t.fit_decay_error = std::max(k.dissipation_estimate, k.check_dissipation_error);
  t.fit_decay_s = window;
  t.fit_decay_profile = k.dissipation_profile;
  if (!k.within_tolerance && is_root_rank())
    std::cerr << fmt::format("cavity-modes response: warning: after {} expansion points the table errs by {:.2g} of "
                             "max|R| and its Im R by {:.2g} of itself, above {}; it is written with that error "
                             "(fit_error, fit_decay_error): larger ones, or a narrower window\n", k.points.size(),
                             t.fit_error, t.fit_decay_error, krylov_tolerances(max_error, max_decay_error));
  const cd sum = add_rows(t, red, t.fit_error);
  t.coverage = t.sum_rule > 0 ? sum.real() / t.sum_rule : 1.0;
  const PassivityScan passivity = scan_rows(red, lo, hi);
  t.normalisation = "pseudo-modes of a Galerkin projection on a rational Krylov space: lambda + i decay a Ritz value, "
                    "E + i E_imag the reduced response's residue there, a + i a_imag = sqrt((E + i E_imag)/2), N2 = 1; "
                    "/galerkin holds the Ritz vectors' Gram and viscous matrices and couplings f^T x (docs/viscous.md, "
                    "\"Krylov response table\")" +
                    offset_rows_note(red);
  t.solver = fmt::format("Galerkin (Hermitian) projection on a rational Krylov space: {} expansion points chosen "
                         "greedily on {} frequencies of [{:g}, {:g}] and {} beyond it up to |s| = {:.3g}, {} vectors "
                         "per point{}, {} basis vectors ({} directions dropped as dependent), {} Ritz pairs; estimated "
                         "error (bilinear against Hermitian projection) at most {:.2g} of max|R| and {:.2g} of Im R itself "
                         "on the window (against {:g} of its largest where it is smaller), measured by a forced solve at the worst "
                         "estimate s = {:.6g}: {:.2g} and {:.2g}{}; min Im R on the window {:.2g} max|R|; sum of "
                         "residues {:.9g}{:+.3g}i, {} = {:.9g}; forced solves on Taylor-Hood P{}/P{}, {} real "
                         "unknowns", k.points.size(), window.size(), lo, hi, beyond.size(), std::abs(beyond.back()),
                         options.vectors_per_point,
                         req.exact_at.empty() ? std::string()
                                              : fmt::format(", and {} more at the given frequencies (--exact-at), "
                                                            "where R is exact", req.exact_at.size()),
                         k.vectors, red.dropped, red.lambda.size(), k.estimate, k.dissipation_estimate,
                         options.dissipation_floor, k.check_point, k.check_error, k.check_dissipation_error,
                         k.within_tolerance ? "" : " (NOT within " + krylov_tolerances(max_error, max_decay_error) + ")",
                         passivity.min_im, sum.real(), sum.imag(), sum_rule_name(t), t.sum_rule,
                         req.mesh.order, req.mesh.order - 1, 2L * forms.complex_size);
  t.tolerance = 1e-10;
  t.sort_by_energy();
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

}  // namespace rc::modes
