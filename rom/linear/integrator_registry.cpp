// The registry of run.method's integrators (integrator.hpp). A new one: its file under linear/integrators/ and one line
// here (its declaration and its entry).
#include "integrator.hpp"

namespace rc::rom {

LinearIntegrator exact_integrator();  // integrators/exact_integrator.cpp
LinearIntegrator gauss_integrator();  // integrators/gauss_integrator.cpp
LinearIntegrator rk45_integrator();   // integrators/rk45_integrator.cpp

const std::vector<LinearIntegrator>& linear_integrators() {
  static const std::vector<LinearIntegrator> all = {exact_integrator(), gauss_integrator(), rk45_integrator()};
  return all;
}

const LinearIntegrator& linear_integrator(const Scene& scene) {
  std::string names;
  for (const LinearIntegrator& i : linear_integrators()) {
    if (i.name == scene.run.method) return i;
    names += (names.empty() ? "\"" : ", \"") + i.name + "\"";
  }
  fail(scene, "run.method", "must be one of " + names + " (got \"" + scene.run.method + "\")");
}

double estimate_integrator_steps(const std::string& method, double rho, const RunSpec& run) {
  for (const LinearIntegrator& i : linear_integrators())
    if (i.name == method) return i.estimate_steps ? i.estimate_steps(rho, run) : 0.0;
  return 0.0;
}

}  // namespace rc::rom
