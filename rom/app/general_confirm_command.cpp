// chain-rom confirm on a chain without axial symmetry (docs/rom.md, "Confirmed roots"): its 3-D response tables remade
// exact at its roots until the roots stop moving (general_confirmation.hpp), then one line per root and the verdict.
#include "confirm_command.hpp"

#include "general_confirmation.hpp"
#include "served_response.hpp"
#include "tank_responses.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <iomanip>
#include <iostream>

namespace rc::rom {
namespace {

void print_general_json(std::ostream& out, const GeneralConfirmation& c, int unconfirmed, double seconds) {
  nlohmann::ordered_json j;
  j["model"] = "general";
  j["roots"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < c.confirmed.size(); ++i)
    j["roots"].push_back({{"table", {c.table_roots[i].real(), c.table_roots[i].imag()}},
                          {"confirmed", {c.confirmed[i].real(), c.confirmed[i].imag()}},
                          {"moved", c.moved[i]}});
  j["stable"] = c.spectrum.verdict.stable;
  j["growth"] = c.spectrum.verdict.growth;
  j["growing"] = c.spectrum.verdict.growing;
  j["unconfirmed"] = unconfirmed;
  j["rounds"] = c.rounds;
  j["refined_tables"] = c.tables;
  j["seconds"] = seconds;
  out << j.dump() << "\n";
}

void print_general_text(std::ostream& out, const GeneralConfirmation& c, double tolerance, double seconds) {
  out << "roots sigma in the frame turning with the bodies: the tables' value, confirmed (the tables made exact "
         "there), the last round's move (relative)\n";
  out << std::setprecision(12);
  for (std::size_t i = 0; i < c.confirmed.size(); ++i)
    out << "  " << c.table_roots[i].real() << (c.table_roots[i].imag() < 0 ? " - " : " + ")
        << std::abs(c.table_roots[i].imag()) << "i  ->  " << c.confirmed[i].real()
        << (c.confirmed[i].imag() < 0 ? " - " : " + ") << std::abs(c.confirmed[i].imag()) << "i   " << std::setprecision(2)
        << c.moved[i] << (c.moved[i] <= tolerance ? "" : "   NOT CONFIRMED") << std::setprecision(12) << "\n";
  const Verdict& v = c.spectrum.verdict;
  out << std::setprecision(6);
  // The 3-D tables' mesh is not studied yet (docs/rom.md, "Mesh error of confirmed roots"): said where the verdict is.
  const char* mesh = "; mesh error NOT MEASURED (3-D tables: compare tables made on two meshes, docs/volume.md)";
  if (v.stable)
    out << "with the confirmed roots: stable -- no root grows by more than rounding; the slowest decays at "
        << -v.growth << " 1/s" << mesh << "\n";
  else
    out << "with the confirmed roots: unstable -- " << v.growing << (v.growing == 1 ? " root grows" : " roots grow")
        << ", the fastest at " << v.growth << " 1/s" << mesh << "\n";
  out << c.tables << (c.tables == 1 ? " table" : " tables") << " remade in " << c.rounds << " round(s) (the files "
      << "replaced: spectrum, run and sweep now give these roots), " << std::setprecision(3) << seconds << " s\n";
}

}  // namespace

int confirm_general_roots(const Scene& scene, const ConfirmRequest& req, std::ostream& out) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!req.refine_tables)
    throw SceneError(scene.file.string() + ": a chain without axial symmetry is confirmed by remaking its 3-D response "
                     "tables exact at its roots, which replaces the table files: chain-rom confirm SCENE --refine-tables "
                     "(docs/rom.md, \"Confirmed roots\")");
  std::ostream& log = req.json ? std::cerr : out;
  const ScratchFolder scratch;
  const GeneralConfirmation c = confirm_general(scene, req.all, std::max(req.tolerance, 1e-12),
                                                cavity_modes_binary(req.cavity_modes), scratch.path, req.run, log);
  int unconfirmed = 0;
  for (const double m : c.moved) unconfirmed += m > req.tolerance ? 1 : 0;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (req.json) print_general_json(out, c, unconfirmed, seconds);
  else print_general_text(out, c, req.tolerance, seconds);
  return unconfirmed;
}

}  // namespace rc::rom
