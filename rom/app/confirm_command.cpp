#include "confirm_command.hpp"

#include "chain_model.hpp"
#include "general_chain.hpp"
#include "output.hpp"
#include "root_confirmation.hpp"
#include "spectrum.hpp"
#include "tank_responses.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace rc::rom {
namespace fs = std::filesystem;
namespace {
using cd = std::complex<double>;

// The roots a verdict rests on: body roots and growing roots (all with --all); never those at sigma = 0.
bool selected(const Root& r, const Spectrum& sp, bool all) {
  if (std::abs(r.sigma) <= sp.tolerance) return false;
  return all || r.owner.rfind("body", 0) == 0 || -r.sigma.imag() > sp.noise;
}

// After --refine-tables: the spectrum of the remade tables against the confirmed roots, one line per root; returns
// the largest relative distance.
double compare_refined(const Scene& scene, const std::vector<cd>& confirmed, std::ostream& log) {
  const Spectrum sp = compute_spectrum(build_model(scene));
  double worst = 0;
  log << "spectrum with the refined tables against the confirmed roots:" << std::endl;
  for (const cd& c : confirmed) {
    const auto nearest = std::min_element(sp.roots.begin(), sp.roots.end(), [&](const Root& a, const Root& b) {
      return std::abs(a.sigma - c) < std::abs(b.sigma - c);
    });
    const double d = std::abs(nearest->sigma - c) / std::abs(c);
    worst = std::max(worst, d);
    log << "  " << std::setw(10) << nearest->owner << "  " << std::setw(34) << root_text(nearest->sigma)
        << std::setprecision(2) << "  relative distance " << d << std::endl;
  }
  return worst;
}

}  // namespace

namespace {

// What the iteration gave: the spectrum with the confirmed roots in place, its verdict, and one JSON row a root.
struct Confirmation {
  Spectrum spectrum;
  Verdict verdict;
  nlohmann::ordered_json roots = nlohmann::ordered_json::array();
  std::vector<cd> sigmas;  // the converged roots
  int unconfirmed = 0;
  std::vector<std::size_t> selected;  // the confirmed roots' places in `spectrum`
  std::vector<cd> level0;             // each selected root on the table's mesh (NaN: not confirmed)
};

// The verdict again from the spectrum's roots as they now stand.
void give_verdict(const ChainModel& m, Confirmation& c) {
  Eigen::VectorXcd sigma(static_cast<Eigen::Index>(c.spectrum.roots.size()));
  for (std::size_t j = 0; j < c.spectrum.roots.size(); ++j)
    sigma[static_cast<Eigen::Index>(j)] = c.spectrum.roots[j].sigma;
  c.verdict = verdict_from_roots(m, sigma);
  c.spectrum.stable = c.verdict.stable;
  c.spectrum.growth = c.verdict.growth;
  c.spectrum.margin = c.verdict.margin;
  c.spectrum.growing = c.verdict.growing;
}

// Iterates every selected root of `sp` on (22) with the tanks' own R, one line each on `log`, and gives the verdict
// again from the confirmed roots (the others as the table gives them).
Confirmation confirm_selected(const ChainModel& m, const Spectrum& sp, const TankResponses& tanks,
                              const ConfirmRequest& req, std::ostream& log) {
  ConfirmSettings settings;
  settings.tolerance = req.tolerance;
  Confirmation c{sp, {}, {}, {}, 0, {}, {}};
  int count = 0;
  for (const Root& r : sp.roots) count += selected(r, sp, req.all) ? 1 : 0;
  log << "roots of (22) with R itself, from the table's (" << count << " roots; docs/rom.md, \"Confirmed roots\"):"
      << std::endl;
  for (std::size_t j = 0; j < c.spectrum.roots.size(); ++j) {
    Root& r = c.spectrum.roots[j];
    if (!selected(r, sp, req.all)) continue;
    const ConfirmedRoot root = confirm_root(m, tanks.responses, r.sigma, settings);
    log << "  " << std::setw(10) << r.owner << "  " << std::setw(34) << root_text(root.start) << "  ->  "
        << std::setw(34) << root_text(root.sigma) << std::setprecision(2) << "  moved " << root.moved() << ", "
        << root.evaluations << " evaluations" << (root.converged ? "" : "  NOT CONFIRMED: " + root.failure)
        << std::endl;
    c.roots.push_back({{"owner", r.owner}, {"table", {root.start.real(), root.start.imag()}},
                       {"confirmed", {root.sigma.real(), root.sigma.imag()}}, {"converged", root.converged},
                       {"moved", root.moved()}, {"evaluations", root.evaluations}});
    c.selected.push_back(j);
    if (root.converged) {
      r.sigma = root.sigma;
      c.sigmas.push_back(root.sigma);
      c.level0.push_back(root.sigma);
    } else {
      ++c.unconfirmed;
      c.level0.push_back({std::nan(""), std::nan("")});
    }
  }
  give_verdict(m, c);
  return c;
}

// The mesh study's finest roots in place of the table mesh's, the verdict again from them, and each root's levels
// and rate error in its JSON row.
void take_finest_roots(const ChainModel& m, const MeshStudyResult& study, Confirmation& c) {
  for (std::size_t j = 0; j < c.selected.size(); ++j) {
    const MeshErrorEstimate& e = study.errors[j];
    auto& row = c.roots[j];
    nlohmann::ordered_json levels = nlohmann::ordered_json::array();
    for (const auto& level : study.levels) levels.push_back({level[j].real(), level[j].imag()});
    row["mesh_levels"] = levels;
    row["growth"] = e.growth;
    row["growth_error"] = e.error;
    row["mesh_converged"] = e.converged;
    row["sign_settled"] = e.sign_settled;
    if (e.order > 0) row["observed_order"] = e.order, row["extrapolated_growth"] = e.extrapolated;
    if (std::isfinite(e.sigma.real()) && std::isfinite(e.sigma.imag()))
      c.spectrum.roots[c.selected[j]].sigma = e.sigma;
  }
  give_verdict(m, c);
}

// --refine-tables: the remade tables and how far their spectrum's roots are from the confirmed ones (-1: none).
struct Refinement {
  std::vector<RefinedTable> tables;
  double distance = -1;
  double seconds() const {
    double s = 0;
    for (const RefinedTable& t : tables) s += t.seconds;
    return s;
  }
};

void print_json(std::ostream& out, const Confirmation& c, const Refinement& refinement, bool refine,
                const MeshStudyResult* study, int solves, double seconds) {
  nlohmann::ordered_json j;
  j["roots"] = c.roots;
  j["stable"] = c.verdict.stable;
  j["growth"] = c.verdict.growth;
  j["growing"] = c.verdict.growing;
  j["unconfirmed"] = c.unconfirmed;
  if (study) {
    j["mesh_levels"] = study->levels.size();
    j["mesh_unknowns"] = study->unknowns;
    j["mesh_converged"] = study->all_converged();
    j["signs_settled"] = study->signs_settled();
    j["symmetry_defect"] = study->symmetry_defect;
    if (!study->failure.empty()) j["mesh_failure"] = study->failure;
  }
  j["forced_solves"] = solves;
  if (refine) {
    j["refined_tables"] = refinement.tables.size();
    j["refined_distance"] = refinement.distance;
    j["refine_seconds"] = refinement.seconds();
  }
  j["seconds"] = seconds;
  out << j.dump() << "\n";
}

// One line per selected root: its growth rate on the finest level with the mesh error.
void print_mesh_errors(std::ostream& out, const Confirmation& c, const MeshStudyResult& study, double tolerance) {
  out << "growth rates with their mesh error (" << study.levels.size() << " mesh levels, each "
      << (study.by_order ? "raising the order by one" : "halving every size") << "; "
      << "tolerance " << std::setprecision(2) << 100 * tolerance << " %; docs/rom.md, \"Mesh error of confirmed roots\"):\n";
  for (std::size_t j = 0; j < c.selected.size(); ++j) {
    const MeshErrorEstimate& e = study.errors[j];
    out << "  " << std::setw(10) << c.spectrum.roots[c.selected[j]].owner << "  " << std::setw(34)
        << root_text(e.sigma) << "  " << rate_with_error(e)
        << (e.converged ? "  converged" : "  NOT CONVERGED") << (e.sign_settled ? "" : ", sign not settled");
    if (e.order > 0)
      out << std::setprecision(3) << "  (order " << e.order << ", extrapolated " << e.extrapolated << " 1/s)";
    out << "\n";
  }
  if (study.symmetry_defect.empty() || std::isnan(study.symmetry_defect.front())) return;
  out << "mirror symmetry: |R_fg| / sqrt(|R_ff R_gg|) at the roots, 0 for the liquid itself (its mid-plane), on each "
      << "level:";
  for (double d : study.symmetry_defect) out << " " << std::setprecision(2) << d;
  out << " (the mesh's own asymmetry)\n";
}

// What the mesh study adds to the verdict line: converged to what, or which rate is not and by how much.
std::string mesh_verdict(const Confirmation& c, const MeshStudyResult& study, double tolerance) {
  if (study.errors.empty()) return "";
  std::ostringstream os;
  os << std::setprecision(2);
  std::size_t worst = 0;
  for (std::size_t j = 1; j < study.errors.size(); ++j)
    if (!(study.errors[j].relative() <= study.errors[worst].relative())) worst = j;
  const MeshErrorEstimate& w = study.errors[worst];
  const std::string who = c.spectrum.roots[c.selected[worst]].owner;
  if (study.all_converged()) {
    os << "; mesh error: every growth rate within " << 100 * tolerance << " % (largest: " << who << ", "
       << rate_with_error(w) << ")";
    return os.str();
  }
  os << "; NOT CONVERGED in the mesh: " << who << "'s " << rate_with_error(w) << " against the " << 100 * tolerance
     << " % tolerance";
  if (!study.signs_settled()) os << ", and the sign of a growth rate is not settled by the mesh";
  if (!study.failure.empty()) os << " (" << study.failure << ")";
  os << " -- a finer mesh: chain-rom confirm --mesh-size, --order, --refine (docs/rom.md, \"Mesh error of confirmed "
     << "roots\")";
  return os.str();
}

void print_text(std::ostream& out, const ChainModel& m, const Confirmation& c, const Refinement& refinement,
                const MeshStudyResult* study, double tolerance, int solves, double seconds) {
  if (study) print_mesh_errors(out, c, *study, tolerance);
  // The mesh's word goes on the verdict's own line, the first.
  std::ostringstream verdict;
  verdict << std::setprecision(6) << verdict_with_dissipation(m, c.spectrum);
  std::string text = verdict.str();
  const std::string mesh = study ? mesh_verdict(c, *study, tolerance)
                                 : "; mesh error NOT MEASURED (--refine 0: the roots on the tables' mesh only)";
  text.insert(std::min(text.find('\n'), text.size()), mesh);
  out << "with the confirmed roots: " << text << "\n";
  if (c.unconfirmed)
    out << "warning: " << c.unconfirmed << " roots NOT CONFIRMED (marked above): the verdict takes the table's value "
        << "for them\n";
  if (refinement.distance >= 0)
    out << std::setprecision(2) << refinement.tables.size() << " tables refined: spectrum's roots are now the "
        << "confirmed ones to " << refinement.distance << " relative\n";
  out << solves << " forced solves, " << std::setprecision(3) << seconds << " s\n";
}

}  // namespace

int confirm_roots(const Scene& scene, const ConfirmRequest& req, std::ostream& out) {
  {
    TableCache tables;
    if (needs_general_chain(scene, tables)) return confirm_general_roots(scene, req, out);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const ChainModel m = build_model(scene);
  std::ostream& log = req.json ? std::cerr : out;
  if (m.viscous && req.refine_tables) check_refinable(scene, m);
  if (!m.viscous) {
    if (req.json) out << nlohmann::json{{"roots", nlohmann::json::array()}, {"unconfirmed", 0}}.dump() << "\n";
    else out << "no viscous tank: the roots of spectrum are (22)'s own, nothing to confirm\n";
    return 0;
  }
  const ScratchFolder scratch;
  log << "the fluid's own response R(s) by forced solves (cavity-modes response ... --serve), one per viscous tank:"
      << std::endl;
  const std::string binary = cavity_modes_binary(req.cavity_modes);
  TankResponses tanks = serve_tanks(scene, m, binary, scratch.path, log, {}, nullptr, req.mesh.base);
  const Spectrum sp = compute_spectrum(m);
  Confirmation c = confirm_selected(m, sp, tanks, req, log);
  int solves = tanks.solves();
  std::optional<MeshStudyResult> study;
  if (req.mesh.refine > 0 && !c.selected.empty()) {
    std::vector<long> unknowns;
    for (const auto& s : tanks.served) unknowns.push_back(s->unknowns());
    const double symmetry = symmetry_defect(m, tanks.responses, c.level0);
    solves = tanks.solves();
    tanks = {};  // one level's factorisations in memory at a time
    ConfirmSettings settings;
    settings.tolerance = req.tolerance;
    study = study_mesh(scene, m, c.level0, unknowns, symmetry, req.mesh, binary, scratch.path, settings, sp.noise,
                       log);
    solves += study->solves;
    take_finest_roots(m, *study, c);
  }
  Refinement refinement;
  if (req.refine_tables && !c.sigmas.empty()) {
    tanks = {};  // the served solvers' memory back before the tables are remade
    log << "tables remade with R exact at the confirmed roots (cavity-modes response ... --exact-at):" << std::endl;
    refinement.tables = refine_tables(scene, m, c.sigmas, binary, scratch.path, req.run, log);
    refinement.distance = compare_refined(scene, c.sigmas, log);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const MeshStudyResult* measured = study ? &*study : nullptr;
  if (req.json) print_json(out, c, refinement, req.refine_tables, measured, solves, seconds);
  else print_text(out, m, c, refinement, measured, req.mesh.tolerance, solves, seconds);
  return c.unconfirmed;
}

}  // namespace rc::rom
