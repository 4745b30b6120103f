// cavity-modes: mode tables of the rotating ideal fluid in an axisymmetric cavity (docs/physics.md §2, §4).
//
//   cavity-modes cylinder --radius 1 --height 2 [--order 4] [--mesh-size 0.2] [--modes N | --coverage c] -o cyl.h5
//   cavity-modes info cyl.h5 [--json]
//   cavity-modes compare cyl.h5 data/reference/cylinder_radius1_height2.csv [--tolerance 1e-6]
//   cavity-modes sphere --radius 1 --ekman 1e-4 -o visc.h5                      (viscous, docs/viscous.md)
//   cavity-modes response sphere --radius 1 --ekman 1e-4 --sigma 0.5:1.5:101 -o R.csv
//   cavity-modes response cylinder --radius 1 --height 2 --sigma 0.5+0.1i,1.2-0.05i -o R.csv   (ideal fluid)
// PETSc/SLEPc options (-pep_type ..., -log_view) pass through.
#include "cavity_table.hpp"
#include "free_surface.hpp"
#include "gmsh_library.hpp"
#include "convergence.hpp"
#include "command_line.hpp"
#include "empty_argument.hpp"
#include "mode_fields.hpp"
#include "mode_table_report.hpp"
#include "petsc_handles.hpp"
#include "reference_table.hpp"
#include "cavity_response.hpp"
#include "galerkin_response_table.hpp"
#include "shape_commands.hpp"
#include "stokes_series.hpp"
#include "table_comparison.hpp"
#include "table_provenance.hpp"
#include "viscous_table.hpp"
#include "volume_command.hpp"
#include "shell_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <unistd.h>

namespace {

using rc::modes::TableRequest;

// A request the command line cannot make (exit code 2, as CLI11's parse errors), found after parsing.
struct CommandLineError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// --ekman and --wall-size: the viscous table (docs/viscous.md); --sigma, --sigma-imag: `cavity-modes response`.
struct ViscousOptions {
  double ekman = 0;
  double wall_size = 0;
  double near_wall_size = 0;  // elements of this size just beyond the wall layers (MeshOptions::near_wall_size)
  double mesh_ekman = 0;   // the mesh as for this Ekman number (0: --ekman's); chain-rom's sweeps over spin
  bool no_shear_layers = false;  // tables: a uniform interior, not refined along the internal shear layers
  int refinements = 0;     // tables: refinement rounds while a row is not converged (ViscousTableSettings)
  std::string target;      // tables: the ideal frequencies to continue, instead of the survey's (--target)
  std::string sigma;       // FROM:TO:N (real parts) or a list of complex numbers
  double sigma_imag = 0;   // imaginary part of every σ
  // response to FILE.h5: the largest fit error accepted. 1e-4 keeps the chain's roots on the table within 1e-4 of those
  // on a 1e-6 table (measured 2026-12-03 at Ek 1e-6: 2e-7 to 8e-5 relative), ten times and more below the default
  // mesh's own error, in a third to half of the time (docs/viscous.md, "The default fit error").
  double max_fit_error = 1e-4;
  // response to FILE.h5, Krylov: the largest error of Im R relative to Im R itself on the window (0: measured and
  // reported only). Im R sets a chain root's decay and is a small part of |R| away from a resonance, so max_fit_error
  // alone left a 1e-7 table's decay 0.35 % off its own mesh's; 1e-3 brings it to 8e-6 but took 100 expansion points
  // and 22 min instead of 42 s, so it is not the default (docs/viscous.md, "The error of Im R").
  double max_decay_fit_error = 0;
  // response to FILE.h5: the Krylov response table (the default), a rational fit, or the Galerkin projection on
  // the forced solutions at the samples.
  bool krylov = false, fit = false, galerkin = false;
  std::string exact_at;         // response to FILE.h5, Krylov: complex frequencies where R must be exact
  bool serve = false;           // response: answer sigma lines on stdin with R on stdout (chain-rom confirm)
  bool stokes_series = false;   // response: print the strong-viscosity series' coefficients (stokes_series.hpp)
  int mesh_level = 0;           // response: every mesh size halved this many times (chain-rom confirm's mesh study)
};

// The mesh of every command; --radial-size and --method (auto|mesh|separable: auto is separable for a cylinder
// table without --fields, mesh otherwise; docs/modes.md) only where the shape is a cylinder.
// A default as people write it: 1e-6, not fmt's 1e-06.
std::string number(double v) {
  std::string s = fmt::format("{:g}", v);
  const auto e = s.find("e-0");
  if (e != std::string::npos) s.erase(e + 2, 1);
  return s;
}

void add_mesh_options(CLI::App* cmd, const std::string& kind, bool response, TableRequest& req, std::string& method) {
  const bool cylinder = kind == "cylinder";
  cmd->add_option("--order", req.mesh.order, cylinder ? "Lagrange order: mesh 1..6 (default 6), separable 1..12 "
                                                        "(default 10)"
                                                      : "Lagrange order 1..6 (default 6)");
  const char* size_help =
      cylinder ? "target element size, d = min(radius, height): mesh (default d/8); separable, along z (default 3d/8)"
      : kind == "sphere" || kind == "spheroid" ? "target element size, d the smallest semi-axis (default d/5)"
      : kind == "cone" ? "target element size, d = min(radius, height) (default d/8)"
                       : "target element size; the sizes the file gives its points are ignored (default 1/8 of the "
                         "smaller side of the section's bounding box)";
  cmd->add_option("--mesh-size", req.mesh.size, size_help);
  if (!cylinder) return;
  cmd->add_option("--radial-size", req.mesh.radial_size,
                  "element size along r: mesh, a structured mesh (--mesh-size is then the size along z); separable "
                  "(default max(d, radius/2)/8)");
  cmd->add_option("--method", method,
                  response ? "auto or mesh (forced solves on the gmsh mesh) or separable (the ideal fluid's "
                             "Σ E/(sigma - lambda) over every eigenpair of the separated problem) (default auto)"
                           : "auto (separable without --fields, else mesh), mesh (gmsh mesh of the meridian section) "
                             "or separable (exact separation on a tensor-product grid) (default auto)")
      ->check(CLI::IsMember({"auto", "mesh", "separable"}));
}

void add_viscous_options(CLI::App* cmd, ViscousOptions& viscous, bool response) {
  cmd->add_option("--ekman", viscous.ekman,
                  "viscous fluid with Ekman number Ek = nu/(omega0 L^2): damped modes (decay, complex coupling) "
                  "continuing the ideal ones, on a wall-graded Taylor-Hood mesh (docs/viscous.md); --order and "
                  "--mesh-size then set that mesh (order 6 and d/8 unless given; d/4 partially filled cylinders, finer "
                  "for filled spheres and cylinders at low Ek: docs/viscous.md, \"Interior size\")");
  cmd->add_option("--wall-size", viscous.wall_size, "with --ekman: element size at the wall (default Ek^(1/2))");
  cmd->add_option("--near-wall-size", viscous.near_wall_size,
                  "with --ekman: isotropic elements of this size from the wall layers' edge outwards, growing by 1 per "
                  "unit distance (0: none); a table's default: (Ek d)^(1/3), d the smallest dimension, for a cylinder "
                  "or a spheroid at Ek <= 1e-5, none otherwise (docs/viscous.md, \"Near-wall zone\")");
  cmd->add_option("--mesh-ekman", viscous.mesh_ekman,
                  "with --ekman: make the wall-layer mesh as for this Ekman number, at most --ekman (default --ekman): "
                  "one mesh for several Ekman numbers (chain-rom's sweeps over spin)");
  if (response) {
    cmd->add_option("--mesh-level", viscous.mesh_level,
                    "with --ekman: the same mesh with every size (interior, wall, near-wall zone) halved this many "
                    "times, a mesh study's finer levels (chain-rom confirm measures the roots' mesh error so: "
                    "docs/viscous.md, \"Mesh study of a response\") (default 0)")
        ->check(CLI::Range(0, 4));
    return;
  }
  cmd->add_flag("--no-shear-layers", viscous.no_shear_layers,
                "with --ekman, a sphere at Ek <= 1e-5 or a section at Ek <= 1e-4: do not refine the mesh along the "
                "internal shear layers from the critical latitudes (docs/viscous.md, \"Internal shear layers\")");
  cmd->add_option("--refine", viscous.refinements,
                  "with --ekman, a table: up to N refinement rounds while a row is not converged (the near-wall zone "
                  "at 2 and 1 times (Ek d)^(1/3), d the smallest dimension, then every size halved), each row then flagged against the round "
                  "before; a round beyond 60 % of the machine's memory is not made (docs/viscous.md, \"Refinement "
                  "rounds\") (default 0)")
      ->check(CLI::Range(0, 8));
  cmd->add_option("--target", viscous.target,
                  "with --ekman, a table: the damped modes nearest these frequencies lambda (a list such as 1.0,0.5, "
                  "each in (-2, 2)) instead of those of the ideal survey's clusters, which it then skips "
                  "(docs/viscous.md, \"Given targets\")");
}

// The cluster search and selection of a table (docs/modes.md).
// --fill on tables and on `cavity-modes response` (CSV only: R about the liquid's centroid and its offset parts).
void add_fill_option(CLI::App* cmd, TableRequest& req, bool response) {
  cmd->add_option("--fill", req.fill,
                  std::string("the liquid's volume fraction, in (0, 1] (default 1): below 1 a partially filled tank "
                              "whose free surface is the coaxial cylinder of rapid spin (docs/physics.md §2, "
                              "\"Partially filled tanks\"); built-in shapes and .geo sections (drawn whole), ideal or "
                              "with --ekman") +
                      (response ? "; the CSV adds R_fg and R_gg: R about a point c below the centroid is R + 2c R_fg "
                                  "+ c^2 R_gg" : ""))
      ->check([](const std::string& v) -> std::string {
        try {
          const double f = std::stod(v);
          if (f > 0 && f <= 1) return {};
        } catch (const std::exception&) {
        }
        return "the liquid's volume fraction must be in (0, 1], not " + v;
      });
}

void add_table_options(CLI::App* cmd, TableRequest& req, bool& fields, std::string& cluster_method) {
  auto* modes = cmd->add_option("--modes", req.selection.modes, "keep the N clusters of largest E");
  auto* coverage = cmd->add_option(
      "--coverage", req.selection.coverage,
      fmt::format("keep clusters until their E sums to this fraction of A_f - J_zh; without --modes or --coverage, "
                  "every cluster with E above {} (A_f - J_zh) is kept", number(req.selection.default_threshold)));
  modes->excludes(coverage);
  cmd->add_option("--min-lambda", req.selection.geostrophic_cutoff,
                  fmt::format("no cluster is sought with |lambda| below this, the lambda -> 0 accumulation; "
                              "1e-6..1.9 (default {})", number(req.selection.geostrophic_cutoff)));
  cmd->add_flag("--fill-gaps", req.clusters.fill_gaps,
                "lanczos clusters: also search the gaps between kept clusters with |lambda| < 0.5 for modes the "
                "survey missed (slower; on coarse meshes it can add unresolved clusters, flagged not converged)");
  cmd->add_option("--lanczos-steps", req.clusters.sil.max_steps,
                  fmt::format("lanczos clusters: shift-and-invert Lanczos steps per node, at most; 1..100000 "
                              "(default {})", req.clusters.sil.max_steps));
  cmd->add_option("--survey-steps", req.survey.max_steps,
                  fmt::format("Lanczos steps of the spectral survey, at most (default {})", req.survey.max_steps));
  cmd->add_option("--clusters", cluster_method,
                  "how the survey's nodes are refined into clusters: lanczos (shift-and-invert Lanczos Gauss rules) "
                  "or slices (SLEPc PEP STOAR spectrum slicing) (default lanczos)")
      ->check(CLI::IsMember({"lanczos", "slices"}));
  cmd->add_option_function<double>(
      "--tolerance", [&req](double tol) { req.clusters.sil.lambda_tolerance = req.clusters.qep.tolerance = tol; },
      fmt::format("lanczos: a Gauss node is settled when its lambda moves less than this, relative (default {}); "
                  "slices: the SLEPc PEP tolerance (default {})",
                  number(req.clusters.sil.lambda_tolerance), number(req.clusters.qep.tolerance)));
  cmd->add_option("--convergence-tolerance", req.convergence_tolerance,
                  fmt::format("a cluster is flagged converged if its lambda and E change by less than this against "
                              "the same order on a mesh twice as coarse (default {})",
                              number(req.convergence_tolerance)));
  cmd->add_flag("--no-convergence-check", [&req](std::int64_t) { req.check_convergence = false; },
                "skip the per-cluster comparison with a coarser discretisation");
  add_fill_option(cmd, req, false);
  cmd->add_flag("--fields", fields, "also store the mesh and each mode's p and V in /fields, with an XDMF companion "
                                    "FILE.xdmf for ParaView (docs/modes.md, Fields)");
}

void add_response_options(CLI::App* cmd, ViscousOptions& viscous) {
  cmd->add_option("--sigma", viscous.sigma,
                  "the complex frequencies sigma at which the fluid's moment response R(sigma) is computed: "
                  "FROM:TO:N (real parts, with --sigma-imag) or a list such as 0.5+0.1i,1.2-0.05i (required)");
  cmd->add_option("--sigma-imag", viscous.sigma_imag,
                  fmt::format("the imaginary part of every sigma of FROM:TO:N (default {})", number(viscous.sigma_imag)));
  cmd->add_option("--max-fit-error", viscous.max_fit_error,
                  fmt::format("-o FILE.h5 only: the largest error of the table's R, relative to max|R| on the window, "
                              "that is accepted (default {})", number(viscous.max_fit_error)));
  cmd->add_option("--max-decay-fit-error", viscous.max_decay_fit_error,
                  fmt::format("-o FILE.h5, Krylov only: the largest error of the table's Im R, which sets the decay "
                              "rates, relative to Im R itself on the window; 0, the default: measured and written "
                              "in the table (fit_decay_error), not a stopping criterion (slow at low Ekman numbers; "
                              "chain-rom confirm removes the table's error at the roots)"));
  cmd->add_flag("--krylov", viscous.krylov,
                "-o FILE.h5 only, the default: the Galerkin projection on a rational Krylov space whose expansion "
                "points are chosen where an error estimate is largest, a few factorisations instead of a forced "
                "solve per sample; passive, its fluid holds an energy (docs/viscous.md, \"Krylov response table\")");
  cmd->add_flag("--fit", viscous.fit,
                "-o FILE.h5 only: instead, a rational (AAA) fit of R by forced solves at the samples, refined where "
                "it errs (docs/viscous.md, \"Response fit\")");
  cmd->add_flag("--galerkin", viscous.galerkin,
                "-o FILE.h5 only: instead, the Galerkin projection on the forced solutions at the samples "
                "(docs/viscous.md, \"Galerkin response table\")");
  cmd->add_option("--exact-at", viscous.exact_at,
                  "-o FILE.h5, Krylov table only: complex frequencies (a list such as 0.81-0.002i,1.3) where the "
                  "table's R must be the fluid's own: expansion points before the greedy search (chain-rom confirm "
                  "--refine-tables gives the chain's roots here: docs/rom.md, \"Confirmed roots\")");
  cmd->add_flag("--serve", viscous.serve,
                "with --ekman, instead of --sigma and -o: assemble once, then answer each complex sigma read from "
                "standard input (one a line) with 'R_re R_im' on standard output (with --fill: R, R_fg, R_gg, six "
                "numbers), until end of input (chain-rom confirm drives it: docs/rom.md, \"Confirmed roots\")");
  cmd->add_flag("--stokes-series", viscous.stokes_series,
                "with --ekman (the mesh's wall layers), instead of --sigma and -o: print the strong-viscosity series "
                "R = sum_n r_n(sigma)/Ek^(n+1), Kononov's P1, P2, P3 and the order after (docs/viscous.md, \"Strong "
                "viscosity\"); a completely filled cavity");
}

// An option the parsed command does not take (CLI11 keeps it in remaining()): one line naming it and the command.
void refuse_extras(const CLI::App& cmd, bool response) {
  const auto extras = cmd.remaining();
  if (extras.empty()) return;
  const std::string& first = extras.front();
  if (!response &&
      (first == "--sigma" || first == "--sigma-imag" || first == "--max-fit-error" ||
       first == "--max-decay-fit-error" || first == "--galerkin" ||
       first == "--krylov" || first == "--fit"))
    throw std::runtime_error("--sigma, --sigma-imag, --max-fit-error, --max-decay-fit-error, --krylov, --fit and "
                             "--galerkin belong to 'cavity-modes response SHAPE ...'");
  const std::string name = (response ? "cavity-modes response " : "cavity-modes ") + cmd.get_name();
  if (first.rfind("--", 0) == 0)
    throw std::runtime_error(name + " does not take " + first + " (its options: " + name + " --help)");
  throw std::runtime_error(name + ": unexpected argument '" + first + "' (see " + name + " --help)");
}

// Resolves --method and the order's default; refuses options that only the other method has.
void choose_method(const CLI::App& cmd, const std::string& choice, bool fields, TableRequest& req) {
  // auto: a partially filled cylinder around a rod has no separable solver yet.
  const bool rod_and_fill = req.fill < 1 && req.shape.dims.count("inner_radius") > 0;
  const bool separable =
      choice == "separable" || (choice == "auto" && req.shape.kind == "cylinder" && !fields && !rod_and_fill);
  req.method = separable ? rc::modes::TableMethod::separable : rc::modes::TableMethod::mesh;
  if (req.mesh.order == 0 && !separable) req.mesh.order = 6;  // separable: its own default (separable_table.hpp)
  if (!separable && !(req.fill < 1)) return;
  // The separable solvers, and the free surface's mesh solver, compute every eigenpair: no cluster search.
  for (const char* mesh_only : {"--clusters", "--fill-gaps", "--lanczos-steps", "--survey-steps", "--tolerance"})
    if (cmd.get_option_no_throw(mesh_only) != nullptr && cmd.count(mesh_only) > 0)
      throw std::runtime_error(std::string(mesh_only) + (separable ? " applies to --method mesh only (the separable "
                                                                     "cylinder solver computes every eigenpair directly)"
                                                                   : " does not apply with --fill (the free surface's "
                                                                     "solver computes every eigenpair directly)"));
}

// The viscous mesh from the user's --order, --mesh-size, --wall-size; the ideal targets keep the method's own
// defaults (the request's mesh is reset) and skip their own convergence check.
// --target's list: real frequencies in (-2, 2), not 0 (the inertial range of a completely filled cavity).
std::vector<double> parse_targets(const std::string& list) {
  std::vector<double> out;
  std::vector<std::complex<double>> items;
  try {
    items = rc::modes::parse_sigma_spec(list, 0);
  } catch (const std::exception& e) {
    std::string what = e.what();
    if (what.rfind("--sigma", 0) == 0) what.replace(0, 7, "--target");
    throw std::runtime_error(what);
  }
  for (const auto& z : items) {
    if (z.imag() != 0 || !(std::abs(z.real()) < 2) || z.real() == 0)
      throw std::runtime_error(fmt::format("--target {}: each target must be a real frequency in (-2, 2), not 0",
                                           list));
    out.push_back(z.real());
  }
  return out;
}

rc::modes::ViscousTableSettings viscous_request(const ViscousOptions& v, TableRequest& req) {
  if (!v.target.empty()) {
    if (req.selection.modes || req.selection.coverage)
      throw std::runtime_error("--target gives the modes itself: drop --modes and --coverage");
    req.targets = parse_targets(v.target);
  }
  rc::modes::ViscousTableSettings s;
  s.ekman = v.ekman;
  s.mesh = req.mesh;
  s.mesh.wall_size = v.wall_size;
  s.mesh.near_wall_size = v.near_wall_size;
  s.convergence_tolerance = req.convergence_tolerance;
  s.check_convergence = req.check_convergence;
  if (v.refinements > 0 && !req.check_convergence)
    throw std::runtime_error("--refine refines while the convergence check finds a row not converged: drop "
                             "--no-convergence-check");
  s.refinements = v.refinements;
  if (v.mesh_ekman > 0) {
    rc::modes::viscous_mesh_defaults(req.shape, v.ekman, s.mesh);  // --ekman's own range check
    if (!(v.mesh_ekman <= v.ekman))
      throw std::runtime_error("--mesh-ekman must be at most --ekman (a mesh made for thicker layers does not resolve "
                               "the flow's)");
  }
  // A partially filled tank's mesh is the liquid's (its smallest dimension the layer outside the free surface).
  const auto liquid = req.fill < 1 ? rc::geometry::partially_filled(req.shape, req.fill) : req.shape;
  s.mesh = rc::modes::viscous_mesh_defaults(liquid, v.mesh_ekman > 0 ? v.mesh_ekman : v.ekman, s.mesh);
  if (!v.no_shear_layers && req.fill >= 1) s.shear_layers_ekman = v.mesh_ekman > 0 ? v.mesh_ekman : v.ekman;
  req.mesh = {};
  req.mesh.order = 0;
  req.check_convergence = false;
  return s;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// What `cavity-modes response` takes together: --serve (stdin, stdout) or --sigma and -o; the fit's options with an
// .h5 output only.
void check_response_options(const CLI::App& cmd, const ViscousOptions& viscous, const std::string& output) {
  if (viscous.stokes_series) {
    if (viscous.serve || cmd.count("--sigma") > 0 || !output.empty())
      throw CommandLineError("--stokes-series prints the series' coefficients: give neither --serve, --sigma nor -o");
    if (cmd.count("--ekman") == 0)
      throw CommandLineError("--stokes-series needs --ekman (the Ekman number whose wall-layer mesh it uses)");
    if (cmd.count("--fill") > 0)
      throw CommandLineError("--stokes-series: a completely filled cavity only (a free surface's normal stress does "
                             "not scale with Ek)");
    return;
  }
  if (viscous.serve && (cmd.count("--sigma") > 0 || !output.empty()))
    throw std::runtime_error("--serve reads its frequencies from standard input and answers on standard output: "
                             "give neither --sigma nor -o");
  if (viscous.serve && cmd.count("--ekman") == 0)
    throw std::runtime_error("--serve needs --ekman (the viscous fluid's forced solves)");
  if (!viscous.serve && output.empty()) throw std::runtime_error("-o,--output is required");
  if (!viscous.serve && cmd.count("--sigma") == 0) throw std::runtime_error("cavity-modes response needs --sigma FROM:TO:N");
  if (cmd.count("--max-fit-error") > 0 && !ends_with(output, ".h5"))
    throw std::runtime_error("--max-fit-error belongs to 'cavity-modes response SHAPE ... -o FILE.h5'");
  if (cmd.count("--max-decay-fit-error") > 0 && (!ends_with(output, ".h5") || viscous.galerkin || viscous.fit))
    throw std::runtime_error("--max-decay-fit-error belongs to a Krylov response table, 'cavity-modes response SHAPE "
                             "... -o FILE.h5' without --fit or --galerkin");
  if ((viscous.galerkin || viscous.krylov || viscous.fit) && !ends_with(output, ".h5"))
    throw std::runtime_error(std::string(viscous.galerkin ? "--galerkin" : viscous.fit ? "--fit" : "--krylov") +
                             " belongs to 'cavity-modes response SHAPE ... -o FILE.h5'");
  if (int(viscous.galerkin) + int(viscous.krylov) + int(viscous.fit) > 1)
    throw std::runtime_error("--krylov, --fit and --galerkin exclude each other (one table method)");
  if (cmd.count("--exact-at") > 0 && (!ends_with(output, ".h5") || viscous.galerkin || viscous.fit))
    throw std::runtime_error("--exact-at belongs to a Krylov response table: 'cavity-modes response SHAPE --ekman Ek "
                             "--sigma ... -o FILE.h5' without --fit or --galerkin");
}

// A section's fill is cut from its file now, so that a fill it cannot take is refused before any solve.
void check_section_fill(const TableRequest& req) {
  if (req.shape.kind != "section") return;
  try {
    rc::geometry::free_surface_radius(req.shape, req.fill);
  } catch (const std::runtime_error& e) {
    throw CommandLineError(e.what());
  }
}

// `cavity-modes response --fill`: R and its offset parts as CSV, ideal or viscous, served (three complex numbers a
// line), or a response table (docs/viscous.md, "Response tables of a partially filled tank").
void check_response_fill(const TableRequest& req, const ViscousOptions& viscous, const std::string& output) {
  if (!(req.fill < 1)) return;
  check_section_fill(req);
}

// --fill below 1: what a partially filled tank's table can be made with so far (docs/modes.md, "Partially filled
// tanks"); each refusal one line, exit code 2.
void check_fill(const TableRequest& req, bool viscous_fields, const std::string& method) {
  if (!(req.fill < 1)) return;
  check_section_fill(req);
  if (viscous_fields) throw CommandLineError("--fill --ekman: not with --fields yet (the ideal --fill table takes it)");
  if (!req.targets.empty()) throw CommandLineError("--fill: not with --target (the targets are the free surface's modes)");
  if (method == "separable" && (req.shape.kind != "cylinder" || req.shape.dims.count("inner_radius")))
    throw CommandLineError("--fill --method separable: a plain cylinder only (--method mesh takes the others)");
}

// The table's report, then the plain line on what converged (empty when everything did).
void print_table(const rc::ModeTable& table) {
  std::cout << rc::modes::table_text(table);
  const auto note = rc::modes::convergence_note(table);
  if (!note.empty()) std::cout << note << "\n";
  std::cout << std::flush;
}

// -o,--output of every shape command (required for a table; for a response unless --serve, checked after parsing).
void add_output_option(CLI::App* cmd, bool response, std::string& output) {
  auto* out = cmd->add_option("-o,--output", output, response ? "R(sigma) as CSV, or FILE.h5: a response table"
                                                            : "mode table to write (HDF5)");
  if (!response) out->required();
  cmd->allow_extras();
}

// The checks of the viscous and response options, once, and the viscous table's settings (empty without --ekman).
rc::modes::ViscousTableSettings resolve_viscous(const CLI::App& cmd, bool response, bool is_viscous,
                                                ViscousOptions& viscous, const std::string& output, TableRequest& req) {
  if (response) check_response_options(cmd, viscous, output);
  if (!(viscous.max_fit_error > 0) || !std::isfinite(viscous.max_fit_error))
    throw std::runtime_error("--max-fit-error must be positive and finite");
  if (!(viscous.max_decay_fit_error >= 0) || !std::isfinite(viscous.max_decay_fit_error))
    throw std::runtime_error("--max-decay-fit-error must be 0 (not a criterion) or positive and finite");
  // Checked here, once: the viscous path hands the tolerance on past compute_mode_table's own check.
  if (!response && req.check_convergence) rc::modes::validate_convergence_tolerance(req.convergence_tolerance);
  if (is_viscous) {
    const double fill = req.fill;
    rc::modes::ViscousTableSettings s = viscous_request(viscous, req);
    // A table's default near-wall zone (whole tanks; a given --near-wall-size, 0 included, is kept).
    if (!response && fill >= 1 && cmd.count("--near-wall-size") == 0)
      s.mesh.near_wall_size = rc::modes::default_near_wall_size(
          req.shape, viscous.mesh_ekman > 0 ? viscous.mesh_ekman : viscous.ekman);
    for (int level = 0; level < viscous.mesh_level; ++level)
      s.mesh = rc::modes::halved_viscous_mesh(viscous.mesh_ekman > 0 ? viscous.mesh_ekman : viscous.ekman, s.mesh);
    return s;
  }
  if (cmd.get_option_no_throw("--mesh-level") && cmd.count("--mesh-level") > 0)
    throw std::runtime_error("--mesh-level applies with --ekman only (the viscous mesh's levels)");
  if (cmd.count("--wall-size") > 0) throw std::runtime_error("--wall-size applies with --ekman only");
  if (cmd.count("--near-wall-size") > 0) throw std::runtime_error("--near-wall-size applies with --ekman only");
  if (cmd.count("--mesh-ekman") > 0) throw std::runtime_error("--mesh-ekman applies with --ekman only");
  if (cmd.get_option_no_throw("--target") && cmd.count("--target") > 0)
    throw std::runtime_error("--target applies with --ekman only (the ideal table's modes come from its survey)");
  if (cmd.get_option_no_throw("--refine") && cmd.count("--refine") > 0)
    throw std::runtime_error("--refine applies with --ekman only (an ideal table's convergence: docs/trust.md)");
  return {};
}

// `response` is taken off the command line before parsing (run's start): listed as a subcommand for --help only.
void list_response_command(CLI::App& app) {
  app.add_subcommand("response", "SHAPE ... --sigma LIST -o R.csv | FILE.h5: the fluid's moment response R(sigma), or "
                                 "a response table for chain-rom (cavity-modes response SHAPE --help; docs/viscous.md)");
}

// `cavity-modes info FILE`: the table's report, its JSON, or its stored section text.
struct InfoRequest {
  std::string file;
  bool json = false, geometry_text = false;
};

CLI::App* add_info_command(CLI::App& app, InfoRequest& r) {
  auto* info = app.add_subcommand("info", "print a mode table's attributes and modes");
  info->add_option("file", r.file, "mode table (HDF5)")->required();
  info->add_flag("--json", r.json, "print docs/physics.md §4's JSON object");
  info->add_flag("--geometry", r.geometry_text, "print only the section file's text stored in the table (redirect it "
                                                "to a file to mesh the same section again)");
  return info;
}

int run_info(const InfoRequest& r) {
  auto table = rc::read_mode_table(r.file);
  if (r.geometry_text) {
    if (table.geometry_text.empty())
      throw std::runtime_error(r.file + ": no section text stored (" +
                               (table.geometry_source.empty() ? "the table predates provenance"
                                                              : "a built-in shape: " + table.geometry_source) + ")");
    std::cout << table.geometry_text << std::flush;
  } else if (r.json) {
    std::cout << rc::modes::table_json(table) << std::flush;
  } else {
    print_table(table);
  }
  return 0;
}

// `cavity-modes compare FILE REFERENCE`: against a reference CSV or another table of the same cavity.
struct CompareRequest {
  std::string table, reference;
  double tolerance = 1e-6;
};

CLI::App* add_compare_command(CLI::App& app, CompareRequest& r) {
  auto* compare = app.add_subcommand("compare", "compare a table with a reference CSV (published or closed-form "
                                                "kappa and E, docs/reference-tables.md), or with another table of "
                                                "the same cavity (REFERENCE.h5: integrals, band weights, clusters; "
                                                "a refinement study, docs/trust.md); fails past the tolerance");
  compare->add_option("file", r.table, "mode table (HDF5)")->required();
  compare->add_option("reference", r.reference, "reference: a CSV, or a mode table (.h5)")->required();
  compare->add_option("--tolerance", r.tolerance,
                      "largest relative difference accepted: of kappa and E (CSV); of the integrals and of the band "
                      "weights over A_f - J_zh (table) (default " + number(r.tolerance) + ")");
  return compare;
}

int run_compare(const CompareRequest& r) {
  if (ends_with(r.reference, ".h5")) {
    const auto a = rc::read_mode_table(r.table), b = rc::read_mode_table(r.reference);
    const auto cmp = rc::modes::compare_tables(a, b, r.tolerance);
    std::cout << rc::modes::table_comparison_text(cmp, a, b, r.table, r.reference) << std::flush;
    if (cmp.failing > 0) throw std::runtime_error(rc::modes::table_comparison_failure(cmp));
    return 0;
  }
  const auto table = rc::read_mode_table(r.table);
  const auto cmp = rc::modes::compare_with_reference(table, rc::modes::read_reference_csv(r.reference), r.tolerance,
                                                     r.reference);
  std::cout << rc::modes::comparison_text(cmp, table, r.table, r.reference) << std::flush;
  if (cmp.failing > 0) throw std::runtime_error(rc::modes::comparison_failure(cmp, r.reference));
  return 0;
}

// The strong-viscosity series' coefficients (stokes_series.hpp), one line each.
void print_stokes_series(const rc::modes::StokesSeries& s) {
  const auto c = [](std::complex<double> z) { return fmt::format("{:.12g}{:+.12g}i", z.real() + 0.0, z.imag() + 0.0); };
  fmt::print("strong-viscosity series R(sigma) = r0/Ek + r1(sigma)/Ek^2 + r2(sigma)/Ek^3 + ... (docs/viscous.md, "
             "\"Strong viscosity\"; Kononov's P1 = r0, P2 and P3 the sigma and constant terms of r1)\n");
  fmt::print("r0 = {}\nr1 = ({}) sigma + ({})\nr2 = ({}) sigma^2 + ({}) sigma + ({})\n", c(s.r0), c(s.r1_s), c(s.r1_0),
             c(s.r2_ss), c(s.r2_s), c(s.r2_0));
}

// `cavity-modes response SHAPE ...`: R(sigma) as CSV, a response table (FILE.h5), or served one sigma at a time.
int run_response(const TableRequest& req, const ViscousOptions& viscous, bool is_viscous,
                 const rc::modes::ViscousTableSettings& viscous_settings, const std::string& method,
                 const std::string& output, const std::string& command_line) {
  rc::modes::ResponseRequest r;
  r.shape = req.shape;
  if (!viscous.serve && !viscous.stokes_series) r.sigmas = rc::modes::parse_sigma_spec(viscous.sigma, viscous.sigma_imag);
  if (!viscous.exact_at.empty()) {
    try {
      r.exact_at = rc::modes::parse_sigma_spec(viscous.exact_at, 0);
    } catch (const std::exception& e) {  // parse_sigma_spec names --sigma; the list was --exact-at's
      std::string what = e.what();
      if (what.rfind("--sigma", 0) == 0) what.replace(0, 7, "--exact-at");
      throw std::runtime_error(what);
    }
  }
  r.ekman = is_viscous ? viscous.ekman : 0;
  r.mesh = is_viscous ? viscous_settings.mesh : req.mesh;
  r.separable = !is_viscous && method == "separable";  // auto: forced solves for every shape
  r.fill = req.fill;
  if (!is_viscous && !r.separable && r.mesh.order == 0) r.mesh.order = 6;
  if (viscous.serve) {
    rc::modes::serve_response(r, std::cin, std::cout);
    return 0;
  }
  if (viscous.stokes_series) {
    print_stokes_series(rc::modes::stokes_series(r.shape, r.mesh));
    return 0;
  }
  if (ends_with(output, ".h5")) {
    // A response table: pseudo-modes whose R is the fluid's on the window (docs/viscous.md, "Krylov response
    // table"). A rational fit keeps its forced solves in FILE.h5.samples until the table is written
    // (viscous/response_samples.hpp).
    if (viscous.fit) r.samples_file = output + ".samples";
    auto table = viscous.galerkin ? rc::modes::galerkin_response_table(r, viscous.max_fit_error)
                 : viscous.fit    ? rc::modes::response_fit_table(r, viscous.max_fit_error)
                                  : rc::modes::krylov_response_table(r, viscous.max_fit_error,
                                                                     viscous.max_decay_fit_error);
    if (!rc::modes::is_root_rank()) return 0;
    rc::modes::record_provenance(table, req.shape, command_line);
    rc::write_mode_table(table, output);
    if (!r.samples_file.empty()) {
      std::error_code gone;
      std::filesystem::remove(r.samples_file, gone);
    }
    print_table(table);
    return 0;
  }
  const auto R = rc::modes::compute_cavity_response(r);
  if (!rc::modes::is_root_rank()) return 0;
  rc::modes::write_response(output, r.sigmas, R);
  std::cout << "wrote " << output << ": R(sigma) at " << r.sigmas.size() << " frequencies (" << R.method << ")\n";
  return 0;
}

// `cavity-modes SHAPE ... -o FILE.h5`: the mode table (ideal, or with --ekman the damped modes).
int run_table(const TableRequest& req, bool is_viscous, const rc::modes::ViscousTableSettings& viscous_settings,
              bool fields, const std::string& output, const std::string& command_line) {
  if (fields) rc::check_companion_name(output);  // before the long computation
  rc::ModeFields mode_fields;
  const bool root = rc::modes::is_root_rank();
  const auto report = [root](const std::string& line) { if (root) std::cerr << line << "\n"; };
  // With --ekman the fields are the damped modes' (the ideal targets need none).
  auto table = rc::modes::compute_mode_table(req, report, fields && !is_viscous ? &mode_fields : nullptr);
  // A partially filled tank's damped modes live in the liquid only: its free surface is part of the viscous mesh.
  const auto liquid = req.fill < 1 ? rc::geometry::partially_filled(req.shape, req.fill) : req.shape;
  if (is_viscous)
    table = rc::modes::compute_viscous_table(liquid, viscous_settings, table, report, fields ? &mode_fields : nullptr);
  if (!root) return 0;  // under mpirun: rank 0 writes the table
  rc::modes::record_provenance(table, req.shape, command_line);
  rc::write_mode_table(table, output, fields ? &mode_fields : nullptr);
  print_table(table);
  if (req.selection.modes && table.size() < static_cast<std::size_t>(*req.selection.modes))
    std::cerr << fmt::format("cavity-modes: note: --modes {} asked, the table holds {}: this cavity has no other "
                             "coupling cluster above the selection's threshold (coverage {:.6f})\n",
                             *req.selection.modes, table.size(), table.coverage);
  return 0;
}

// A first word that is neither a shape nor a command: one line naming what is expected.
void check_command_name(CLI::App& app, const std::vector<std::string>& ours) {
  const auto commands = app.get_subcommands([](CLI::App*) { return true; });
  const bool known = std::any_of(commands.begin(), commands.end(), [&](CLI::App* c) {
    return ours.size() > 1 && c->get_name() == ours[1];
  });
  if (ours.size() > 1 && ours[1][0] != '-' && !known)
    throw std::runtime_error("unknown shape or command '" + ours[1] +
                             "' (expected sphere, spheroid, cylinder, cone, section, ellipsoid, volume, shell, response, info or compare)");
}

// The pass-through PETSc words as PetscInitialize takes them (argc, argv with its closing null).
struct PetscArguments {
  explicit PetscArguments(std::vector<std::string>& words) {
    for (auto& a : words) pointers.push_back(a.data());
    argc = static_cast<int>(pointers.size());
    pointers.push_back(nullptr);
    argv = pointers.data();
  }
  std::vector<char*> pointers;
  int argc = 0;
  char** argv = nullptr;
};

// Parses; returns -1 when parsed, else the exit code (help printed, or a command-line error: 2).
int parse_command_line(CLI::App& app, std::vector<std::string>& words) {
  std::vector<char*> ours;
  for (auto& a : words) ours.push_back(a.data());
  try {
    app.parse(static_cast<int>(ours.size()), ours.data());
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "cavity-modes: error: " << e.what() << " (see --help)\n";
    return 2;  // every command-line error, whatever CLI11's own code
  }
  return -1;
}

// A command that computes opens gmsh here, before PETSc starts, whether or not it meshes: its libraries then sit at
// the same place in memory for every such command (a table, and confirm's remake of it), not wherever a first mesh
// happened to ask for them (geometry/gmsh_library.hpp).
void open_gmsh_before_computing() { rc::geometry::load_gmsh(); }

// A command that solves on its own inside one PETSc session: `ellipsoid|volume ...`, a 3-D cavity's table
// (docs/volume.md), and `shell ...`, the sphere or spherical shell by spectral expansion (docs/spherical.md). Neither
// has a `response` form: `refusal` says why.
template <class Command>
int run_in_session(const Command& command, bool response, const char* refusal, std::vector<std::string>& petsc_words,
                   const std::string& command_line) {
  if (response) throw CommandLineError(refusal);
  open_gmsh_before_computing();
  PetscArguments petsc(petsc_words);
  rc::modes::PetscSession session(&petsc.argc, &petsc.argv);
  return command.run(command_line);
}

constexpr const char* kProgramDescription =
    "cavity-modes: inertial-mode tables (kappa, lambda, E, a, N2, J_zh, coverage) of a rotating "
    "fluid in an axisymmetric cavity: ideal, or viscous with --ekman (damped modes). "
    "'cavity-modes response SHAPE ... [--ekman Ek] --sigma FROM:TO:N [--sigma-imag y] -o R.csv' computes the "
    "fluid's moment response R(sigma) instead (docs/viscous.md, section 6). PETSc/SLEPc options "
    "(-pep_type, -log_view) pass through.";

// `cavity-modes response SHAPE ...`: the shape's command line, answered with R(sigma) instead of a table. Takes the
// word out of `words` and says whether it was there.
bool take_response_word(std::vector<std::string>& words) {
  if (words.size() < 2 || words[1] != "response") return false;
  words.erase(words.begin() + 1);
  words[0] += " response";  // the program's name in --help's usage line: "cavity-modes response sphere"
  return true;
}

int run(int argc, char** argv) {
  const std::string command_line = rc::modes::quoted_command_line(std::vector<std::string>(argv, argv + argc));
  if (const std::string empty = rc::empty_argument_error(argc, argv); !empty.empty()) {
    if (rc::modes::is_root_rank()) std::cerr << "cavity-modes: error: " << empty << "\n";
    return 2;  // a command-line error, like CLI11's
  }
  auto args = rc::modes::split_arguments(argc, argv);
  const bool response = take_response_word(args.ours);
  CLI::App app{kProgramDescription};
  app.require_subcommand(1);
  TableRequest req;
  req.mesh.order = 0;  // the method's default, set below
  std::string output;
  bool fields = false;
  std::string method = "auto", cluster_method = "lanczos";
  ViscousOptions viscous;
  rc::modes::ShapeCommands shapes(app, response ? ": its moment response R(sigma)" : ": its mode table");
  // Each shape lists only what it takes (cavity-modes sphere --help); anything else is refused by name.
  for (auto& s : shapes.all()) {
    add_mesh_options(s.app, s.kind, response, req, method);
    add_viscous_options(s.app, viscous, response);
    if (response) add_response_options(s.app, viscous), add_fill_option(s.app, req, true);
    else add_table_options(s.app, req, fields, cluster_method);
    add_output_option(s.app, response, output);
  }
  list_response_command(app);
  InfoRequest info_request;
  CompareRequest compare_request;
  CLI::App* info = add_info_command(app, info_request);
  CLI::App* compare = add_compare_command(app, compare_request);
  rc::modes::VolumeCommands volumes(app);
  rc::modes::ShellCommand shell(app);
  check_command_name(app, args.ours);
  if (const int code = parse_command_line(app, args.ours); code >= 0) return code;
  if (info->parsed()) return run_info(info_request);
  if (compare->parsed()) return run_compare(compare_request);
  if (volumes.parsed())
    return run_in_session(volumes, response, "response takes an axisymmetric shape (3-D cavities: tables only so far)",
                          args.petsc, command_line);
  if (shell.parsed())
    return run_in_session(shell, response, "response takes an axisymmetric shape meshed by gmsh (shell: damped modes "
                          "only)", args.petsc, command_line);

  CLI::App* table_command = shapes.parsed()->app;
  refuse_extras(*table_command, response);
  req.shape = shapes.parsed_shape();
  req.clusters.method = cluster_method == "slices" ? rc::modes::ClusterMethod::slices : rc::modes::ClusterMethod::lanczos;
  const bool is_viscous = table_command->count("--ekman") > 0;
  const auto viscous_settings = resolve_viscous(*table_command, response, is_viscous, viscous, output, req);
  if (!response) check_fill(req, fields && is_viscous, method);
  else check_response_fill(req, viscous, output);
  choose_method(*table_command, method, fields, req);

  open_gmsh_before_computing();
  PetscArguments petsc(args.petsc);
  rc::modes::PetscSession session(&petsc.argc, &petsc.argv);
  if (response) return run_response(req, viscous, is_viscous, viscous_settings, method, output, command_line);
  return run_table(req, is_viscous, viscous_settings, fields, output, command_line);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const CommandLineError& e) {
    if (rc::modes::is_root_rank()) std::cerr << "cavity-modes: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    // Under mpirun every rank fails alike: one line, from rank 0.
    if (rc::modes::is_root_rank()) std::cerr << "cavity-modes: error: " << e.what() << "\n";
    return 1;
  }
}
