// The companion check of `chain-rom spectrum`: each cavity may name a companion table, the same cavity on a
// coarser mesh (docs/trust.md). The roots are computed again with every companion in place of its table, and each
// root the verdict rests on (a body root, or a growing root) is marked when its frequency moves by more than
// kCompanionTolerance or its growth or decay rate by more than kCompanionRateTolerance (relative): what the answer
// says depends on the mesh, like a root of an unconverged cluster (docs/rom.md, "Spectrum"). The fluid's own roots
// (a response table's pseudo-modes are many) are measured but not marked: they are the tables', not the answer.
#pragma once

#include "scene.hpp"
#include "spectrum.hpp"

namespace rc::rom {

inline constexpr double kCompanionTolerance = 1e-6;
inline constexpr double kCompanionRateTolerance = 1e-3;

// True if some cavity of the scene names a companion table.
bool has_companions(const Scene& scene);

// The scene with each companion in place of its cavity's table (cavities without one unchanged). Throws SceneError
// if a companion describes another cavity than its table (shape, dimensions, ideal or viscous and Ekman number).
Scene with_companions(const Scene& scene);

// For each root of `sp`, the relative distance to the nearest root of `companion` and the relative change of its rate;
// marks the roots the verdict rests on that pass either tolerance.
void mark_companion_shifts(Spectrum& sp, const Spectrum& companion);

}  // namespace rc::rom
