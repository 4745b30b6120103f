// spectral-window: the spectral weight Σ E of EVERY discrete eigenpair in given λ-windows, by spectrum
// slicing (no Gauss rule), for any shape, on the mesh cavity-modes would build with the same options. A table's
// /bands come from the survey's Gauss rule, whose band weights are only as sharp as its node spacing; this gives
// the exact discrete band weight of one discretisation, to separate the two errors (docs/cones.md,
// docs/trust.md).
//
//   build/modes/spectral-window cone --radius 1 --height 1 --mesh-size 0.1 --window -0.4,-0.3
//   build/modes/spectral-window section data/sections/capsule.geo --order 4 --window 0.6,0.7 --window 0.3,0.6
//
// Prints one JSON object per window (lo, hi, pairs, E, lambda_mean, E_max, lambda_of_E_max) plus ndof,
// A_f − J_zh and the run time. Cost: the slice holds about 2·ndof·(hi − lo)/4 eigenpairs; keep windows narrow
// on fine meshes.
#include "cavity_table.hpp"
#include "fe_space.hpp"
#include "petsc_handles.hpp"
#include "poincare_forms.hpp"
#include "shape_commands.hpp"
#include "stiffness_solver.hpp"
#include "window_weight.hpp"
#include "zhukovsky.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>

namespace {

struct Window {
  double lo = 0, hi = 0;
};

std::vector<Window> parse_windows(const std::vector<std::string>& specs) {
  std::vector<Window> ws;
  for (const auto& s : specs) {
    Window w;
    const auto comma = s.find(',');
    std::size_t used_lo = 0, used_hi = 0;
    try {
      if (comma == std::string::npos) throw std::invalid_argument("no comma");
      w.lo = std::stod(s.substr(0, comma), &used_lo);
      w.hi = std::stod(s.substr(comma + 1), &used_hi);
    } catch (const std::logic_error&) {
      throw std::runtime_error("--window " + s + ": expected LO,HI");
    }
    if (used_lo != comma || used_hi != s.size() - comma - 1) throw std::runtime_error("--window " + s + ": expected LO,HI");
    if (!(w.lo < w.hi && w.lo > -2 && w.hi < 2)) throw std::runtime_error("--window " + s + ": need -2 < LO < HI < 2");
    ws.push_back(w);
  }
  return ws;
}

int run(int argc, char** argv) {
  CLI::App app{"spectral-window: sum of E over every eigenpair in lambda-windows (exact discrete band weights of "
               "the mesh cavity-modes builds with the same options)"};
  app.require_subcommand(1);
  rc::modes::ShapeCommands shapes(app, ": exact band weights");
  rc::geometry::MeshOptions mesh;
  mesh.order = 6;
  std::vector<std::string> windows;
  for (auto& s : shapes.all()) {
    s.app->add_option("--order", mesh.order, "Lagrange order 1..6")->capture_default_str();
    s.app->add_option("--mesh-size", mesh.size, "element size (default: as cavity-modes, d/8; spheres and "
                                                "spheroids d/5; d the smallest dimension)");
    if (s.kind == "cylinder")
      s.app->add_option("--radial-size", mesh.radial_size, "element size along r (a structured mesh)");
    s.app->add_option("--window", windows, "LO,HI (repeatable), inside (-2, 2)")->required();
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "spectral-window: error: " << e.what() << " (see --help)\n";
    return 2;  // every command-line error, whatever CLI11's own code
  }
  const auto ws = parse_windows(windows);
  const auto shape = shapes.parsed_shape();
  int pargc = 1;
  char** pargv = argv;
  rc::modes::PetscSession session(&pargc, &pargv);
  const auto start = std::chrono::steady_clock::now();
  const rc::modes::FESpace space(rc::geometry::mesh_meridian(shape, rc::modes::mesh_method_defaults(shape, mesh)));
  const auto fluid = rc::modes::integrate_fluid(space);
  const auto forms = rc::modes::assemble_poincare_forms(space, fluid.centroid_z);
  const rc::modes::StiffnessSolver stiffness(forms.M);
  const double sum_rule = fluid.A_f - rc::modes::zhukovsky_inertia(forms, stiffness).J_zh;
  const rc::modes::QuadraticEigenSolver solver(forms, rc::modes::QepSettings{});
  for (const auto& w : ws) {
    const auto r = rc::modes::weigh_window(solver, w.lo, w.hi);
    nlohmann::json j = {{"lo", r.lo}, {"hi", r.hi}, {"pairs", r.pairs}, {"E", r.E}, {"lambda_mean", r.lambda_mean},
                        {"E_max", r.E_max}, {"lambda_of_E_max", r.lambda_of_E_max}};
    j["ndof"] = space.ndof();
    j["order"] = mesh.order;
    j["mesh_h"] = space.mesh().size;
    j["sum_rule"] = sum_rule;
    j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << j.dump() << std::endl;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "spectral-window: error: " << e.what() << "\n";
    return 1;
  }
}
