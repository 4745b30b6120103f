// `chain-rom run`: time histories, by the linearised chain (26) or, with [run] model = "nonlinear", the rigid chain
// at any angle (docs/rom.md, "Propagation", "Nonlinear chain").
#include "commands.hpp"

#include "chain_model.hpp"
#include "general_run.hpp"
#include "general_system.hpp"
#include "linear_validity.hpp"
#include "load_scene.hpp"
#include "nonlinear_run.hpp"
#include "output.hpp"
#include "propagation.hpp"
#include "scene.hpp"
#include "spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

namespace rc::rom::app {
namespace {

int run_nonlinear(const Scene& scene, const std::string& out_file) {
  const NonlinearChain chain = nonlinear_chain(scene);
  const NonlinearHistory h = integrate_nonlinear(chain, nonlinear_initial_state(scene, chain), scene.run);
  write_nonlinear_history(h, chain.size(), out_file);
  std::cout << "wrote " << out_file << ": " << h.base.t.size() << " samples, model nonlinear (Lie-group Dormand-Prince "
            << "5(4), tolerance " << scene.run.tolerance << ", " << h.base.integrator_steps << " steps, "
            << h.rejected_steps << " rejected), " << h.base.wall_seconds << " s\n";
  if (h.viscous_spin_change > kEkmanTolerance)
    std::fprintf(stderr, "chain-rom: warning: a body with a viscous tank changed its spin by %.3g %%: its table holds "
                         "for the scene's spin (Ek to %.3g %%), and the modes were scaled as if Ek stayed (docs/rom.md, "
                         "\"Nonlinear chain\", \"Viscous tanks\")\n",
                 100 * h.viscous_spin_change, 100 * kEkmanTolerance);
  const bool damped = std::any_of(chain.joints.begin(), chain.joints.end(),
                                  [](const ChainJoint& j) { return j.friction > 0 || j.axial_friction > 0; }) ||
                      std::any_of(chain.bodies.begin(), chain.bodies.end(),
                                  [](const ChainBody& b) { return b.pitch_damping > 0 || b.magnus != 0; });
  if (!h.integrals_valid) {
    std::cout << "energy: not an integral with fluid tanks in the nonlinear model (docs/rom.md, \"Nonlinear chain\")";
    if (h.momentum_valid && !external_loads(chain))
      std::cout << "; angular momentum with the liquid's " << (chain.free_chain ? "(vector)" : "(about the vertical "
                "through O_1)") << ": largest relative drift " << h.max_momentum_drift;
    std::cout << "\n";
    return 0;
  }
  std::cout << "energy: H(0) = " << h.base.H.front() << ", H(end) = " << h.base.H.back() << ", ";
  if (!std::isnan(h.base.work_balance))
    std::cout << "H(t) - H(0) = the work of the moments, forces and field less the friction's to " << h.base.work_balance
              << " of H's scale (trapezoid rule on the output samples; Batyr (11))";
  else
    std::cout << (damped ? "largest relative increase per sample " : "largest relative drift ") << h.base.max_energy_drift;
  if (external_loads(chain))
    std::cout << "; angular momentum: not an integral under the external moments, forces and fields\n";
  else
    std::cout << "; angular momentum " << (chain.free_chain ? "(vector)" : "(about the vertical through O_1)")
              << ": largest relative drift " << h.max_momentum_drift << "\n";
  return 0;
}

// An unstable scene is integrated all the same (its growth may be what the user studies), but said first: the linear
// model's tilts then grow without bound (fuzz: 30 000 degrees without a word). Returns the e-folds of the fastest
// growing root over the run (0 when stable or when the eigen-solver fails: the propagation reports its own trouble).
double warn_if_unstable(const ChainModel& model, double t_end) {
  try {
    const Verdict v = compute_verdict(model);
    if (v.stable) return 0;
    std::fprintf(stderr, "chain-rom: warning: the scene is unstable (%s %.6g %s): the linearised tilts grow "
                         "without bound and leave the model's small-angle range\n",
                 model.dissipative() ? "largest growth rate" : "margin, largest |Im sigma|", v.margin,
                 model.dissipative() ? "1/s" : "rad/s");
    return (model.dissipative() ? v.growth : v.margin) * t_end;
  } catch (const std::runtime_error&) {
    return 0;
  }
}

// Is the amplitude small enough for the linear model? Measured against the nonlinear chain, unless the tilts grow more
// than tenfold during the run: they then leave any small-angle range whatever the amplitude, and the check (a
// nonlinear run, seconds) could only say so (docs/rom.md, "Nonlinear chain").
LinearValidity check_validity(const Scene& scene, const ChainModel& model, History& h, double growth_over_run) {
  LinearValidity validity;
  if (growth_over_run > std::log(10.0)) {
    char why[200];
    std::snprintf(why, sizeof why, "the scene is unstable and its tilts grow by e^%.3g during the run, out of the "
                                   "small-angle range at any amplitude", growth_over_run);
    validity.why_not = std::string(why) + "; [run] model = \"nonlinear\" integrates the full motion";
  } else {
    const bool exact = h.method_used.rfind("exact", 0) == 0;  // then the check reuses this history
    validity = linear_validity(scene, model, exact ? &h : nullptr);
  }
  if (!validity.measured) {
    h.validity_note = validity.why_not;
    return validity;
  }
  h.nonlinear_difference = validity.difference;
  h.amplitude_at_limit = validity.amplitude_at_limit;
  if (validity.difference > kLinearValidityLimit)
    std::fprintf(stderr, "chain-rom: warning: at this amplitude (%.3g rad) the tilts differ from the nonlinear chain's "
                         "by %.2g %%: the linear model holds to 1 %% below about %.3g rad (docs/rom.md, "
                         "\"Nonlinear chain\"); [run] model = \"nonlinear\" integrates the full motion\n",
                 validity.amplitude, 100 * validity.difference, validity.amplitude_at_limit);
  return validity;
}

void print_energy(const ChainModel& model, const History& h) {
  if (h.forced && !model.viscous) {
    std::cout << "energy: H(0) = " << h.H.front() << ", H(end) = " << h.H.back()
              << " (external moments and forces do work: not an integral; docs/rom.md, \"External moments in the linear "
                 "chain\")";
    if (!std::isnan(h.work_balance))
      std::cout << "; H(t) - H(0) = their work less the friction's, to " << h.work_balance
                << " of H's scale (trapezoid rule on the output samples; Batyr (11))";
    std::cout << "\n";
    return;
  }
  if (!model.viscous) {
    std::cout << "energy: H(0) = " << h.H.front() << ", H(end) = " << h.H.back() << ", "
              << (model.has_friction() ? "largest relative increase per step " : "largest relative drift ")
              << h.max_energy_drift << "\n";
    return;
  }
  const EnergyBudget& b = h.budget;
  const EnergyBalance& e = h.balance;
  if (!e.empty())
    std::cout << "energy: H(0) = " << e.energy.front() << ", H(end) = " << e.energy.back() << " J, dissipated "
              << e.dissipated.back() << " J (fluid " << e.fluid_dissipated
              << " J); dH/dt = -(joint power + fluid dissipation) to " << e.residual
              << " on the samples (docs/rom.md, \"Galerkin tanks\")\n";
  else
    std::cout << "energy: no integral with these viscous tanks: " << galerkin_energy_unavailable(model) << "\n";
  if (b.frozen_energy.empty()) {  // propagation.cpp: not kept for a free chain with a partially filled tank
    std::cout << "energy budget: not measured (a free chain whose liquid has momentum of its own)\n";
    return;
  }
  std::cout << "energy budget of the chain with its fluid frozen: H_b(0) = " << b.frozen_energy.front()
            << ", H_b(end) = " << b.frozen_energy.back() << " J, work taken by the fluid " << b.fluid_work.back()
            << " J, friction " << b.friction_work << " J; dH_b/dt = -(friction + fluid power) to " << b.balance_residual
            << " on the samples (docs/rom.md, \"Energy budget\")\n";
}

int run_linear(const Scene& scene, const ChainModel& model, const std::string& scene_file, const std::string& out) {
  if (!scene.run.present) throw std::runtime_error(scene_file + ": run: missing [run] section");
  const double growth_over_run = warn_if_unstable(model, scene.run.t_end);
  History h = propagate(model, scene);
  const LinearValidity validity = check_validity(scene, model, h, growth_over_run);
  // A trajectory that left the double range (a scene of extreme magnitudes) is reported, never written.
  const bool energy_finite = model.viscous ||  // no energy with viscous tanks (output.cpp writes none)
                             std::all_of(h.H.begin(), h.H.end(), [](double e) { return std::isfinite(e); });
  if (!h.u.allFinite() || !h.z.allFinite() || !energy_finite)
    throw std::runtime_error("the trajectory is not finite (method " + h.method_used +
                             "): the scene's magnitudes leave double precision; nothing written");
  write_history(model, h, out);
  std::cout << "wrote " << out << ": " << h.t.size() << " samples, method " << h.method_used << ", " << h.wall_seconds
            << " s (CPU " << h.cpu_seconds << " s)\n";
  if (validity.measured)
    std::cout << "validity: the nonlinear chain differs by " << validity.difference << " relative (1 % at about "
              << validity.amplitude_at_limit << " rad; checked in " << validity.seconds << " s)\n";
  else
    std::cout << "validity: not measured (" << validity.why_not << ")\n";
  print_energy(model, h);
  return 0;
}

// The chain without axial symmetry (rom/general/): its exact propagation, its angular momentum integral when it has
// one, and its validity against the nonlinear chain.
int run_general(const Scene& scene, TableCache& tables, const std::string& scene_file, const std::string& out) {
  if (!scene.run.present) throw std::runtime_error(scene_file + ": run: missing [run] section");
  const GeneralChain g = build_general_chain(scene, &tables);
  const GeneralSpectrum sp = general_spectrum(g);
  const Verdict& v = sp.verdict;
  if (!v.stable)
    std::fprintf(stderr, "chain-rom: warning: the scene is unstable (largest growth rate %.6g 1/s): the linearised "
                         "tilts grow without bound and leave the model's small-angle range\n", v.growth);
  const GeneralHistory h = propagate_general(g, scene, sp.floquet_steps);
  write_general_history(g, h, out);
  std::cout << "wrote " << out << ": " << h.t.size() << " samples, the chain without axial symmetry propagated "
            << (g.periodic() ? "by sixth-order Magnus steps (periodic coefficients: two spins)" : "exactly") << ", "
            << h.wall_seconds << " s\n";
  if (!std::isnan(h.momentum_drift))
    std::cout << "angular momentum in space: largest relative drift " << h.momentum_drift << "\n";
  LinearValidity validity;
  if (!v.stable) validity.why_not = "the scene is unstable";
  else validity = linear_validity(scene, h.u);
  if (validity.measured)
    std::cout << "validity: the nonlinear chain differs by " << validity.difference << " relative (1 % at about "
              << validity.amplitude_at_limit << " rad; checked in " << validity.seconds << " s)\n";
  else
    std::cout << "validity: not measured (" << validity.why_not << ")\n";
  return 0;
}

}  // namespace

Command add_run_command(CLI::App& app) {
  struct Options {
    std::string scene, out;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("run", "time histories of u_k and the fluid coordinates with the energy monitored");
  cmd->add_option("SCENE", o->scene, "scene file (TOML)")->required();
  cmd->add_option("-o,--output", o->out, "output file: HDF5, or CSV when the name ends in .csv")->required();
  return {cmd, [o] {
            const Scene scene = load_scene(o->scene);
            if (scene.run.present && scene.run.nonlinear()) return run_nonlinear(scene, o->out);
            TableCache tables;
            if (needs_general_chain(scene, tables)) return run_general(scene, tables, o->scene, o->out);
            return run_linear(scene, build_model(scene, &tables), o->scene, o->out);
          }};
}

}  // namespace rc::rom::app
