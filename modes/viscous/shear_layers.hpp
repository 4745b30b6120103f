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

// The same through a wall given as straight pieces (r0, z0, r1, z1, inward normal): critical points where the tangent
// turns through a characteristic between two pieces that share an end, rays reflected at the pieces. A user's section
// (a spherical shell's inner sphere launches its own layers) through section_wall_pieces.
std::vector<std::array<double, 4>> polyline_shear_layers(const std::vector<std::array<double, 6>>& pieces, double lambda,
                                                         int max_segments = 8);
// A section's wall as straight pieces with their inward normals: its order-1 mesh at 1/8 of the default size.
std::vector<std::array<double, 6>> section_wall_pieces(const geometry::ShapeSpec& shape);

// The bands' rules, measured on the sphere's spin-over mode at Ek = 1e-6 against Kore (docs/benchmarks.md, "Internal
// shear layers"): elements of 0.4 Ek^{1/5} R^{3/5} within 0.5 Ek^{1/5} R^{3/5} of the characteristics, growing by 2
// per unit distance beyond, from Ek = 1e-5 down.
inline constexpr double kShearSize = 0.4, kShearWidth = 0.5, kShearGrowth = 2, kShearLayersFrom = 1e-5;
// A user's section gets them from Ek = 1e-4: measured on Kore's shell, whose inner sphere launches layers that a uniform
// interior misses already there (decay 6.4e-7 off Kore's, 3.7e-9 with the bands; docs/benchmarks.md, "Shells").
inline constexpr double kSectionShearLayersFrom = 1e-4;

// With a built-in sphere at Ek ≤ kShearLayersFrom or a user's section at Ek ≤ kSectionShearLayersFrom, bands along every
// target's shear layers (MeshOptions::bands; their sizes times D^{3/5}, the layers' Ek_D^{1/5} D in the table's unit, D
// the cavity's size). Other shapes: unchanged (spheroids are traced but not applied yet: shear_layers.cpp).
void add_shear_layer_bands(const geometry::ShapeSpec& shape, double ekman, const std::vector<double>& lambdas,
                           geometry::MeshOptions& mesh);

}  // namespace rc::modes
