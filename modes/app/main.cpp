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
#include "command_line.hpp"
#include "mode_fields.hpp"
#include "mode_table_report.hpp"
#include "petsc_handles.hpp"
#include "reference_table.hpp"
#include "cavity_response.hpp"
#include "viscous_table.hpp"

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

struct ShapeCommand {
  CLI::App* app = nullptr;
  std::string kind;
  std::map<std::string, double> dims;
};

// --method auto|mesh|separable: auto is separable for a cylinder table without --fields, mesh otherwise
// (docs/modes.md).
// --ekman and --wall-size: the viscous table (docs/viscous.md); --sigma, --sigma-imag: `cavity-modes response`.
struct ViscousOptions {
  double ekman = 0;
  double wall_size = 0;
  std::string sigma;       // FROM:TO:N (real parts) or a list of complex numbers
  double sigma_imag = 0;   // imaginary part of every σ
  double max_fit_error = 1e-6;  // response to FILE.h5: the largest fit error accepted
};

void add_common_options(CLI::App* cmd, TableRequest& req, std::string& output, bool& fields, std::string& method,
                        ViscousOptions& viscous) {
  cmd->add_option("--ekman", viscous.ekman,
                  "viscous fluid with Ekman number Ek = nu/(omega0 L^2): damped modes (decay, complex coupling) "
                  "continuing the ideal ones, on a wall-graded Taylor-Hood mesh (docs/viscous.md); --order, "
                  "--mesh-size then set that mesh (default order 6, d/8)");
  cmd->add_option("--wall-size", viscous.wall_size,
                  "with --ekman: element size at the wall (default Ek^(1/2))");
  cmd->add_option("--sigma", viscous.sigma,
                  "cavity-modes response only: the complex frequencies sigma at which the fluid's moment response "
                  "R(sigma) is computed (CSV to -o): FROM:TO:N (real parts, with --sigma-imag) or a list such as "
                  "0.5+0.1i,1.2-0.05i");
  cmd->add_option("--sigma-imag", viscous.sigma_imag, "cavity-modes response only: the imaginary part of every sigma");
  cmd->add_option("--max-fit-error", viscous.max_fit_error,
                  "cavity-modes response -o FILE.h5 only: the largest relative error of the rational fit of R between "
                  "its samples that is accepted (default 1e-6)");
  cmd->add_option("--method", method,
                  "auto (separable for cylinders without --fields, else mesh), mesh (gmsh mesh of the meridian "
                  "section, every shape) or separable (cylinder: exact separation on a tensor-product grid)")
      ->check(CLI::IsMember({"auto", "mesh", "separable"}))
      ->capture_default_str();
  cmd->add_option("--order", req.mesh.order, "Lagrange order: mesh 1..6 (default 6), separable 1..12 (default 10)");
  cmd->add_option("--mesh-size", req.mesh.size, "target element size in the shape's length unit (mesh: d/8, spheres "
                                                "and spheroids d/5, d the smallest dimension; separable: axial size, 3d/8)");
  cmd->add_option("--radial-size", req.mesh.radial_size,
                  "cylinder: element size along r (mesh: a structured mesh, --mesh-size is then the size along z; "
                  "separable: default max(d, radius/2)/8)");
  auto* modes = cmd->add_option("--modes", req.selection.modes, "keep the N clusters of largest E");
  auto* coverage = cmd->add_option("--coverage", req.selection.coverage,
                                   "keep clusters until their E sums to this fraction of A_f - J_zh");
  modes->excludes(coverage);
  cmd->add_option("--min-lambda", req.selection.geostrophic_cutoff,
                  "no cluster is sought with |lambda| below this (the lambda -> 0 accumulation)")
      ->check(CLI::Range(1e-6, 1.9))->capture_default_str();
  cmd->add_flag("--fill-gaps", req.clusters.fill_gaps,
                "lanczos clusters: also search the gaps between kept clusters with |lambda| < 0.5 for modes the "
                "survey missed (slower; on coarse meshes it can add unresolved clusters, flagged not converged)");
  cmd->add_option("--lanczos-steps", req.clusters.sil.max_steps,
                  "lanczos clusters: shift-and-invert Lanczos steps per node (at most)")
      ->check(CLI::Range(1, 100000))->capture_default_str();
  cmd->add_option("--survey-steps", req.survey.max_steps, "Lanczos steps of the spectral survey (at most)")
      ->capture_default_str();
  cmd->add_option("--clusters", req.clusters.method,
                  "how the survey's nodes are refined into clusters: lanczos (shift-and-invert Lanczos Gauss rules) "
                  "or slices (SLEPc PEP STOAR spectrum slicing)")
      ->transform(CLI::CheckedTransformer(std::map<std::string, rc::modes::ClusterMethod>{{"lanczos", rc::modes::ClusterMethod::lanczos},
                                                                                {"slices", rc::modes::ClusterMethod::slices}}))
      ->capture_default_str();
  cmd->add_option_function<double>(
      "--tolerance", [&req](double tol) { req.clusters.sil.lambda_tolerance = req.clusters.qep.tolerance = tol; },
      "lanczos: a Gauss node is settled when its lambda moves less than this (relative; default 1e-11); slices: "
      "the SLEPc PEP tolerance (default 1e-12)");
  cmd->add_option("--convergence-tolerance", req.convergence_tolerance,
                  "a cluster is flagged converged if its lambda and E change by less than this against the same "
                  "order on a mesh twice as coarse")->capture_default_str();
  cmd->add_flag("--no-convergence-check", [&req](std::int64_t) { req.check_convergence = false; },
                "skip the per-cluster comparison with a coarser discretisation");
  cmd->add_flag("--fields", fields, "also store the mesh and each mode's p and V in /fields, with an XDMF companion "
                                    "FILE.xdmf for ParaView (docs/modes.md, Fields)");
  cmd->add_option("-o,--output", output, "mode table to write (HDF5)")->required();
}

// Resolves --method and the order's default; refuses options that only the other method has.
void choose_method(const CLI::App& cmd, const std::string& choice, bool fields, TableRequest& req) {
  const bool separable = choice == "separable" || (choice == "auto" && req.shape.kind == "cylinder" && !fields);
  req.method = separable ? rc::modes::TableMethod::separable : rc::modes::TableMethod::mesh;
  if (req.mesh.order == 0 && !separable) req.mesh.order = 6;  // separable: its own default (separable_table.hpp)
  if (!separable) return;
  for (const char* mesh_only : {"--clusters", "--fill-gaps", "--lanczos-steps", "--survey-steps", "--tolerance"})
    if (cmd.count(mesh_only) > 0)
      throw std::runtime_error(std::string(mesh_only) + " applies to --method mesh only (the separable cylinder "
                                                        "solver computes every eigenpair directly)");
}

// The viscous mesh from the user's --order, --mesh-size, --wall-size; the ideal targets keep the method's own
// defaults (the request's mesh is reset) and skip their own convergence check.
rc::modes::ViscousTableSettings viscous_request(const CLI::App& cmd, const ViscousOptions& v, bool fields,
                                                TableRequest& req) {
  if (fields) throw std::runtime_error("--fields is not available with --ekman yet (docs/viscous.md, \"Limits\")");
  rc::modes::ViscousTableSettings s;
  s.ekman = v.ekman;
  s.mesh = req.mesh;
  s.mesh.wall_size = v.wall_size;
  s.convergence_tolerance = req.convergence_tolerance;
  s.check_convergence = req.check_convergence;
  s.mesh = rc::modes::viscous_mesh_defaults(req.shape, v.ekman, s.mesh);
  req.mesh = {};
  req.mesh.order = 0;
  req.check_convergence = false;
  return s;
}

int run(int argc, char** argv) {
  auto args = rc::modes::split_arguments(argc, argv);
  // `cavity-modes response SHAPE ...`: the shape's command line, answered with R(sigma) instead of a table.
  const bool response = args.ours.size() > 1 && args.ours[1] == "response";
  if (response) args.ours.erase(args.ours.begin() + 1);
  CLI::App app{"cavity-modes: inertial-mode tables (kappa, lambda, E, a, N2, J_zh, coverage) of a rotating "
               "fluid in an axisymmetric cavity: ideal, or viscous with --ekman (damped modes). "
               "'cavity-modes response SHAPE ... [--ekman Ek] --sigma FROM:TO:N [--sigma-imag y] -o R.csv' computes the "
               "fluid's moment response R(sigma) instead (docs/viscous.md, section 6). PETSc/SLEPc options "
               "(-pep_type, -log_view) pass through."};
  app.require_subcommand(1);
  TableRequest req;
  req.mesh.order = 0;  // the method's default, set below
  std::string output;
  bool fields = false;
  std::string method = "auto";
  std::vector<ShapeCommand> shapes;
  auto shape = [&](const std::string& kind, const std::string& help,
                   std::vector<std::pair<std::string, std::string>> dims) {
    ShapeCommand s;
    s.kind = kind;
    s.app = app.add_subcommand(kind, help);
    shapes.push_back(std::move(s));
    for (auto& [name, what] : dims)
      shapes.back().app->add_option("--" + name, shapes.back().dims[name], what)->required();
  };
  shape("sphere", "sphere of radius R", {{"radius", "radius R"}});
  shape("spheroid", "spheroid with equatorial semi-axis a and polar semi-axis c",
        {{"a", "equatorial semi-axis"}, {"c", "polar semi-axis"}});
  shape("cylinder", "circular cylinder", {{"radius", "radius"}, {"height", "full height"}});
  shape("cone", "cone, apex down, flat lid on top", {{"radius", "lid radius"}, {"height", "height"}});
  auto* section = app.add_subcommand("section", "the user's meridian section (.geo or .msh; see docs/geometry.md)");
  section->add_option("file", req.shape.file, "section file")->required();
  ViscousOptions viscous;
  for (auto& s : shapes) add_common_options(s.app, req, output, fields, method, viscous);
  add_common_options(section, req, output, fields, method, viscous);

  std::string info_file;
  bool json = false;
  auto* info = app.add_subcommand("info", "print a mode table's attributes and modes");
  info->add_option("file", info_file, "mode table (HDF5)")->required();
  info->add_flag("--json", json, "print docs/physics.md §4's JSON object");

  std::string compare_table, compare_reference;
  double compare_tolerance = 1e-6;
  auto* compare = app.add_subcommand("compare", "compare a table's kappa and E with a reference CSV (published or "
                                                "closed-form values, docs/reference-tables.md); fails past the "
                                                "tolerance");
  compare->add_option("file", compare_table, "mode table (HDF5)")->required();
  compare->add_option("reference", compare_reference, "reference table (CSV)")->required();
  compare->add_option("--tolerance", compare_tolerance, "largest relative difference of kappa and E accepted")
      ->capture_default_str();

  const auto commands = app.get_subcommands([](CLI::App*) { return true; });
  const bool known = std::any_of(commands.begin(), commands.end(), [&](CLI::App* c) {
    return args.ours.size() > 1 && c->get_name() == args.ours[1];
  });
  if (args.ours.size() > 1 && args.ours[1][0] != '-' && !known)
    throw std::runtime_error("unknown shape or command '" + args.ours[1] +
                             "' (expected sphere, spheroid, cylinder, cone, section, info or compare)");
  std::vector<char*> ours;
  for (auto& a : args.ours) ours.push_back(a.data());
  try {
    app.parse(static_cast<int>(ours.size()), ours.data());
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "cavity-modes: error: " << e.what() << " (see --help)\n";
    return e.get_exit_code() != 0 ? e.get_exit_code() : 2;
  }

  if (info->parsed()) {
    auto table = rc::read_mode_table(info_file);
    std::cout << (json ? rc::modes::table_json(table) : rc::modes::table_text(table)) << std::flush;
    return 0;
  }
  if (compare->parsed()) {
    const auto table = rc::read_mode_table(compare_table);
    const auto cmp = rc::modes::compare_with_reference(table, rc::modes::read_reference_csv(compare_reference),
                                                       compare_tolerance, compare_reference);
    std::cout << rc::modes::comparison_text(cmp, table, compare_table, compare_reference) << std::flush;
    if (cmp.failing > 0) throw std::runtime_error(rc::modes::comparison_failure(cmp, compare_reference));
    return 0;
  }
  CLI::App* table_command = section;
  if (section->parsed()) req.shape.kind = "section";
  for (auto& s : shapes)
    if (s.app->parsed()) { req.shape.kind = s.kind; req.shape.dims = s.dims; table_command = s.app; }
  if (response != (table_command->count("--sigma") > 0))
    throw std::runtime_error(response ? "cavity-modes response needs --sigma FROM:TO:N"
                                      : "--sigma and --sigma-imag belong to 'cavity-modes response SHAPE ...'");
  if (!response && table_command->count("--sigma-imag") > 0)
    throw std::runtime_error("--sigma and --sigma-imag belong to 'cavity-modes response SHAPE ...'");
  if (table_command->count("--max-fit-error") > 0 &&
      !(response && output.size() > 3 && output.compare(output.size() - 3, 3, ".h5") == 0))
    throw std::runtime_error("--max-fit-error belongs to 'cavity-modes response SHAPE ... -o FILE.h5'");
  if (!(viscous.max_fit_error > 0) || !std::isfinite(viscous.max_fit_error))
    throw std::runtime_error("--max-fit-error must be positive and finite");
  const bool is_viscous = table_command->count("--ekman") > 0;
  rc::modes::ViscousTableSettings viscous_settings;
  if (is_viscous) viscous_settings = viscous_request(*table_command, viscous, fields, req);
  else if (table_command->count("--wall-size") > 0) throw std::runtime_error("--wall-size applies with --ekman only");
  choose_method(*table_command, method, fields, req);

  int petsc_argc = static_cast<int>(args.petsc.size());
  std::vector<char*> petsc_argv;
  for (auto& a : args.petsc) petsc_argv.push_back(a.data());
  petsc_argv.push_back(nullptr);
  char** pargv = petsc_argv.data();
  rc::modes::PetscSession session(&petsc_argc, &pargv);
  if (response) {
    rc::modes::ResponseRequest r;
    r.shape = req.shape;
    r.sigmas = rc::modes::parse_sigma_spec(viscous.sigma, viscous.sigma_imag);
    r.ekman = is_viscous ? viscous.ekman : 0;
    r.mesh = is_viscous ? viscous_settings.mesh : req.mesh;
    r.separable = !is_viscous && method == "separable";  // auto: forced solves for every shape
    if (!is_viscous && !r.separable && r.mesh.order == 0) r.mesh.order = 6;
    if (output.size() > 3 && output.compare(output.size() - 3, 3, ".h5") == 0) {
      // A response-fit table: the fit's poles and residues as damped modes (docs/viscous.md, "Response fit").
      const auto table = rc::modes::response_fit_table(r, viscous.max_fit_error);
      if (!rc::modes::is_root_rank()) return 0;
      rc::write_mode_table(table, output);
      std::cout << rc::modes::table_text(table) << std::flush;
      return 0;
    }
    const auto R = rc::modes::compute_cavity_response(r);
    if (!rc::modes::is_root_rank()) return 0;
    rc::modes::write_response(output, r.sigmas, R.R, R.method);
    std::cout << "wrote " << output << ": R(sigma) at " << r.sigmas.size() << " frequencies (" << R.method << ")\n";
    return 0;
  }
  if (fields) rc::check_companion_name(output);  // before the long computation
  rc::ModeFields mode_fields;
  const bool root = rc::modes::is_root_rank();
  const auto report = [root](const std::string& line) { if (root) std::cerr << line << "\n"; };
  auto table = rc::modes::compute_mode_table(req, report, fields ? &mode_fields : nullptr);
  if (is_viscous) table = rc::modes::compute_viscous_table(req.shape, viscous_settings, table, report);
  if (!root) return 0;  // under mpirun: rank 0 writes the table
  rc::write_mode_table(table, output, fields ? &mode_fields : nullptr);
  std::cout << rc::modes::table_text(table) << std::flush;
  if (req.selection.modes && table.size() < static_cast<std::size_t>(*req.selection.modes))
    std::cerr << fmt::format("cavity-modes: note: --modes {} asked, the table holds {}: this cavity has no other "
                             "coupling cluster above the selection's threshold (coverage {:.6f})\n",
                             *req.selection.modes, table.size(), table.coverage);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "cavity-modes: error: " << e.what() << "\n";
    return 1;
  }
}
