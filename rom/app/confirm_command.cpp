#include "confirm_command.hpp"

#include "chain_model.hpp"
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

int confirm_roots(const Scene& scene, const ConfirmRequest& req, std::ostream& out) {
  const auto t0 = std::chrono::steady_clock::now();
  const ChainModel m = build_model(scene);
  const Spectrum sp = compute_spectrum(m);
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
  ConfirmSettings settings;
  settings.tolerance = req.tolerance;
  Spectrum confirmed = sp;
  nlohmann::ordered_json jroots = nlohmann::ordered_json::array();
  std::vector<cd> confirmed_sigmas;
  int unconfirmed = 0, count = 0;
  for (const Root& r : sp.roots) count += selected(r, sp, req.all) ? 1 : 0;
  log << "roots of (22) with R itself, from the table's (" << count << " roots; docs/rom.md, \"Confirmed roots\"):"
      << std::endl;
  for (Root& r : confirmed.roots) {
    if (!selected(r, sp, req.all)) continue;
    const ConfirmedRoot c = confirm_root(m, tanks.responses, r.sigma, settings);
    log << "  " << std::setw(10) << r.owner << "  " << std::setw(34) << complex_text(c.start) << "  ->  "
        << std::setw(34) << complex_text(c.sigma) << std::setprecision(2) << "  moved " << c.moved() << ", "
        << c.evaluations << " evaluations" << (c.converged ? "" : "  NOT CONFIRMED: " + c.failure) << std::endl;
    jroots.push_back({{"owner", r.owner}, {"table", {c.start.real(), c.start.imag()}},
                      {"confirmed", {c.sigma.real(), c.sigma.imag()}}, {"converged", c.converged},
                      {"moved", c.moved()}, {"evaluations", c.evaluations}});
    if (c.converged) {
      r.sigma = c.sigma;
      confirmed_sigmas.push_back(c.sigma);
    } else {
      ++unconfirmed;
    }
  }
  // The verdict again, from the confirmed roots (the others as the table gives them).
  Eigen::VectorXcd sigma(static_cast<Eigen::Index>(confirmed.roots.size()));
  for (std::size_t j = 0; j < confirmed.roots.size(); ++j) sigma[static_cast<Eigen::Index>(j)] = confirmed.roots[j].sigma;
  const Verdict v = verdict_from_roots(m, sigma);
  confirmed.stable = v.stable;
  confirmed.growth = v.growth;
  confirmed.margin = v.margin;
  confirmed.growing = v.growing;
  const int solves = tanks.solves();
  double refined_distance = -1;
  std::vector<RefinedTable> refined;
  if (req.refine_tables && !confirmed_sigmas.empty()) {
    tanks = {};  // the served solvers' memory back before the tables are remade
    log << "tables remade with R exact at the confirmed roots (cavity-modes response ... --exact-at):" << std::endl;
    refined = refine_tables(scene, m, confirmed_sigmas, cavity_modes_binary(req.cavity_modes), scratch.path, req.run,
                            log);
    refined_distance = compare_refined(scene, confirmed_sigmas, log);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (req.json) {
    nlohmann::ordered_json j;
    j["roots"] = jroots;
    j["stable"] = v.stable;
    j["growth"] = v.growth;
    j["growing"] = v.growing;
    j["unconfirmed"] = unconfirmed;
    j["forced_solves"] = solves;
    if (req.refine_tables) {
      j["refined_tables"] = refined.size();
      j["refined_distance"] = refined_distance;
      double remade = 0;
      for (const RefinedTable& r : refined) remade += r.seconds;
      j["refine_seconds"] = remade;
    }
    j["seconds"] = seconds;
    out << j.dump() << "\n";
    return unconfirmed;
  }
  out << std::setprecision(6) << "with the confirmed roots: " << verdict_with_dissipation(m, confirmed) << "\n";
  if (unconfirmed)
    out << "warning: " << unconfirmed << " roots NOT CONFIRMED (marked above): the verdict takes the table's value "
        << "for them\n";
  if (refined_distance >= 0)
    out << std::setprecision(2) << refined.size() << " tables refined: spectrum's roots are now the confirmed ones to "
        << refined_distance << " relative\n";
  out << solves << " forced solves, " << std::setprecision(3) << seconds << " s\n";
  return unconfirmed;
}

}  // namespace rc::rom
