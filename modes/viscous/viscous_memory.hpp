#pragma once
// What a viscous meridian (Taylor–Hood) solve costs in memory, and the refusal of a mesh beyond this machine's.
#include <string>

namespace rc::modes {

// MUMPS's complex factorisation and the forms: about 10 kB per real unknown, measured 2026-11-27 at P6 (2.26 GB at
// 224 034 real unknowns, 7.2 GB at 762 704); 1.2e4 with a margin. A P5 served response of 2 128 052 real unknowns (the
// 30 %-full sphere's reference at Ek = 1e-6, docs/trust.md) was killed by the system at 24 GB: 11.3 kB and more.
constexpr double kBytesPerViscousUnknown = 1.2e4;

// The real unknowns whose factorisation fits in `share` of this machine's memory (all ranks together); 0 where the
// system does not say how much it has.
long most_viscous_unknowns(double share);

// Throws std::runtime_error with one line (the mesh, its size, the memory it needs, what to change) when `copies`
// factorisations of `real_unknowns` would pass 90 % of the memory this machine has free now (available_memory_bytes). `mesh` names the mesh ("order 5, h =
// 0.008, ..."). Called after meshing and before assembly, so that a forced response or a table is refused up front.
void refuse_viscous_beyond_memory(long real_unknowns, long copies, const std::string& mesh);

}  // namespace rc::modes
