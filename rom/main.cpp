// chain-rom: characteristic roots and time histories of a chain of spinning bodies with
// fluid-filled cavities (SPEC §3-4). One-line error and exit code 1 on bad input.
#include "chain_model.hpp"
#include "output.hpp"
#include "propagation.hpp"
#include "scene.hpp"
#include "spectrum.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"chain-rom: stability and motion of a chain of n spinning bodies with fluid-filled "
               "cavities (reads mode tables written by cavity-modes; scene format: docs/scene-format.md)"};
  app.require_subcommand(1);
  std::string scene_file, out_file;
  bool json = false;
  auto* spec = app.add_subcommand("spectrum", "characteristic roots sigma (e^{i sigma t}), stability verdict, margin");
  spec->add_option("SCENE", scene_file, "scene file (TOML)")->required();
  spec->add_flag("--json", json, "print {\"roots\", \"stable\", \"margin\", \"det_residual\"} as JSON");
  auto* run = app.add_subcommand("run", "time histories of u_k and the fluid coordinates with the energy monitored");
  run->add_option("SCENE", scene_file, "scene file (TOML)")->required();
  run->add_option("-o,--output", out_file, "output file: HDF5, or CSV when the name ends in .csv")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    const rc::rom::Scene scene = rc::rom::parse_scene(scene_file);
    const rc::rom::ChainModel model = rc::rom::build_model(scene);
    if (spec->parsed()) {
      const rc::rom::Spectrum sp = rc::rom::compute_spectrum(model);
      if (json) std::cout << rc::rom::spectrum_json(sp) << "\n";
      else rc::rom::print_spectrum(std::cout, model, sp);
    } else {
      if (!scene.run.present) throw std::runtime_error(scene_file + ": run: missing [run] section");
      const rc::rom::History h = rc::rom::propagate(model, scene);
      rc::rom::write_history(model, h, out_file);
      std::cout << "wrote " << out_file << ": " << h.t.size() << " samples, method " << h.method_used
                << ", " << h.wall_seconds << " s\n";
      std::cout << "energy: H(0) = " << h.H.front() << ", H(end) = " << h.H.back() << ", "
                << (model.has_friction() ? "largest relative increase per step " : "largest relative drift ")
                << h.max_energy_drift << "\n";
    }
  } catch (const std::exception& e) {
    std::string msg = e.what();
    for (auto& ch : msg) if (ch == '\n') ch = ' ';
    std::cerr << "chain-rom: error: " << msg << "\n";
    return 1;
  }
  return 0;
}
