#pragma once
// This machine's physical memory, the measure every refusal of a problem too large for it compares against (a run
// killed by the system's out-of-memory killer half-way is no answer; a one-line refusal up front is).
#include <unistd.h>

namespace rc {

// Bytes of physical memory; 0 where the system does not say.
inline double machine_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

}  // namespace rc
