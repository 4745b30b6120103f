// `chain-rom spectrum` and `chain-rom confirm`: the roots, the verdict, and the roots again with the fluid's own
// response (docs/rom.md, "Spectrum", "Confirmed roots").
#include "commands.hpp"

#include "chain_model.hpp"
#include "companion_check.hpp"
#include "confirm_command.hpp"
#include "external_programs.hpp"
#include "general_output.hpp"
#include "load_scene.hpp"
#include "mesh_study_options.hpp"
#include "output.hpp"
#include "scene.hpp"
#include "spectrum.hpp"

#include <iostream>
#include <memory>
#include <string>

namespace rc::rom::app {
namespace {

void add_cavity_modes_option(CLI::App* cmd, ConfirmRequest& req, const char* when) {
  cmd->add_option("--cavity-modes", req.cavity_modes, std::string(when) + "the cavity-modes binary (default: "
                                                      "$CAVITY_MODES, else the one beside chain-rom's build folder)");
}

int confirm_exit(const Scene& scene, const ConfirmRequest& req) { return confirm_roots(scene, req, std::cout) > 0 ? 3 : 0; }

// A chain without axial symmetry (rom/general/): its own model and roots (--confirm goes to confirm, which takes it).
template <class Options>
int general_spectrum_command(const Scene& scene, TableCache& tables, const Options& o) {
  const GeneralChain g = build_general_chain(scene, &tables);
  const GeneralSpectrum sp = general_spectrum(g);
  if (o.json) std::cout << general_spectrum_json(g, sp) << "\n";
  else print_general_spectrum(std::cout, g, sp);
  return 0;
}

}  // namespace

Command add_spectrum_command(CLI::App& app) {
  struct Options {
    std::string scene;
    bool json = false, confirm = false, all = false;
    ConfirmRequest confirm_request;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("spectrum", "characteristic roots sigma (e^{i sigma t}), stability verdict, margin");
  cmd->add_option("SCENE", o->scene, "scene file (TOML)")->required();
  cmd->add_flag("--json", o->json, "print {\"roots\", \"stable\", \"margin\", \"det_residual\"} as JSON");
  cmd->add_flag("--all", o->all, "list every root (default: the bodies' roots, the growing ones and those a check "
                                 "marks, and one line on the rest)");
  cmd->add_flag("--confirm", o->confirm, "viscous tanks: what chain-rom confirm prints, the roots the verdict rests "
                                         "on with the fluid's own response (docs/rom.md, \"Confirmed roots\")");
  add_cavity_modes_option(cmd, o->confirm_request, "with --confirm: ");
  add_mesh_study_options(cmd, o->confirm_request.mesh, "with --confirm: ");
  return {cmd, [o] {
            const Scene scene = load_scene(o->scene);
            TableCache tables;
            if (o->confirm) {
              o->confirm_request.json = o->json;
              return confirm_exit(scene, o->confirm_request);
            }
            if (needs_general_chain(scene, tables)) return general_spectrum_command(scene, tables, *o);
            const ChainModel model = build_model(scene, &tables);  // the tables needs_general_chain read
            Spectrum sp = compute_spectrum(model);
            if (has_companions(scene))
              mark_companion_shifts(sp, compute_spectrum(build_model(with_companions(scene))));
            if (o->json) std::cout << spectrum_json(model, sp) << "\n";
            else print_spectrum(std::cout, model, sp, o->all);
            return 0;
          }};
}

Command add_confirm_command(CLI::App& app) {
  struct Options {
    std::string scene;
    ConfirmRequest request;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "confirm", "the roots of spectrum checked against the viscous tanks' own response: each body root and each "
                 "growing root iterated on (22) with R(s) by forced solves on the table's mesh (cavity-modes response "
                 "--serve), and the verdict from them (docs/rom.md, \"Confirmed roots\")");
  cmd->add_option("SCENE", o->scene, "scene file (TOML)")->required();
  cmd->add_flag("--all", o->request.all, "every root, not only the body roots and the growing ones");
  cmd->add_option("--tolerance", o->request.tolerance, "relative step at which a root counts as converged "
                                                       "(default 1e-10)")->check(CLI::PositiveNumber);
  add_cavity_modes_option(cmd, o->request, "");
  cmd->add_flag("--json", o->request.json, "print {\"roots\", \"stable\", \"growth\", \"unconfirmed\", ...} as JSON");
  cmd->add_flag("--refine-tables", o->request.refine_tables,
                "then remake each viscous tank's Krylov response table with its R exact at the confirmed roots "
                "(cavity-modes response ... --exact-at; the file replaced when that succeeds), so that spectrum, run "
                "and sweep give the confirmed roots; prints how far the new tables' roots are from them");
  add_mesh_study_options(cmd, o->request.mesh);
  o->request.run = run_program_logged;
  return {cmd, [o] { return confirm_exit(load_scene(o->scene), o->request); }};
}

}  // namespace rc::rom::app
