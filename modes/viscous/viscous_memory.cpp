#include "viscous_memory.hpp"

#include "machine_memory.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace rc::modes {

long most_viscous_unknowns(double share) {
  return static_cast<long>(share * machine_memory_bytes() / kBytesPerViscousUnknown);
}

void refuse_viscous_beyond_memory(long real_unknowns, long copies, const std::string& mesh) {
  constexpr double kShare = 0.9;  // the rest for the system, the mesh and the other programs of the run
  const long most = most_viscous_unknowns(kShare);
  if (most <= 0 || real_unknowns * copies <= most) return;
  throw std::runtime_error(fmt::format(
      "the viscous mesh ({}) has {} real unknowns{}, about {:.1f} GB for the factorisation, more than {:.0f} % of this "
      "machine's {:.1f} GB: use a larger --mesh-size or --wall-size or a lower --order (at most about {} real "
      "unknowns fit; a sphere or spherical shell: cavity-modes shell, docs/spherical.md)",
      mesh, real_unknowns, copies > 1 ? fmt::format(" on each of {} ranks", copies) : std::string(),
      kBytesPerViscousUnknown * static_cast<double>(real_unknowns * copies) / 1e9, 100 * kShare,
      machine_memory_bytes() / 1e9, most / copies));
}

}  // namespace rc::modes
