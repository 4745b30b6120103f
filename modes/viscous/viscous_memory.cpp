#include "viscous_memory.hpp"

#include "machine_memory.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace rc::modes {

long most_viscous_unknowns(double share) {
  return static_cast<long>(share * machine_memory_bytes() / kBytesPerViscousUnknown);
}

void refuse_viscous_beyond_memory(long real_unknowns, long copies, const std::string& mesh) {
  constexpr double kShare = 0.9;  // the rest for the system, the mesh and the run's other objects
  const double have = available_memory_bytes(), total = machine_memory_bytes();
  const double need = kBytesPerViscousUnknown * static_cast<double>(real_unknowns * copies);
  if (!(have > 0) || need <= kShare * have) return;
  const std::string free_now = have < 0.9 * total ? fmt::format(" free now ({:.1f} GB in all)", total / 1e9) : "";
  throw std::runtime_error(fmt::format(
      "the viscous mesh ({}) has {} real unknowns{}, about {:.1f} GB for the factorisation, more than {:.0f} % of the "
      "{:.1f} GB this machine has{}: use a larger --mesh-size or --wall-size or a lower --order (about {} real "
      "unknowns fit; a sphere or spherical shell: cavity-modes shell, docs/spherical.md)",
      mesh, real_unknowns, copies > 1 ? fmt::format(" on each of {} ranks", copies) : std::string(), need / 1e9,
      100 * kShare, have / 1e9, free_now,
      static_cast<long>(kShare * have / kBytesPerViscousUnknown) / copies));
}

}  // namespace rc::modes
