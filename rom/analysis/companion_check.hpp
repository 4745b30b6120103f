// The companion check of `chain-rom spectrum`: each cavity may name a companion table, the same cavity on a
// coarser mesh (docs/trust.md). The roots are computed again with every companion in place of its table, and a
// root that moves more than kCompanionTolerance (relative) is marked: its frequency depends on the mesh, like the
// root of an unconverged cluster (docs/rom.md, "Spectrum").
#pragma once

#include "scene.hpp"
#include "spectrum.hpp"

namespace rc::rom {

inline constexpr double kCompanionTolerance = 1e-6;

// True if some cavity of the scene names a companion table.
bool has_companions(const Scene& scene);

// The scene with each companion in place of its cavity's table (cavities without one unchanged). Throws SceneError
// if a companion describes another cavity than its table (shape, dimensions, ideal or viscous and Ekman number).
Scene with_companions(const Scene& scene);

// For each root of `sp`, the relative distance to the nearest root of `companion`; marks those above the tolerance.
void mark_companion_shifts(Spectrum& sp, const Spectrum& companion);

}  // namespace rc::rom
