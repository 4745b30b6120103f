// `chain-rom sweep`: stability maps over one or two scene values (docs/rom.md, "Stability maps"), and over a viscous
// tank's Ekman number by forced solves (docs/rom.md, "Spin sweeps with viscous tanks").
#include "commands.hpp"

#include "chain_model.hpp"
#include "general_chain.hpp"
#include "general_confirmation.hpp"
#include "general_confirmed_sweep.hpp"
#include "confirmed_sweep.hpp"
#include "external_programs.hpp"
#include "load_scene.hpp"
#include "mesh_study_options.hpp"
#include "scene.hpp"
#include "served_response.hpp"
#include "sweep.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

namespace rc::rom::app {
namespace {

struct SweepOptions {
  std::string scene, key1, key2, out, png, cavity_modes;
  double from1 = 0, to1 = 0, from2 = 0, to2 = 0;
  int steps1 = 0, steps2 = 0, threads = 0;
  bool confirm = false, no_track = false;
  MeshStudy study;  // the confirmed sweeps' mesh study
  CLI::Option *from2_opt = nullptr, *to2_opt = nullptr, *steps2_opt = nullptr;
};

// The request, resolved once: the axes checked against the scene, the output folder, the plot tools.
struct SweepRequest {
  Scene scene;
  SweepAxis a1;
  std::optional<SweepAxis> a2;
  bool by_forced_solves = false;  // a key that moves a viscous tank's Ek, or --confirm
  bool general = false;           // ... on a chain without axial symmetry: by remade response tables
};

SweepRequest resolve(const SweepOptions& o) {
  const bool two = !o.key2.empty();
  if (two != (o.from2_opt->count() > 0) || two != (o.to2_opt->count() > 0) || two != (o.steps2_opt->count() > 0))
    throw SweepError("--param2, --from2, --to2 and --steps2 go together");
  if (o.steps1 < 1) throw SweepError("--steps " + std::to_string(o.steps1) + ": must be >= 1");
  if (two && o.steps2 < 1) throw SweepError("--steps2 " + std::to_string(o.steps2) + ": must be >= 1");
  if (two && o.key2 == o.key1) throw SweepError("--param2 " + o.key2 + ": same key as --param");
  SweepRequest r{load_scene(o.scene), {}, std::nullopt, false};
  r.a1 = SweepAxis{parse_param_key(o.key1, r.scene, "--param"), o.from1, o.to1, o.steps1};
  check_param_value(r.a1.key, o.from1, "--from (--param)");
  check_param_value(r.a1.key, o.to1, "--to (--param)");
  if (two) {
    r.a2 = SweepAxis{parse_param_key(o.key2, r.scene, "--param2"), o.from2, o.to2, o.steps2};
    check_param_value(r.a2->key, o.from2, "--from2 (--param2)");
    check_param_value(r.a2->key, o.to2, "--to2 (--param2)");
  }
  const std::filesystem::path out(o.out);
  if (out.has_parent_path() && !std::filesystem::is_directory(out.parent_path()))
    throw std::runtime_error(o.out + ": the output folder does not exist");
  const bool moves = moves_viscous_ekman(r.scene, r.a1.key) || (r.a2 && moves_viscous_ekman(r.scene, r.a2->key));
  if (moves && two)
    throw SweepError("a key that moves a viscous tank's Ekman number sweeps one value at a time (no --param2): "
                     "each point serves forced solves at its own Ek");
  // A chain without axial symmetry has no served forced solves: its response tables are remade instead
  // (general_confirmed_sweep.hpp).
  if (moves || o.confirm) {
    TableCache tables;
    r.general = needs_general_chain(r.scene, tables);
  }
  if (o.confirm && two) throw SweepError("--confirm sweeps one value at a time (no --param2)");
  if (o.confirm && !(r.general ? has_viscous_tables(r.scene) : build_model(r.scene).viscous))
    throw SweepError("--confirm: the scene has no viscous tank (its roots are (22)'s own)");
  if (r.general) check_general_refinable(r.scene);
  r.by_forced_solves = moves || o.confirm;
  if (!o.png.empty()) check_plot_tools(RC_PLOT_SWEEP_SCRIPT, "map");  // fail before the sweep, not after it
  return r;
}

// The line under the sweep's summary: whether the mesh study converged every point's growth rates, and where not.
std::string mesh_summary(const std::vector<ConfirmedSweepPoint>& points, const SweepOptions& o, bool general) {
  if (general) return "mesh error NOT MEASURED: a sweep of a chain without axial symmetry has no mesh study yet (confirm --refine-tables at a point has)";
  if (o.study.refine == 0) return "mesh error NOT MEASURED (--refine 0: the roots on the tables' mesh only)";
  std::ostringstream os;
  os << std::setprecision(3);
  const ConfirmedSweepPoint* first = nullptr;  // the first point not converged
  const ConfirmedSweepPoint* worst = nullptr;  // the largest relative error of a point's largest growth
  int open = 0, unsettled = 0, measured = 0;
  for (const ConfirmedSweepPoint& p : points) {
    if (!p.ok) continue;
    ++measured;
    if (!p.mesh_converged()) {
      ++open;
      if (!first) first = &p;
    }
    if (!p.sign_settled()) ++unsettled;
    const double rel = p.growth_error / std::abs(p.growth);
    if (!worst || !(rel <= worst->growth_error / std::abs(worst->growth))) worst = &p;
  }
  const auto where = [&](const ConfirmedSweepPoint& p) {
    std::ostringstream w;
    w << std::setprecision(6) << o.key1 << " = " << p.value << ": largest growth " << p.growth << std::setprecision(2)
      << " ± " << p.growth_error << " 1/s";
    if (!p.mesh_failure.empty()) w << " (" << p.mesh_failure << ")";
    return w.str();
  };
  if (!worst) return "mesh error NOT MEASURED: no point was evaluated";
  if (open == 0) {
    os << "mesh error: every point's growth rates within " << 100 * o.study.tolerance << " % (largest at "
       << where(*worst) << ")";
    return os.str();
  }
  os << "NOT CONVERGED in the mesh at " << open << " of " << measured << " points (first at " << where(*first) << ")";
  if (unsettled) os << "; the sign of a growth rate not settled at " << unsettled << " points";
  os << " -- a finer mesh: --mesh-size, --order, --refine (docs/rom.md, \"Mesh error of confirmed roots\")";
  return os.str();
}

int sweep_by_forced_solves(const SweepOptions& o, const SweepRequest& r) {
  const auto points = r.general ? run_general_confirmed_sweep(r.scene, r.a1, cavity_modes_binary(o.cavity_modes), 1e-10,
                                                              run_program_logged, std::cerr)
                                : run_confirmed_sweep(r.scene, r.a1, cavity_modes_binary(o.cavity_modes), 1e-10, o.study,
                                                      std::cerr);
  write_confirmed_sweep(points, r.a1, o.out);
  int stable = 0, failed = 0;
  for (const auto& p : points) {
    stable += p.ok && p.stable ? 1 : 0;
    failed += p.ok ? 0 : 1;
  }
  std::printf("wrote %s and its roots beside it: %zu points (%d stable, %d unstable, %d failed), roots %s with the "
              "fluid's own response\n", o.out.c_str(), points.size(), stable,
              static_cast<int>(points.size()) - stable - failed, failed,
              r.general ? "of the chain without axial symmetry" : "of (22)");
  std::printf("%s\n", mesh_summary(points, o, r.general).c_str());
  if (!o.png.empty()) draw_plot(RC_PLOT_SWEEP_SCRIPT, o.out, o.png, {"--growth"});
  return 0;
}

void report_failures(const SweepResult& r, const std::string& key) {
  if (r.failed == 0) return;
  for (const auto& p : r.points)
    if (!p.ok) {
      std::string msg = p.error;
      for (auto& ch : msg) if (ch == '\n') ch = ' ';
      std::fprintf(stderr, "chain-rom sweep: warning: %d points not evaluated (nan in the CSV); first at %s = %g: %s\n",
                   r.failed, key.c_str(), p.v1, msg.c_str());
      return;
    }
}

int sweep_by_roots(const SweepOptions& o, const SweepRequest& q) {
  TableCache tables;
  // Validates the scene as given and reads its tables once; a dissipative chain's margin is a growth rate.
  const bool growth_map = needs_general_chain(q.scene, tables) ? build_general_chain(q.scene, &tables).dissipative
                                                               : build_model(q.scene, &tables).dissipative();
  const SweepResult r = run_sweep(q.scene, tables, q.a1, q.a2, o.threads, [](long d, long total, double el) {
    std::fprintf(stderr, "chain-rom sweep: %ld/%ld points, %.1f s, about %.0f s left\n", d, total, el,
                 el * static_cast<double>(total - d) / static_cast<double>(d));
  }, !o.no_track);
  write_sweep_csv(r, q.a1, q.a2, o.out);
  int stable = 0;
  for (const auto& p : r.points) stable += (p.ok && p.verdict.stable) ? 1 : 0;
  std::printf("wrote %s: %zu points (%d stable, %d unstable, %d failed), %.3g s on %d thread%s\n", o.out.c_str(),
              r.points.size(), stable, static_cast<int>(r.points.size()) - stable - r.failed, r.failed, r.wall_seconds,
              r.threads, r.threads == 1 ? "" : "s");
  std::printf("roots: %ld points tracked from their neighbours, %ld by the eigen-solver%s%s\n", r.tracked,
              static_cast<long>(r.points.size()) - r.tracked - r.failed,
              r.first_fallback.empty() ? "" : "; first fallback: ", r.first_fallback.c_str());
  std::fflush(stdout);
  report_failures(r, o.key1);
  if (!o.png.empty()) draw_plot(RC_PLOT_SWEEP_SCRIPT, o.out, o.png, growth_map ? std::vector<std::string>{"--growth"}
                                                                            : std::vector<std::string>{});
  return 0;
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  auto* cmd = app.add_subcommand(
      "sweep", "stability map: verdict, margin and number of non-real roots over one or two scene values "
               "(keys like body[1].spin, joint[2].stiffness, body[3].cavity.density, system.gravity; docs/rom.md)");
  cmd->add_option("SCENE", o->scene, "scene file (TOML)")->required();
  cmd->add_option("--param", o->key1, "scene value to sweep, e.g. body[1].spin (1-based indices), or a family of "
                                      "tables, body[2].cavity.table=cone_h%.2f.h5")->required();
  cmd->add_option("--from", o->from1, "first value")->required();
  cmd->add_option("--to", o->to1, "last value")->required();
  cmd->add_option("--steps", o->steps1, "number of values, from..to inclusive (>= 1)")->required();
  cmd->add_option("--param2", o->key2, "second scene value (2D map)");
  o->from2_opt = cmd->add_option("--from2", o->from2, "first value of --param2");
  o->to2_opt = cmd->add_option("--to2", o->to2, "last value of --param2");
  o->steps2_opt = cmd->add_option("--steps2", o->steps2, "number of values of --param2 (>= 1)");
  cmd->add_option("-o,--output", o->out, "CSV: <key>[,<key2>],stable,margin,nonreal, one row per point")->required();
  cmd->add_option("--png", o->png, "also draw the map (scripts/plot_sweep.py with /usr/bin/python3 + matplotlib)");
  cmd->add_option("--threads", o->threads, "worker threads (default: all cores)");
  cmd->add_option("--cavity-modes", o->cavity_modes, "a key that moves a viscous tank's Ekman number (spin, "
                  "spin_factor, cavity scale): the cavity-modes binary that serves its forced solves (default: "
                  "$CAVITY_MODES, else the one beside chain-rom's build folder)");
  cmd->add_flag("--confirm", o->confirm, "viscous tanks: every point's body and growing roots confirmed with the "
                "fluid's own response by forced solves (docs/rom.md, \"Confirmed roots\"; always so for a key that "
                "moves a viscous tank's Ekman number)");
  add_mesh_study_options(cmd, o->study, "with --confirm or a key that moves Ek: ");
  cmd->add_flag("--no-track", o->no_track, "every point's roots by the eigen-solver (default: tracked from the "
                                           "neighbouring point's, checked, the eigen-solver where the check fails)");
  return {cmd, [o] {
            const SweepRequest r = resolve(*o);
            return r.by_forced_solves ? sweep_by_forced_solves(*o, r) : sweep_by_roots(*o, r);
          }};
}

}  // namespace rc::rom::app
