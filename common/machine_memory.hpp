#pragma once
// This machine's memory, the measure every refusal of a problem too large for it compares against (a run killed by
// the system's out-of-memory killer half-way is no answer; a one-line refusal up front is).
#include <unistd.h>

#include <fstream>
#include <string>

namespace rc {

// Bytes of physical memory; 0 where the system does not say.
inline double machine_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

// Bytes the system can give a new program now (MemAvailable of /proc/meminfo: free memory plus what it can reclaim);
// the physical memory where the system does not say. Another program's tables on the same machine are not ours to
// take: a served mesh level that fitted the machine was killed beside one (measured 2026-12-03, docs/trust.md).
inline double available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kib = 0;
  while (in >> key >> kib) {
    if (key == "MemAvailable:") return kib * 1024.0;
    in.ignore(256, '\n');
  }
  return machine_memory_bytes();
}

}  // namespace rc
