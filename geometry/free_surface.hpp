// The free surface of a partially filled tank under rapid spin (docs/physics.md §2, "Partially filled cylinder: the
// free surface"): the centrifugal acceleration far above gravity makes the liquid's surface the coaxial cylinder
// r = b on which the rigid rotation's pressure is constant, the liquid being the part of the cavity with r >= b.
// For the built-in shapes b follows from the volume fraction in closed form (with c = b/a, the shape's outer radius a):
//   sphere, spheroid   F = (1 − c²)^{3/2}             (every slice z = const scales alike)
//   cylinder           F = (a² − b²)/(a² − r_i²)        (r_i: a coaxial rod's radius, 0 without)
//   cone (apex down)   F = 1 − 3c² + 2c³              (∫ π((a z/H)² − b²) dz over z >= cH, over πa²H/3)
#pragma once

#include "meridian_mesh.hpp"

namespace rc::geometry {

// b for the volume fraction `fill` (0 < fill < 1) of a built-in shape or a .geo section (cut at trial radii).
// Throws std::runtime_error (one line) for a fill outside (0, 1) or a section that cannot be read or cut.
double free_surface_radius(const ShapeSpec& shape, double fill);

// The shape with its free surface: dims["free_radius"] = free_surface_radius(shape, fill).
ShapeSpec partially_filled(ShapeSpec shape, double fill);

}  // namespace rc::geometry
