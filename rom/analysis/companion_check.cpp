#include "companion_check.hpp"

#include "mode_table.hpp"

#include <cmath>
#include <limits>

namespace rc::rom {
namespace {

// The companion must be the same cavity: the check a user cannot see from the spectrum.
void check_same_cavity(const std::filesystem::path& table, const std::filesystem::path& companion,
                       const std::string& where) {
  const rc::ModeTable a = rc::read_mode_table(table), b = rc::read_mode_table(companion);
  std::string why = rc::cavity_difference(a, b);
  if (why.empty() && a.ekman != b.ekman) why = "another Ekman number";
  if (!why.empty())
    throw SceneError(where + ".companion: " + companion.string() + " describes another cavity than the table (" +
                     why + ")");
}

}  // namespace

bool has_companions(const Scene& scene) {
  for (const BodySpec& b : scene.bodies)
    if (b.cavity && !b.cavity->companion.empty()) return true;
  return false;
}

Scene with_companions(const Scene& scene) {
  Scene s = scene;
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    auto& cav = s.bodies[k].cavity;
    if (!cav || cav->companion.empty()) continue;
    check_same_cavity(cav->table, cav->companion, "body[" + std::to_string(k + 1) + "].cavity");
    cav->table = cav->companion;
    cav->companion.clear();
  }
  return s;
}

void mark_companion_shifts(Spectrum& sp, const Spectrum& companion) {
  sp.companion_moved = 0;
  sp.companion_worst = 0;
  sp.companion_worst_rate = 0;
  for (Root& r : sp.roots) {
    const Root* nearest = nullptr;
    for (const Root& c : companion.roots)
      if (!nearest || std::abs(c.sigma - r.sigma) < std::abs(nearest->sigma - r.sigma)) nearest = &c;
    if (!nearest) continue;
    r.companion_shift = std::abs(nearest->sigma - r.sigma) / std::max(std::abs(r.sigma), 1e-300);
    const bool has_rate = std::abs(r.sigma.imag()) > std::max(sp.tolerance, sp.noise);
    if (has_rate) r.companion_rate_shift = std::abs(nearest->sigma.imag() - r.sigma.imag()) / std::abs(r.sigma.imag());
    const bool decides = r.owner.rfind("body", 0) == 0 || -r.sigma.imag() > std::max(sp.noise, sp.tolerance);
    if (!decides) continue;
    r.companion_moved = !(r.companion_shift <= kCompanionTolerance) ||
                        (has_rate && !(r.companion_rate_shift <= kCompanionRateTolerance));
    if (r.companion_moved) ++sp.companion_moved;
    sp.companion_worst = std::max(sp.companion_worst, r.companion_shift);
    if (has_rate) sp.companion_worst_rate = std::max(sp.companion_worst_rate, r.companion_rate_shift);
  }
  sp.companion_checked = true;
}

}  // namespace rc::rom
