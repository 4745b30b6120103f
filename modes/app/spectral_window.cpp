// spectral-window: the spectral weight Σ E of EVERY discrete eigenpair in given λ-windows, by spectrum
// slicing (no Gauss rule). A development tool of the cone study (docs/cones.md, bench/cone_study.py):
// a table's /bands come from the survey's Gauss rule, whose band weights are only as sharp as its node
// spacing; this gives the exact discrete band weight of one discretisation, to separate the two errors.
//
//   build/modes/spectral-window cone --radius 1 --height 1 --order 6 --mesh-size 0.1 --window -0.4,-0.3
//
// Prints one JSON object per window (lo, hi, pairs, E, lambda_mean, E_max, lambda_of_E_max) plus ndof,
// A_f − J_zh and the run time. Cost: the slice holds about 2·ndof·(hi − lo)/4 eigenpairs; keep windows narrow
// on fine meshes.
#include "fe_space.hpp"
#include "petsc_handles.hpp"
#include "poincare_forms.hpp"
#include "qep_solver.hpp"
#include "stiffness_solver.hpp"
#include "zhukovsky.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>

namespace {

struct Window {
  double lo = 0, hi = 0;
};

nlohmann::json weigh(const rc::modes::QuadraticEigenSolver& solver, const Window& w) {
  const auto sol = solver.solve_interval(w.lo, w.hi);
  double E = 0, El = 0, Emax = 0, lmax = 0;
  for (const auto& p : sol.pairs) {
    E += p.coupling.E;
    El += p.coupling.E * p.lambda;
    if (p.coupling.E > Emax) { Emax = p.coupling.E; lmax = p.lambda; }
  }
  return {{"lo", w.lo}, {"hi", w.hi}, {"pairs", sol.pairs.size()}, {"E", E},
          {"lambda_mean", E > 0 ? El / E : 0.0}, {"E_max", Emax}, {"lambda_of_E_max", lmax}};
}

int run(int argc, char** argv) {
  CLI::App app{"spectral-window: sum of E over every eigenpair in lambda-windows (exact discrete band weights)"};
  std::string kind;
  double radius = 0, height = 0;
  rc::geometry::MeshOptions mesh;
  mesh.order = 6;
  std::vector<std::string> windows;
  app.add_option("shape", kind, "cylinder or cone")->required()->check(CLI::IsMember({"cylinder", "cone"}));
  app.add_option("--radius", radius, "radius (cone: of the lid)")->required();
  app.add_option("--height", height, "height")->required();
  app.add_option("--order", mesh.order, "element order")->capture_default_str();
  app.add_option("--mesh-size", mesh.size, "element size (0: the shape's default)")->capture_default_str();
  app.add_option("--window", windows, "LO,HI (repeatable), inside (-2, 2)")->required();
  CLI11_PARSE(app, argc, argv);

  std::vector<Window> ws;
  for (const auto& s : windows) {
    Window w;
    const auto comma = s.find(',');
    if (comma == std::string::npos) throw std::runtime_error("--window " + s + ": expected LO,HI");
    w.lo = std::stod(s.substr(0, comma));
    w.hi = std::stod(s.substr(comma + 1));
    if (!(w.lo < w.hi && w.lo > -2 && w.hi < 2)) throw std::runtime_error("--window " + s + ": need -2 < LO < HI < 2");
    ws.push_back(w);
  }
  int pargc = 1;
  char** pargv = argv;
  rc::modes::PetscSession session(&pargc, &pargv);
  const auto start = std::chrono::steady_clock::now();
  rc::geometry::ShapeSpec shape;
  shape.kind = kind;
  shape.dims = {{"radius", radius}, {"height", height}};
  const rc::modes::FESpace space(rc::geometry::mesh_meridian(shape, mesh));
  const auto fluid = rc::modes::integrate_fluid(space);
  const auto forms = rc::modes::assemble_poincare_forms(space, fluid.centroid_z);
  const rc::modes::StiffnessSolver stiffness(forms.M);
  const double sum_rule = fluid.A_f - rc::modes::zhukovsky_inertia(forms, stiffness).J_zh;
  const rc::modes::QuadraticEigenSolver solver(forms, rc::modes::QepSettings{});
  for (const auto& w : ws) {
    auto j = weigh(solver, w);
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
