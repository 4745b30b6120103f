#include "general_output.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace rc::rom {

namespace {

// The chain at two spins (floquet.hpp): what its roots are and how well the monodromy settled them.
void print_floquet(std::ostream& os, const GeneralChain& g, const GeneralSpectrum& sp) {
  const double omega = 2 * M_PI / g.period;
  os << "two spins: a body without axial symmetry or with tanks turns against the frame at " << omega
     << " rad/s, so the coefficients are periodic (period " << g.period << " s); the roots are Floquet exponents, "
     << "Re sigma defined modulo " << omega << " rad/s and given nearest the period-averaged chain's roots, Im sigma "
     << "exact (docs/rom.md, \"Bodies at different spins\")\n";
  os << "monodromy: " << sp.floquet_steps << " sixth-order Magnus steps a period, the roots settled to "
     << sp.floquet_error << " rad/s against half as many";
  if (sp.floquet_unresolved > 0)
    os << "; " << sp.floquet_unresolved << " root(s) decay too fast against the fastest-growing one to settle over a "
       << "period (their decay rates are not converged)";
  os << "\n";
}

}  // namespace

void print_general_spectrum(std::ostream& os, const GeneralChain& g, const GeneralSpectrum& sp) {
  const Verdict& v = sp.verdict;
  const auto precision = os.precision();
  os << std::setprecision(6);
  const bool own_spins = !g.periodic() && g.spins.size() > 0 && (g.spins.array() != g.spin).any();  // a dual-spin chain's rotors
  os << (g.free_chain ? "free" : "fixed") << " chain without axial symmetry, " << g.n << (g.n == 1 ? " body" : " bodies")
     << (g.periodic() ? " in the frame turning at " : own_spins ? " in the frame turning at " : " at the common spin ")
     << g.spin << " rad/s"
     << (own_spins ? " (axisymmetric bodies without tanks at their own spins)" : "") << ", " << g.n_modes() << (g.n_modes() == 1 ? " fluid mode" : " fluid modes")
     << (g.axial ? "; the spins' rates are coordinates too (a 3-D tank's modes may couple to the spin)" : "") << "\n";
  os << "roots sigma (e^{i sigma t}) in the frame turning with the bodies: the motion in space has sigma -+ spin "
        "too (docs/rom.md, \"Bodies and tanks without axial symmetry\")\n";
  if (g.periodic()) print_floquet(os, g, sp);
  if (g.recoil)
    os << "free chain: the base recoils with its partially filled tanks' liquid (its translation eliminated through the "
          "momentum, check " << sp.recoil_residual << "); the liquid's axial recoil is not modelled, so the roots of "
          "order 0 about the spin axis (the spins' rates, the liquid's axial sloshing) are those of a base held "
          "axially; the tilts' are exact (docs/volume.md section 8, \"The free chain\")\n";
  for (const auto& [k, share] : g.coverage)
    if (share < 1 - 1e-9) os << "body " << k + 1 << ": a tank's kept modes cover " << share << " of its sum rule\n";
  for (const auto& [k, rows] : g.pruned_rows)
    os << "body " << k + 1 << ": a tank's response table has " << rows << (rows == 1 ? " row" : " rows")
       << " left out that no root needs (together "
       << "under 1e-2 of its fit error and 1e-4 of Im R on its window; prune = false keeps them)\n";
  // The verdict as (26)'s (docs/rom.md, "Spectrum", "Verdict with dissipation"), its line saying when a tank's rows
  // did not settle.
  std::string unsettled = g.not_converged.empty() ? "" : "; NOT CONVERGED: a partially filled 3-D tank's rows (below)";
  // A viscous tank's rates are its table mesh's: said on the line a user reads, as (26)'s (docs/rom.md, "Mesh error of
  // confirmed roots").
  if (std::any_of(g.modes.begin(), g.modes.end(), [](const GeneralMode& m) { return m.damped(); }))
    unsettled += "; mesh error NOT MEASURED (the tables' mesh only: chain-rom confirm SCENE --refine-tables measures it)";
  if (!g.dissipative) {
    os << "stable: " << (v.stable ? "yes" : "no") << " (|Im sigma| <= " << v.tolerance << " counts as real)" << unsettled << "\n";
    os << "margin (largest |Im sigma|): " << v.margin << " rad/s\n";
  } else if (v.stable) {
    os << "stable: yes -- no root grows by more than rounding (" << v.noise << " 1/s; friction or viscous fluid), the slowest "
       << "decays at " << -v.growth << " 1/s (" << v.at_zero << " neutral roots at sigma = 0 or -+ the spin left out)" << unsettled << "\n";
  } else {
    os << "stable: no -- " << v.growing << (v.growing == 1 ? " root grows" : " roots grow") << ", the fastest at "
       << v.growth << " 1/s (e-folding " << 1 / v.growth << " s)" << unsettled << "\n";
  }
  for (const std::string& note : g.not_converged)
    os << "NOT CONVERGED: " << note << ": the roots near those rows' frequencies, and any their weight moves, are not "
          "reliable (docs/volume.md §8)\n";
  const double grows = g.dissipative ? v.noise : v.tolerance;
  const auto outside = [&](std::complex<double> r) { return g.response_window > 0 && std::abs(r.real()) > g.response_window; };
  const auto beyond = std::count_if(sp.roots.begin(), sp.roots.end(), outside);
  if (beyond > 0)
    os << beyond << " root(s) beyond a response table's window (|Re sigma| > " << g.response_window << " rad/s), "
       << "where the table is its reduced model's extrapolation: marked \"outside\" (docs/volume.md, section 7)\n";
  os << std::setprecision(static_cast<int>(precision));
  os << "  #   Re sigma (rad/s)         Im sigma (1/s)\n";
  for (std::size_t i = 0; i < sp.roots.size(); ++i) {
    const auto r = sp.roots[i];
    os << std::setw(3) << i + 1 << "   " << std::setw(22) << std::setprecision(15) << r.real() << "   "
       << std::setw(22) << r.imag() << (-r.imag() > grows && std::abs(r) > v.tolerance ? "   grows" : "")
       << (outside(r) ? "   outside" : "") << "\n";
  }
  os << std::setprecision(static_cast<int>(precision));
}

std::string general_spectrum_json(const GeneralChain& g, const GeneralSpectrum& sp) {
  nlohmann::ordered_json j;
  j["model"] = "general";
  j["frame"] = "turning";
  j["spin"] = g.spin;
  j["roots"] = nlohmann::ordered_json::array();
  for (const auto& r : sp.roots) j["roots"].push_back({r.real(), r.imag()});
  j["stable"] = sp.verdict.stable;
  j["margin"] = sp.verdict.margin;
  j["growth"] = sp.verdict.growth;
  j["growing"] = sp.verdict.growing;
  j["tolerance"] = sp.verdict.tolerance;
  j["fluid_modes"] = g.n_modes();
  j["coverage"] = nlohmann::ordered_json::array();  // [body (1-based), share] per tank
  for (const auto& [k, share] : g.coverage) j["coverage"].push_back({k + 1, share});
  j["not_converged"] = g.not_converged;
  if (g.response_window > 0) {  // the roots beyond a response table's window, as the text marks them "outside"
    j["window"] = g.response_window;
    j["outside"] = nlohmann::ordered_json::array();
    for (const auto& r : sp.roots) j["outside"].push_back(std::abs(r.real()) > g.response_window);
  }
  if (g.recoil) j["recoil_residual"] = sp.recoil_residual;
  if (g.periodic())
    j["floquet"] = {{"period", g.period}, {"steps_per_period", sp.floquet_steps}, {"settled", sp.floquet_error},
                    {"unresolved", sp.floquet_unresolved}};
  return j.dump();
}

}  // namespace rc::rom
