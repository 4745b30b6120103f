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

std::string complex_text(cd z) {
  std::ostringstream os;
  os << std::setprecision(10) << z.real() << (z.imag() < 0 ? " - " : " + ") << std::abs(z.imag()) << "i";
  return os.str();
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
    log << "  " << std::setw(10) << nearest->owner << "  " << std::setw(34) << complex_text(nearest->sigma)
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
};

// Iterates every selected root of `sp` on (22) with the tanks' own R, one line each on `log`, and gives the verdict
// again from the confirmed roots (the others as the table gives them).
Confirmation confirm_selected(const ChainModel& m, const Spectrum& sp, const TankResponses& tanks,
                              const ConfirmRequest& req, std::ostream& log) {
  ConfirmSettings settings;
  settings.tolerance = req.tolerance;
  Confirmation c{sp, {}, {}, {}, 0};
  int count = 0;
  for (const Root& r : sp.roots) count += selected(r, sp, req.all) ? 1 : 0;
  log << "roots of (22) with R itself, from the table's (" << count << " roots; docs/rom.md, \"Confirmed roots\"):"
      << std::endl;
  for (Root& r : c.spectrum.roots) {
    if (!selected(r, sp, req.all)) continue;
    const ConfirmedRoot root = confirm_root(m, tanks.responses, r.sigma, settings);
    log << "  " << std::setw(10) << r.owner << "  " << std::setw(34) << complex_text(root.start) << "  ->  "
        << std::setw(34) << complex_text(root.sigma) << std::setprecision(2) << "  moved " << root.moved() << ", "
        << root.evaluations << " evaluations" << (root.converged ? "" : "  NOT CONFIRMED: " + root.failure)
        << std::endl;
    c.roots.push_back({{"owner", r.owner}, {"table", {root.start.real(), root.start.imag()}},
                       {"confirmed", {root.sigma.real(), root.sigma.imag()}}, {"converged", root.converged},
                       {"moved", root.moved()}, {"evaluations", root.evaluations}});
    if (root.converged) {
      r.sigma = root.sigma;
      c.sigmas.push_back(root.sigma);
    } else {
      ++c.unconfirmed;
    }
  }
  Eigen::VectorXcd sigma(static_cast<Eigen::Index>(c.spectrum.roots.size()));
  for (std::size_t j = 0; j < c.spectrum.roots.size(); ++j)
    sigma[static_cast<Eigen::Index>(j)] = c.spectrum.roots[j].sigma;
  c.verdict = verdict_from_roots(m, sigma);
  c.spectrum.stable = c.verdict.stable;
  c.spectrum.growth = c.verdict.growth;
  c.spectrum.margin = c.verdict.margin;
  c.spectrum.growing = c.verdict.growing;
  return c;
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

void print_json(std::ostream& out, const Confirmation& c, const Refinement& refinement, bool refine, int solves,
                double seconds) {
  nlohmann::ordered_json j;
  j["roots"] = c.roots;
  j["stable"] = c.verdict.stable;
  j["growth"] = c.verdict.growth;
  j["growing"] = c.verdict.growing;
  j["unconfirmed"] = c.unconfirmed;
  j["forced_solves"] = solves;
  if (refine) {
    j["refined_tables"] = refinement.tables.size();
    j["refined_distance"] = refinement.distance;
    j["refine_seconds"] = refinement.seconds();
  }
  j["seconds"] = seconds;
  out << j.dump() << "\n";
}

void print_text(std::ostream& out, const ChainModel& m, const Confirmation& c, const Refinement& refinement,
                int solves, double seconds) {
  out << std::setprecision(6) << "with the confirmed roots: " << verdict_with_dissipation(m, c.spectrum) << "\n";
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
  TankResponses tanks = serve_tanks(scene, m, cavity_modes_binary(req.cavity_modes), scratch.path, log);
  const Confirmation c = confirm_selected(m, compute_spectrum(m), tanks, req, log);
  const int solves = tanks.solves();
  Refinement refinement;
  if (req.refine_tables && !c.sigmas.empty()) {
    tanks = {};  // the served solvers' memory back before the tables are remade
    log << "tables remade with R exact at the confirmed roots (cavity-modes response ... --exact-at):" << std::endl;
    refinement.tables = refine_tables(scene, m, c.sigmas, cavity_modes_binary(req.cavity_modes), scratch.path,
                                      req.run, log);
    refinement.distance = compare_refined(scene, c.sigmas, log);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (req.json) print_json(out, c, refinement, req.refine_tables, solves, seconds);
  else print_text(out, m, c, refinement, solves, seconds);
  return c.unconfirmed;
}

}  // namespace rc::rom
