// Where a viscous inertial mode's internal shear layers lie, so that the mesh can follow them (docs/viscous.md,
// "Internal shear layers"). At a critical latitude, where a characteristic of the Poincaré equation at the mode's
// frequency is tangent to the wall, the Ekman layer erupts and launches a layer along the other characteristic, of
// width ~Ek^{1/5} near its source and ~Ek^{1/3} far from it (Kerswell 1995, "On the internal shear layers spawned by the
// critical regions in oscillatory Ekman boundary layers"; Hollerbach & Kerswell 1995, "Oscillatory internal shear
// layers in rotating and precessing flows"). At a viscous table's low Ekman numbers these layers, not the wall's
// Ekman layers, limit the accuracy of the damping on a uniform interior mesh (docs/benchmarks.md, "Kore").
#pragma once

#include "meridian_mesh.hpp"

#include <array>
#include <vector>

namespace rc::modes {

// The characteristics launched from a sphere's critical latitudes at frequency λ (ω0 = 1, 0 < |λ| < 2), traced in the
// meridian half-plane r ≥ 0 through up to `max_segments` segments each: the lines dr/dz = ±tan φ, sin φ = |λ|/2, of
// λ² p_rr − (4 − λ²) p_zz = 0 (docs/physics.md §2), reflected at the wall into the other family and at the axis by
// symmetry, ended at a pole. For the spin-over mode (λ = 1) each runs from a critical latitude (±30°) straight to the
// opposite pole.
std::vector<std::array<double, 4>> sphere_shear_layers(double radius, double lambda, int max_segments = 8);
// The same in a spheroid (semi-axes a along r, c along z): critical points where the ellipse's tangent is a
// characteristic, rays reflected at the ellipse.
std::vector<std::array<double, 4>> spheroid_shear_layers(double a, double c, double lambda, int max_segments = 8);

// The bands' rules, measured on the sphere's spin-over mode at Ek = 1e-6 against Kore (docs/benchmarks.md, "Internal
// shear layers"): elements of 0.4 Ek^{1/5} R^{3/5} within 0.5 Ek^{1/5} R^{3/5} of the characteristics, growing by 2
// per unit distance beyond, from Ek = 1e-5 down.
inline constexpr double kShearSize = 0.4, kShearWidth = 0.5, kShearGrowth = 2, kShearLayersFrom = 1e-5;

// With a built-in sphere at Ek ≤ kShearLayersFrom, bands along every target's shear layers (MeshOptions::bands; their
// sizes times R^{3/5}, the layers' Ek_R^{1/5} R in the table's unit). Other shapes: unchanged (spheroids are traced but
// not applied yet: shear_layers.cpp).
void add_shear_layer_bands(const geometry::ShapeSpec& shape, double ekman, const std::vector<double>& lambdas,
                           geometry::MeshOptions& mesh);

}  // namespace rc::modes
