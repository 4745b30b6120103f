#include "general_output.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iomanip>

namespace rc::rom {
namespace {

double margin(const GeneralSpectrum& sp) {
  double m = 0;
  for (const auto& r : sp.roots) m = std::max(m, std::abs(r.imag()));
  return m;
}

double tolerance(const GeneralSpectrum& sp) { return 1e-8 * sp.scale; }

}  // namespace

void print_general_spectrum(std::ostream& os, const GeneralChain& g, const GeneralSpectrum& sp) {
  const auto precision = os.precision();
  os << std::setprecision(6);
  os << (g.free_chain ? "free" : "fixed") << " chain without axial symmetry, " << g.n << (g.n == 1 ? " body" : " bodies")
     << " at the common spin " << g.spin << " rad/s, " << g.n_modes() << (g.n_modes() == 1 ? " fluid mode" : " fluid modes")
     << (g.axial ? "; the spins' rates are coordinates too (a 3-D tank's modes may couple to the spin)" : "") << "\n";
  os << "roots sigma (e^{i sigma t}) in the frame turning with the bodies: the motion in space has sigma -+ spin "
        "too (docs/rom.md, \"Bodies and tanks without axial symmetry\")\n";
  for (const auto& [k, share] : g.coverage)
    if (share < 1 - 1e-9) os << "body " << k + 1 << ": a tank's kept modes cover " << share << " of its sum rule\n";
  if (!g.dissipative) {
    os << "stable: " << (sp.stable ? "yes" : "no") << " (|Im sigma| <= " << tolerance(sp) << " counts as real)\n";
    os << "margin (largest |Im sigma|): " << margin(sp) << " rad/s\n";
  } else if (sp.stable) {
    os << "stable: yes -- no root grows by more than " << tolerance(sp) << " 1/s (joint friction)\n";
  } else {
    os << "stable: no -- the fastest root grows at " << sp.growth << " 1/s (e-folding " << 1 / sp.growth << " s)\n";
  }
  os << std::setprecision(static_cast<int>(precision));
  os << "  #   Re sigma (rad/s)         Im sigma (1/s)\n";
  for (std::size_t i = 0; i < sp.roots.size(); ++i) {
    const auto r = sp.roots[i];
    os << std::setw(3) << i + 1 << "   " << std::setw(22) << std::setprecision(15) << r.real() << "   "
       << std::setw(22) << r.imag() << (-r.imag() > tolerance(sp) ? "   grows" : "") << "\n";
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
  j["stable"] = sp.stable;
  j["growth"] = sp.growth;
  j["margin"] = margin(sp);
  j["tolerance"] = tolerance(sp);
  j["fluid_modes"] = g.n_modes();
  j["coverage"] = nlohmann::ordered_json::array();  // [body (1-based), share] per tank
  for (const auto& [k, share] : g.coverage) j["coverage"].push_back({k + 1, share});
  return j.dump();
}

}  // namespace rc::rom
