// chain-rom confirm on a chain without axial symmetry (docs/rom.md, "Confirmed roots"): its response tables (3-D, or
// axisymmetric Krylov) remade exact at its roots until the roots stop moving (general_confirmation.hpp), the mesh
// check — the same on tables made again on a coarser 3-D mesh or a finer meridian one (general_mesh_check.hpp) — then
// one line per root and the verdict with the mesh error.
#include "confirm_command.hpp"

#include "general_confirmation.hpp"
#include "general_mesh_check.hpp"
#include "served_response.hpp"
#include "tank_responses.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace rc::rom {
namespace {

constexpr double kCoarsen = 1.5;  // the check's mesh: every element size 1.5 times the table's (general_mesh_check.hpp)

// "against tables on a mesh 1.5 times as coarse" or "against tables one mesh level finer", as the check was made.
std::string check_mesh_text(const GeneralMeshCheck& check) {
  if (check.finer) return "on tables one mesh level finer against the tables' own";
  std::ostringstream os;
  os << "against tables on a mesh " << check.coarsen << " times as coarse";
  return os.str();
}

// The check, or why there is none (--refine 0, or a check's table that could not be made).
struct MeshCheckOutcome {
  std::optional<GeneralMeshCheck> check;
  std::string not_measured;
};

void print_general_json(std::ostream& out, const GeneralConfirmation& c, const MeshCheckOutcome& m, int unconfirmed,
                        double seconds) {
  nlohmann::ordered_json j;
  j["model"] = "general";
  j["roots"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < c.confirmed.size(); ++i) {
    nlohmann::ordered_json r{{"table", {c.table_roots[i].real(), c.table_roots[i].imag()}},
                             {"confirmed", {c.confirmed[i].real(), c.confirmed[i].imag()}},
                             {"moved", c.moved[i]}};
    if (m.check) {
      const MeshErrorEstimate& e = m.check->errors[i];
      r[m.check->finer ? "finer" : "coarse"] = {m.check->twins[i].real(), m.check->twins[i].imag()};
      r["growth"] = e.growth;
      r["growth_error"] = e.error;
      r["mesh_converged"] = e.converged;
    }
    j["roots"].push_back(r);
  }
  j["stable"] = c.spectrum.verdict.stable;
  j["growth"] = c.spectrum.verdict.growth;
  j["growing"] = c.spectrum.verdict.growing;
  j["unconfirmed"] = unconfirmed;
  j["rounds"] = c.rounds;
  j["refined_tables"] = c.tables;
  j["mesh_converged"] = m.check ? m.check->all_converged() : false;
  if (m.check && m.check->finer) j["mesh_finer_levels"] = 1;
  else if (m.check) j["mesh_coarsen"] = m.check->coarsen;
  else j["mesh_not_measured"] = m.not_measured;
  j["seconds"] = seconds;
  out << j.dump() << "\n";
}

std::string complex_text(std::complex<double> z) {
  std::ostringstream os;
  os << std::setprecision(12) << z.real() << (z.imag() < 0 ? " - " : " + ") << std::abs(z.imag()) << "i";
  return os.str();
}

// What the mesh check adds to the verdict line: converged to what, or which rate is not, or why nothing was measured.
std::string mesh_verdict(const GeneralConfirmation& c, const MeshCheckOutcome& m, double tolerance) {
  if (!m.check) return "; mesh error NOT MEASURED (" + m.not_measured + ")";
  const GeneralMeshCheck& check = *m.check;
  if (check.errors.empty()) return "; mesh error: no root to check";
  std::size_t worst = 0;
  for (std::size_t j = 1; j < check.errors.size(); ++j)
    if (!(check.errors[j].relative() <= check.errors[worst].relative())) worst = j;
  std::ostringstream os;
  os << std::setprecision(2);
  const std::string root = "the root " + complex_text(c.confirmed[worst]);
  if (check.all_converged()) {
    os << "; mesh error: every growth rate within " << 100 * tolerance << " % (largest: " << root << ", "
       << rate_with_error(check.errors[worst]) << ", " << check_mesh_text(check) << ")";
    return os.str();
  }
  os << "; NOT CONVERGED in the mesh: " << root << "'s " << rate_with_error(check.errors[worst]) << " against the "
     << 100 * tolerance << " % tolerance";
  if (!check.signs_settled()) os << ", and the sign of a growth rate is not settled by the mesh";
  if (check.finer) os << " -- finer tables: cavity-modes response SHAPE --mesh-size, --order, --mesh-level (docs/viscous.md)";
  else os << " -- finer 3-D tables: cavity-modes ellipsoid|volume --mesh-size, --wall-size, --order (docs/volume.md §7)";
  return os.str();
}

void print_roots(std::ostream& out, const GeneralConfirmation& c, const MeshCheckOutcome& m, double tolerance) {
  out << "roots sigma in the frame turning with the bodies: the tables' value, confirmed (the tables made exact "
         "there), the last round's move (relative)"
      << (!m.check ? "" : m.check->finer ? "; the growth rate on the finer tables with its mesh error (against the tables' root)"
                                          : "; the growth rate with its mesh error (against the coarse tables' root)")
      << "\n";
  for (std::size_t i = 0; i < c.confirmed.size(); ++i) {
    out << "  " << complex_text(c.table_roots[i]) << "  ->  " << complex_text(c.confirmed[i]) << "   "
        << std::setprecision(2) << c.moved[i] << (c.moved[i] <= tolerance ? "" : "   NOT CONFIRMED");
    if (m.check) {
      const MeshErrorEstimate& e = m.check->errors[i];
      out << "   " << rate_with_error(e) << (e.converged ? "  converged" : "  NOT CONVERGED")
          << (e.sign_settled ? "" : ", sign not settled");
    }
    out << "\n";
  }
}

void print_general_text(std::ostream& out, const GeneralConfirmation& c, const MeshCheckOutcome& m,
                        const ConfirmRequest& req, double seconds) {
  print_roots(out, c, m, req.tolerance);
  const Verdict& v = c.spectrum.verdict;
  out << std::setprecision(6);
  const std::string mesh = mesh_verdict(c, m, req.mesh.tolerance);
  if (v.stable)
    out << "with the confirmed roots: stable -- no root grows by more than rounding; the slowest decays at "
        << -v.growth << " 1/s" << mesh << "\n";
  else
    out << "with the confirmed roots: unstable -- " << v.growing << (v.growing == 1 ? " root grows" : " roots grow")
        << ", the fastest at " << v.growth << " 1/s" << mesh << "\n";
  out << c.tables << (c.tables == 1 ? " table" : " tables") << " remade in " << c.rounds << " round(s) (the files "
      << "replaced: spectrum, run and sweep now give these roots)";
  if (m.check) out << "; the mesh check's " << (m.check->finer ? "finer" : "coarse") << " tables in " << m.check->rounds << " round(s)";
  out << ", " << std::setprecision(3) << seconds << " s\n";
}

// --mesh-size, --order and --refine-by choose the forced solves' meshes of axisymmetric tanks; a 3-D table's own
// options do that here (docs/rom.md, "Mesh error of confirmed roots").
void check_general_mesh_options(const Scene& scene, const MeshStudy& study) {
  if (study.base.mesh_size > 0 || study.base.order > 0 || study.by_order || study.refine > 1)
    throw SceneError(scene.file.string() + ": a chain without axial symmetry checks its tables' mesh on one other mesh "
                     "(3-D tables 1.5 times as coarse, axisymmetric Krylov tables one level finer: --refine 1, the "
                     "default, or 0 for none); --mesh-size, --order, --refine-by and --refine 2..3 choose the served "
                     "forced solves of a chain with axial symmetry: make finer tables instead (cavity-modes "
                     "ellipsoid|volume --mesh-size, --wall-size, --order, docs/volume.md §7; cavity-modes response SHAPE "
                     "--mesh-size, --order, --mesh-level, docs/viscous.md)");
}

}  // namespace

int confirm_general_roots(const Scene& scene, const ConfirmRequest& req, std::ostream& out) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!req.refine_tables)
    throw SceneError(scene.file.string() + ": a chain without axial symmetry is confirmed by remaking its response "
                     "tables exact at its roots, which replaces the table files: chain-rom confirm SCENE --refine-tables "
                     "(docs/rom.md, \"Confirmed roots\")");
  check_general_mesh_options(scene, req.mesh);
  std::ostream& log = req.json ? std::cerr : out;
  const ScratchFolder scratch;
  const std::string binary = cavity_modes_binary(req.cavity_modes);
  const double tolerance = std::max(req.tolerance, 1e-12);
  const GeneralConfirmation c = confirm_general(scene, req.all, tolerance, binary, scratch.path, req.run, log);
  MeshCheckOutcome m;
  if (req.mesh.refine == 0) m.not_measured = "--refine 0: the roots on the tables' mesh only";
  else if (c.tables == 0) m.not_measured = "no viscous table";
  else {
    try {
      m.check = check_general_mesh(scene, c.confirmed, req.all, kCoarsen, req.mesh.tolerance, c.spectrum.verdict.noise,
                                   tolerance, binary, scratch.path, req.run, log);
    } catch (const std::runtime_error& e) {
      m.not_measured = std::string("the check's tables could not be made: ") + e.what();
    }
  }
  int unconfirmed = 0;
  for (const double moved : c.moved) unconfirmed += moved > req.tolerance ? 1 : 0;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (req.json) print_general_json(out, c, m, unconfirmed, seconds);
  else print_general_text(out, c, m, req, seconds);
  return unconfirmed;
}

}  // namespace rc::rom
