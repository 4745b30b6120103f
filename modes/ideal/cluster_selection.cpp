#include "cluster_selection.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace rc::modes {

void validate(const ModeSelection& s) {
  if (s.modes && *s.modes < 1) throw std::runtime_error(fmt::format("--modes must be at least 1 (got {})", *s.modes));
  if (s.coverage && !(*s.coverage > 0 && *s.coverage <= 1))
    throw std::runtime_error(fmt::format("--coverage must be in (0, 1] (got {})", *s.coverage));
}

}  // namespace rc::modes
