#include "cavity_response.hpp"

#include "atomic_file.hpp"
#include "cavity_table.hpp"
#include "discretisation.hpp"
#include "free_surface.hpp"
#include "free_surface_mesh.hpp"
#include "free_surface_quadratic.hpp"
#include "partial_fill_cylinder.hpp"
#include "partial_fill_table.hpp"
#include "offset_rows.hpp"
#include "ideal_response.hpp"
#include "petsc_handles.hpp"
#include "progress.hpp"
#include "response_samples.hpp"
#include "table_assembly.hpp"
#include "separable_table.hpp"
#include "viscous_mesh.hpp"
#include "viscous_response.hpp"
#include "viscous_table.hpp"
#include "window_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace rc::modes {
namespace {

// Σ E_l/(σ − λ_l) over every eigenpair of the separated cylinder problem.
CavityResponse separable_response(const ResponseRequest& req) {
  if (req.shape.kind != "cylinder") throw std::runtime_error("--method separable is for cylinders only");
  const SeparableGrid grid = separable_grid(req.shape, req.mesh);
  const SeparableSpectrum s =
      solve_separable_cylinder(req.shape.dims.at("radius"), req.shape.dims.at("height"), grid);
  CavityResponse out;
  for (const auto sigma : req.sigmas) {
    std::complex<double> R = 0;
    for (const auto& m : s.modes) R += m.E / (sigma - m.lambda);
    out.R.push_back(R);
  }
  out.method = fmt::format("ideal fluid, sum of E/(sigma - lambda) over all {} eigenpairs of the separable cylinder "
                           "(order {}, {} x {} elements; sum of E = {:.12g}, A_f - J_zh = {:.12g})",
                           s.modes.size(), grid.order, grid.radial_elements(), grid.axial_elements(), s.sum_E,
                           s.sum_rule);
  return out;
}

CavityResponse mesh_response(const ResponseRequest& req) {
  const Discretisation d(req.shape, mesh_method_defaults(req.shape, req.mesh));
  CavityResponse out;
  out.R = ideal_response(d.velocity, d.forms, req.sigmas);
  out.method = fmt::format("ideal fluid, forced solves of the Poincare problem (no modes) on P{} elements of size {:g}, "
                           "{} pressure unknowns; A_f - J_zh = {:.12g}",
                           d.space.order(), d.space.mesh().size, d.space.ndof(), d.sum_rule);
  return out;
}

// Progress lines go to stderr on rank 0 only.
void stderr_on_root(const std::string& line) {
  if (is_root_rank()) std::cerr << line << "\n";
}

// The ideal response sums over every pair: the dense solver only, up to its own limit (free_surface_mesh.hpp).
constexpr int kDenseResponseUnknowns = 4000;

// A partially filled tank's ideal response: the sums over EVERY pair (the separable cylinder's, or the mesh method's
// dense solver) of 2a²/(σ − λ), 2at/(σ − λ), 2t²/(σ − λ) (free_surface_coupling.hpp).
CavityResponse partially_filled_ideal_response(const ResponseRequest& req) {
  const geometry::ShapeSpec liquid = geometry::partially_filled(req.shape, req.fill);
  PartialFillSpectrum s;
  if (req.separable) {
    if (req.shape.kind != "cylinder" || req.shape.dims.count("inner_radius"))
      throw std::runtime_error("--fill --method separable: a plain cylinder only (the mesh method takes the others)");
    const double R = req.shape.dims.at("radius"), H = req.shape.dims.at("height");
    geometry::ShapeSpec annulus = req.shape;
    annulus.dims["inner_radius"] = liquid.dims.at("free_radius");
    s = solve_partially_filled_cylinder(R, H, req.fill, separable_grid(annulus, req.mesh));
  } else {
    geometry::MeshOptions mesh = req.mesh;
    if (mesh.size == 0) mesh.size = geometry::default_mesh_size(liquid) * kFreeSurfaceSizeFactor;
    s = solve_partially_filled_mesh(FESpace(geometry::mesh_meridian(liquid, mesh)), kDenseResponseUnknowns);
  }
  CavityResponse out;
  for (const auto sigma : req.sigmas) {
    std::complex<double> ff = 0, fg = 0, gg = 0;
    for (const auto& p : s.pairs) {
      if (p.coupling.E == 0 && p.coupling.t == 0) continue;  // the geostrophic λ = 0: no coupling
      const std::complex<double> w = 2.0 / (sigma - p.lambda);
      ff += w * p.coupling.a * p.coupling.a;
      fg += w * p.coupling.a * p.coupling.t;
      gg += w * p.coupling.t * p.coupling.t;
    }
    out.R.push_back(ff);
    out.R_fg.push_back(fg);
    out.R_gg.push_back(gg);
  }
  out.method = fmt::format("ideal fluid, partially filled (fill {:g}, free surface r = {:.10g}): the sums over all {} "
                           "eigenpairs of the {} (sum of E - (A_f + K2 - J_zh) = {:.1e} relative)", req.fill,
                           s.surface_radius, s.pairs.size(), req.separable ? "separable cylinder" : "mesh method",
                           (s.sum_E - s.sum_rule) / s.sum_rule);
  return out;
}

// A partially filled tank's viscous response by forced solves on the liquid's mesh (its free surface stress-free).
CavityResponse partially_filled_viscous_response(const ResponseRequest& req) {
  const geometry::ShapeSpec liquid = geometry::partially_filled(req.shape, req.fill);
  const ViscousForms forms = assemble_cavity_forms(liquid, req.mesh, req.ekman);
  Progress lines(stderr_on_root);
  ForcedResponse response(forms);
  CavityResponse out;
  for (std::size_t k = 0; k < req.sigmas.size(); ++k) {
    const OffsetResponse r = response.with_offset(req.sigmas[k]);
    out.R.push_back(r.ff);
    out.R_fg.push_back(r.fg);
    out.R_gg.push_back(r.gg);
    lines.step(fmt::format("cavity-modes response: {}/{} frequencies", k + 1, req.sigmas.size()), k + 1,
               req.sigmas.size());
  }
  out.unknowns = 2L * forms.complex_size;
  out.method = fmt::format("viscous fluid, Ekman number {:g}, partially filled (fill {:g}, free surface stress-free): "
                           "forced solves on Taylor-Hood P{}/P{} ({} real unknowns); R = sum_l E_l/(sigma - lambda_l) + "
                           "const", req.ekman, req.fill, req.mesh.order, req.mesh.order - 1, out.unknowns);
  return out;
}


// R at req.sigmas from forms assembled once (assemble_cavity_forms), a progress line per frequency through the run's
// `lines` ("<label>: 3/40 frequencies"; `left_of` says what the time left is of when more counts follow). With
// `kept`, the frequencies it holds are read from it and every new solve is added to it as soon as it is made. With
// `split` (forms assembled on PETSC_COMM_SELF under mpirun) each rank solves every ranks-th frequency on its own
// and the answers are summed over the ranks: the frequencies, not the matrices, are shared out.
// A partially filled tank's response about a point at height −c below the liquid's centroid.
std::complex<double> about(const OffsetResponse& r, double c) { return r.ff + 2 * c * r.fg + c * c * r.gg; }

CavityResponse viscous_cavity_response(const ResponseRequest& req, const ViscousForms& forms, Progress& lines,
                                       const std::string& label, const std::string& left_of = "",
                                       ResponseSamples* kept = nullptr, bool split = false) {
  CavityResponse out;
  out.R.resize(req.sigmas.size());
  std::vector<std::size_t> missing;
  for (std::size_t k = 0; k < req.sigmas.size(); ++k)
    if (!kept || !kept->find(req.sigmas[k], out.R[k])) missing.push_back(k);
  int rank = 0, ranks = 1;
  if (split) {
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    ranks = world_ranks();
  }
  if (!missing.empty()) {
    ForcedResponse response(forms);
    std::vector<double> mine(2 * missing.size(), 0.0), all(2 * missing.size(), 0.0);
    for (std::size_t i = static_cast<std::size_t>(rank); i < missing.size(); i += static_cast<std::size_t>(ranks)) {
      const std::size_t k = missing[i];
      const std::complex<double> R = req.offset == 0 ? response(req.sigmas[k]) : about(response.with_offset(req.sigmas[k]), req.offset);
      mine[2 * i] = R.real();
      mine[2 * i + 1] = R.imag();
      if (kept && !split) kept->add(req.sigmas[k], R);
      lines.step(fmt::format("{}: {}/{} frequencies", label, i + 1, missing.size()), i + 1, missing.size(), left_of);
    }
    if (split) MPI_Allreduce(mine.data(), all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    else all = mine;
    for (std::size_t i = 0; i < missing.size(); ++i) {
      out.R[missing[i]] = {all[2 * i], all[2 * i + 1]};
      if (kept && split) kept->add(req.sigmas[missing[i]], out.R[missing[i]]);
    }
  }
  out.unknowns = 2L * forms.complex_size;
  out.method = fmt::format("viscous fluid, Ekman number {:g}, forced solves on Taylor-Hood P{}/P{} ({} real unknowns); "
                           "R = sum_l E_l/(sigma - lambda_l) + const",
                           req.ekman, req.mesh.order, req.mesh.order - 1, out.unknowns);
  return out;
}

// One complex number: "a", "a+bi", "a-bi", "bi" (no spaces).
std::complex<double> parse_complex(const std::string& item) {
  const auto bad = [&] { return std::runtime_error("--sigma item '" + item + "' is not a complex number like 0.5+0.1i"); };
  if (item.empty()) throw bad();
  std::size_t used = 0;
  double a = 0, b = 0;
  try {
    a = std::stod(item, &used);
  } catch (...) {
    throw bad();
  }
  if (used == item.size()) return {a, 0};
  if (item.substr(used) == "i") return {0, a};
  if (item.back() != 'i' || (item[used] != '+' && item[used] != '-')) throw bad();
  const std::string rest = item.substr(used, item.size() - used - 1);
  std::size_t used_b = 0;
  try {
    b = std::stod(rest, &used_b);
  } catch (...) {
    throw bad();
  }
  if (used_b != rest.size()) throw bad();
  return {a, b};
}

}  // namespace

void serve_response(const ResponseRequest& req, std::istream& in, std::ostream& out) {
  if (!(req.ekman > 0)) throw std::runtime_error("--serve needs --ekman (the ideal response has its modes' closed sum)");
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  if (ranks > 1) throw std::runtime_error("--serve runs on one rank (it reads standard input)");
  // A partially filled tank: the liquid's part of the cavity, and each answer R, R_fg, R_gg (viscous_response.hpp).
  const bool offset = req.fill < 1;
  geometry::MeshOptions used = req.mesh;
  const ViscousForms forms = assemble_cavity_forms(offset ? geometry::partially_filled(req.shape, req.fill) : req.shape,
                                                   req.mesh, req.ekman, PETSC_COMM_WORLD, &used);
  ForcedResponse response(forms);
  out << fmt::format("ready: viscous fluid, Ekman number {:g}, {}forced solves on Taylor-Hood P{}/P{} ({} real unknowns)"
                     " [mesh: {}]",
                     req.ekman, offset ? fmt::format("partially filled (fill {:g}; R R_fg R_gg), ", req.fill) : "",
                     req.mesh.order, req.mesh.order - 1, 2L * forms.complex_size, mesh_text(used))
      << std::endl;
  std::string line;
  while (std::getline(in, line) && !line.empty()) {
    try {
      const std::complex<double> sigma = parse_complex(line);
      if (!std::isfinite(sigma.real()) || !std::isfinite(sigma.imag())) throw std::runtime_error("sigma must be finite");
      if (offset) {
        const OffsetResponse r = response.with_offset(sigma);
        out << fmt::format("{:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}", r.ff.real(), r.ff.imag(), r.fg.real(),
                           r.fg.imag(), r.gg.real(), r.gg.imag())
            << std::endl;
        continue;
      }
      const std::complex<double> R = response(sigma);
      out << fmt::format("{:.17g} {:.17g}", R.real(), R.imag()) << std::endl;
    } catch (const std::exception& e) {
      std::string why = e.what();
      std::replace(why.begin(), why.end(), '\n', ' ');
      out << "error: " << why << std::endl;
    }
  }
}

CavityResponse compute_cavity_response(const ResponseRequest& req) {
  if (req.sigmas.empty()) throw std::runtime_error("no frequency sigma given");
  for (const auto s : req.sigmas)
    if (!std::isfinite(s.real()) || !std::isfinite(s.imag())) throw std::runtime_error("every sigma must be finite");
  if (req.fill < 1) return req.ekman > 0 ? partially_filled_viscous_response(req) : partially_filled_ideal_response(req);
  if (req.ekman > 0) {  // under mpirun the frequencies are shared out, as for a response table
    const bool split = world_ranks() > 1 && req.sigmas.size() > 1;
    Progress lines(stderr_on_root);
    return viscous_cavity_response(
        req, assemble_cavity_forms(req.shape, req.mesh, req.ekman, split ? PETSC_COMM_SELF : PETSC_COMM_WORLD), lines,
        "cavity-modes response", "", nullptr, split);
  }
  return req.separable ? separable_response(req) : mesh_response(req);
}

void check_response_window(const ResponseRequest& req, const std::string& what) {
  if (!(req.ekman > 0)) throw std::runtime_error(what + " (-o FILE.h5) needs --ekman");
  const std::size_t n = req.sigmas.size();
  if (n < 9) throw std::runtime_error(what + " needs --sigma FROM:TO:N with N >= 9 real frequencies");
  for (std::size_t k = 0; k < n; ++k)
    if (req.sigmas[k].imag() != 0 || (k > 0 && !(req.sigmas[k].real() > req.sigmas[k - 1].real())))
      throw std::runtime_error(what + " needs increasing real frequencies (--sigma FROM:TO:N, no --sigma-imag)");
}

namespace {

// A partially filled tank's frozen liquid, Zhukovsky's inertia and the /free_surface attributes: the ideal problem's
// integrals on the liquid's default mesh, as the ideal --fill table's (no eigenpairs: free_surface_quadratic.hpp).
ModeTable partially_filled_start(const ResponseRequest& req) {
  const geometry::ShapeSpec liquid = geometry::partially_filled(req.shape, req.fill);
  geometry::MeshOptions mesh;
  mesh.order = 6;
  mesh.size = geometry::default_mesh_size(liquid) * kFreeSurfaceSizeFactor;
  const FESpace space(geometry::mesh_meridian(liquid, mesh));
  const PartialFillSpectrum s = spectrum_integrals(space, free_surface_quadratic(space));
  ModeTable t = start_table(req.shape, s.fluid, s.J_D);
  t.sum_rule = s.sum_rule;
  t.free_surface = free_surface_attributes(s, req.fill);
  return t;
}

}  // namespace

ModeTable response_table_start(const ResponseRequest& req, long unknowns) {
  ModeTable t;
  if (req.fill < 1) {
    t = partially_filled_start(req);
  } else {
    // The frozen-fluid integrals and J_zh: the ideal problem on the shape's default mesh.
    rc::geometry::MeshOptions ideal_mesh;
    ideal_mesh.order = 6;
    const Discretisation d(req.shape, mesh_method_defaults(req.shape, ideal_mesh));
    t = start_table(req.shape, d.fluid, d.zhukovsky.J_zh);
  }
  t.ekman = req.ekman;
  t.fe_order = req.mesh.order;
  t.mesh_h = req.mesh.size;
  t.mesh_h_wall = req.mesh.wall_size;
  t.mesh_h_near_wall = req.mesh.near_wall_size;
  t.ndof = unknowns;
  t.fit_lo = req.sigmas.front().real();
  t.fit_hi = req.sigmas.back().real();
  return t;
}

namespace {

// The response's kept forced solves (viscous/response_samples.hpp): those of an earlier run of the same cavity, mesh
// and Ek are read back and said so; none when the request keeps none.
ResponseSamples kept_samples(const ResponseRequest& req, const ViscousForms& forms) {
  if (req.samples_file.empty()) return {};
  ResponseSamples kept(req.samples_file, response_samples_key(req.shape, req.mesh, req.ekman, 2L * forms.complex_size));
  if (kept.read() > 0 && is_root_rank())
    std::cerr << fmt::format("cavity-modes response: {} forced solves read back from {}\n", kept.read(),
                             kept.path().string());
  return kept;
}

// A fit that misses its tolerance: what to change and what it costs (the solves made so far are kept, so a retry pays
// only for new frequencies).
std::string fit_failure(double lo, double hi, double err, double max_error, int refinements, std::size_t solved,
                        std::size_t window, const ResponseSamples& kept,
                        std::chrono::steady_clock::time_point solve_start) {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - solve_start).count();
  const std::size_t new_solves = std::max<std::size_t>(kept.added(), 1);
  const std::string kept_note =
      kept.path().empty() ? std::string()
                          : fmt::format("; its {} forced solves are kept in {} and read back by the same command, so "
                                        "a retry pays only for new frequencies (about {:.2g} s each here)",
                                        solved, kept.path().string(), seconds / static_cast<double>(new_solves));
  return fmt::format("the rational fit of R(s) on [{:g}, {:g}] errs by {:.2g} between its samples after {} refinements "
                     "({} samples; allowed {:.2g}): give more frequencies N or a larger --max-fit-error (at least "
                     "{:.2g}){}", lo, hi, err, refinements, window, max_error, err, kept_note);
}

}  // namespace

namespace {

// One rational fit of R on the request's window (at its offset with a free surface) by the finite elements' forced
// solves, refined where it errs or is not passive (viscous/window_fit.hpp); throws (fit_failure) when the error stays
// above max_error. `first` receives the first samples' response (its method line and unknowns).
WindowedFit fe_window_fit(const ResponseRequest& req, const ViscousForms& forms, ResponseSamples& kept, bool split,
                          const std::vector<double>& tail, double max_error, Progress& lines, CavityResponse& first) {
  const auto solve_start = std::chrono::steady_clock::now();
  std::size_t solved = 0;
  const ResponseSampler sample = [&](const std::vector<double>& s, const std::string& round) {
    ResponseRequest at = req;
    at.sigmas.assign(s.begin(), s.end());
    const bool first_round = round == "first samples";
    // The run's one clock: the time left is this round's, and the number of rounds is not known in advance.
    CavityResponse r = viscous_cavity_response(at, forms, lines, "response fit: " + round,
                                               first_round ? " for the first samples (refinements may follow)"
                                                           : " in this round (more rounds may follow)",
                                               &kept, split);
    solved += s.size();
    if (first_round) first = r;
    return r.R;
  };
  std::vector<double> window;
  for (const auto& sigma : req.sigmas) window.push_back(sigma.real());
  const WindowedFit w = fit_on_window(sample, window, tail, max_error, [&](const std::string& l) { lines.note(l); });
  if (!(w.error <= max_error))
    throw std::runtime_error(fit_failure(window.front(), window.back(), w.error, max_error, w.refinements, solved,
                                         w.samples, kept, solve_start));
  return w;
}

// The offsets (table units) at which a partially filled tank's response is fitted: R(c) is quadratic in c, so three
// fits determine it at every c by Lagrange interpolation, ℓ_i(c) = α_i + β_i c + γ_i c² (docs/viscous.md, "Response
// tables of a partially filled tank").
constexpr std::array<double, 3> kFitOffsets{-1.0, 0.0, 1.0};
constexpr std::array<std::array<double, 3>, 3> kLagrange{{{0.0, -0.5, 0.5}, {1.0, 0.0, -1.0}, {0.0, 0.5, 0.5}}};

// A partially filled tank's three fits as rows: fit i's pole p with residue r contributes r ℓ_i(c)/(s − p), a residue
// matrix r [[α_i, β_i/2], [β_i/2, γ_i]] written as two rows (offset_rows). Returns the residues' sum about the centroid.
std::complex<double> add_offset_pseudo_modes(ModeTable& t, const std::array<WindowedFit, 3>& fits, double err) {
  std::complex<double> sum = 0;
  for (std::size_t i = 0; i < fits.size(); ++i)
    for (std::size_t j = 0; j < fits[i].fit.poles.size(); ++j) {
      const std::complex<double> r = fits[i].fit.residues[j];
      const auto& l = kLagrange[i];
      add_offset_rows(t, fits[i].fit.poles[j], r * l[0], r * (0.5 * l[1]), r * l[2], err);
      sum += r * l[0];
    }
  return sum;
}

// `cavity-modes response --fill --fit`: the three fits at kFitOffsets, each refined and scanned as a filled cavity's
// fit is; their forced solves are not kept in FILE.h5.samples (its key is the filled response's).
ModeTable partially_filled_fit_table(const ResponseRequest& req, double max_error, const std::vector<double>& tail,
                                     bool split, Progress& lines, std::chrono::steady_clock::time_point start) {
  const ViscousForms forms = assemble_cavity_forms(geometry::partially_filled(req.shape, req.fill), req.mesh, req.ekman,
                                                   split ? PETSC_COMM_SELF : PETSC_COMM_WORLD);
  ResponseSamples none;
  std::array<WindowedFit, 3> fits;
  CavityResponse first;
  for (std::size_t i = 0; i < fits.size(); ++i) {
    ResponseRequest at = req;
    at.offset = kFitOffsets[i];
    CavityResponse first_at;
    fits[i] = fe_window_fit(at, forms, none, split, tail, max_error, lines, first_at);
    if (i == 1) first = first_at;
  }
  const double lo = req.sigmas.front().real(), hi = req.sigmas.back().real();
  double err = 0;
  std::string each;
  for (std::size_t i = 0; i < fits.size(); ++i) {
    err = std::max(err, fits[i].error);
    each += fmt::format("{}c = {:g}: AAA degree {}, {} poles kept, {} dropped, {} samples, {} refinements, error {:.2g}, "
                        "{}", i ? "; " : "", kFitOffsets[i], fits[i].fit.aaa_degree, fits[i].fit.poles.size(),
                        fits[i].fit.dropped_poles, fits[i].samples, fits[i].refinements, fits[i].error,
                        passivity_phrase(fits[i].fit, lo, hi));
  }
  ModeTable t = response_table_start(req, first.unknowns);
  t.fit_error = err;
  const std::complex<double> sum = add_offset_pseudo_modes(t, fits, err);
  t.coverage = t.sum_rule > 0 ? sum.real() / t.sum_rule : 1.0;
  t.normalisation = "pseudo-modes of three rational fits of a partially filled tank's R(c) about points at heights "
                    "-c = 1, 0, -1 below the liquid's centroid, combined by their quadratic interpolation in c: each "
                    "pole's residue matrix as two rows, 2 (a + c t)^2 each (docs/viscous.md, \"Response tables of a "
                    "partially filled tank\")";
  t.solver = fmt::format("AAA rational fits of R(c) on [{:g}, {:g}] and {} beyond it up to |s| = {:.3g} at c = -1, 0, "
                         "1 ({}); sum of residues about the centroid {:.9g}{:+.9g}i, A_f + K2 - J_zh = {:.9g}; R by {}",
                         lo, hi, tail.size(), std::abs(tail.back()), each, sum.real(), sum.imag(), t.sum_rule,
                         first.method);
  t.tolerance = 1e-10;
  t.sort_by_energy();
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

}  // namespace

ModeTable response_fit_table(const ResponseRequest& req, double max_error) {
  const auto start = std::chrono::steady_clock::now();
  check_response_window(req, "a response-fit table");
  const std::size_t n = req.sigmas.size();
  // Beyond the window the fit must still fall off as R ~ (its weight)/s, as R does (docs/viscous.md, "Response
  // fit"): without samples there AAA may spend a pole far off with a huge residue on the window's near-constant
  // background, a pseudo-mode whose coupling E would swamp the chain's inertia. So R is also sampled on a
  // geometric tail on both sides (response_tail), which the fit matches but the window's error does not count.
  const double lo = req.sigmas.front().real(), hi = req.sigmas.back().real();
  const std::vector<double> tail = response_tail(lo, hi);
  // Under mpirun the frequencies are shared out, each rank with the whole problem (a response table solves 100 and
  // more of them, which a distributed factorisation on 2 cores does not speed up).
  const bool split = world_ranks() > 1;
  Progress lines(stderr_on_root);  // one clock for the whole fit: assembly, first samples, refinements
  if (req.fill < 1) return partially_filled_fit_table(req, max_error, tail, split, lines, start);
  const ViscousForms forms =  // once, for every refinement
      assemble_cavity_forms(req.shape, req.mesh, req.ekman, split ? PETSC_COMM_SELF : PETSC_COMM_WORLD);
  // Every forced solve is kept as it is made: a fit that misses its tolerance, or a stopped run, loses none of them.
  ResponseSamples kept = kept_samples(req, forms);
  CavityResponse first;
  const WindowedFit w = fe_window_fit(req, forms, kept, split, tail, max_error, lines, first);
  const RationalFit& fit = w.fit;
  const double err = w.error;

  ModeTable t = response_table_start(req, first.unknowns);
  t.fit_error = err;
  const std::complex<double> sum = add_pseudo_modes(t, fit, err);
  t.coverage = t.sum_rule > 0 ? sum.real() / t.sum_rule : 1.0;
  t.normalisation = "pseudo-modes of a rational fit: lambda + i decay a pole of R(s), E + i E_imag its residue, "
                    "a + i a_imag = sqrt((E + i E_imag)/2), N2 = 1 (docs/viscous.md, \"Response fit\")";
  t.solver = fmt::format("AAA rational fit of R(s) (degree {}, {} poles kept, {} dropped) on every other of {} real "
                         "samples in [{:g}, {:g}] ({} given, {} refinements where the fit erred) and {} beyond it up to |s| = {:.3g}, max error between the window's samples {:.2g}; "
                         "{}; sum of residues {:.9g}{:+.9g}i, s R(s) at s = {:.3g}: {:.9g}, A_f - J_zh = {:.9g}; R by {}",
                         fit.aaa_degree, fit.poles.size(), fit.dropped_poles, w.samples, lo, hi, n,
                         w.refinements, tail.size(), std::abs(tail.back()), err,
                         passivity_phrase(fit, lo, hi), sum.real(), sum.imag(), tail.back(),
                         (tail.back() * w.tail_R).real(), t.sum_rule, first.method);
  if (kept.read() > 0) t.solver += fmt::format(" ({} forced solves were at hand from an earlier run's kept samples)",
                                               kept.read());
  t.tolerance = 1e-10;
  t.sort_by_energy();
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

std::vector<std::complex<double>> parse_sigma_spec(const std::string& spec, double imag) {
  if (!std::isfinite(imag)) throw std::runtime_error("--sigma-imag must be finite");
  std::vector<std::complex<double>> s;
  if (spec.find(':') == std::string::npos) {
    if (imag != 0) throw std::runtime_error("--sigma-imag applies to a range FROM:TO:N, not to a list of sigmas");
    std::stringstream in(spec);
    std::string item;
    while (std::getline(in, item, ',')) s.push_back(parse_complex(item));
    if (s.empty() || s.size() > 100000 || spec.back() == ',')
      throw std::runtime_error("--sigma '" + spec + "' is neither FROM:TO:N nor a list of 1 to 100000 complex numbers");
    for (const auto z : s)
      if (!std::isfinite(z.real()) || !std::isfinite(z.imag())) throw std::runtime_error("every sigma must be finite");
    return s;
  }
  double from = 0, to = 0;
  long n = 0;
  char c1 = 0, c2 = 0, extra = 0;
  if (std::sscanf(spec.c_str(), "%lf%c%lf%c%ld%c", &from, &c1, &to, &c2, &n, &extra) != 5 || c1 != ':' || c2 != ':' ||
      !std::isfinite(from) || !std::isfinite(to) || n < 1 || n > 100000 || (n > 1 && !(to > from)))
    throw std::runtime_error("--sigma '" + spec + "' is not FROM:TO:N with finite FROM < TO and 1 <= N <= 100000");
  for (long k = 0; k < n; ++k) s.emplace_back(n == 1 ? from : from + (to - from) * k / (n - 1), imag);
  return s;
}

void write_response(const std::string& path, const std::vector<std::complex<double>>& sigma, const CavityResponse& R) {
  const bool offset = !R.R_fg.empty();
  write_text_atomically(path, [&](std::ostream& out) {
    out << "# cavity-modes response: " << R.method << "\n# R(sigma) = sum_l E_l/(sigma - lambda_l) (docs/viscous.md, "
        << "\"Response function\")\n";
    if (offset)
      out << "# partially filled: R is about the liquid's centroid; about a point at height -c below it R + 2c R_fg + "
             "c^2 R_gg (docs/physics.md section 2, \"Partially filled tanks\")\n";
    out << "sigma_re,sigma_im,R_re,R_im" << (offset ? ",R_fg_re,R_fg_im,R_gg_re,R_gg_im" : "") << "\n";
    out.precision(17);
    for (std::size_t k = 0; k < sigma.size(); ++k) {
      out << sigma[k].real() << ',' << sigma[k].imag() << ',' << R.R[k].real() << ',' << R.R[k].imag();
      if (offset) out << ',' << R.R_fg[k].real() << ',' << R.R_fg[k].imag() << ',' << R.R_gg[k].real() << ',' << R.R_gg[k].imag();
      out << '\n';
    }
  });
}

}  // namespace rc::modes
