// A viscous mode table: the damped continuation of an ideal table's modes at one Ekman number
// (docs/viscous.md). Each ideal row's λ is the real shift of one shift-and-invert solve on a wall-graded
// Taylor–Hood mesh; the damped mode kept is the one of largest coupling |E_c| near it. Convergence flags compare
// each row with the same order on a mesh twice as coarse (interior and wall sizes both doubled).
#pragma once

#include "meridian_mesh.hpp"
#include "mode_fields.hpp"
#include "mode_table.hpp"
#include "viscous_eigensolver.hpp"

#include <functional>
#include <string>

namespace rc::modes {

struct ViscousTableSettings {
  double ekman = 0;                   // > 0
  geometry::MeshOptions mesh;         // order (>= 2), size, wall_size; 0 = viscous_mesh_defaults
  ViscousSolveSettings solve;
  double convergence_tolerance = 1e-6;
  bool check_convergence = true;
  // > 0: the mesh also follows the targets' internal shear layers as at this Ekman number (shear_layers.hpp; the
  // command sets it to the mesh's Ekman number unless --no-shear-layers); 0: it does not.
  double shear_layers_ekman = 0;
  // With the check: at most this many refinement rounds while a row is not converged (refined_viscous_mesh); each
  // round's rows are then flagged against the round before it. 0: the check against the doubled mesh only.
  int refinements = 0;
};

// The near-wall zone a table's mesh gets by default (docs/viscous.md, "Near-wall zone"): (Ek d)^{1/3} for a cylinder
// or a spheroid at Ek <= 1e-5 (there the uniform interior leaves the decay 1e-5 … 2e-2 off), 0 otherwise (the sphere
// meets 1e-5 with its shear-layer bands; elsewhere it was not measured to pay).
double default_near_wall_size(const geometry::ShapeSpec& shape, double ekman);

// The mesh of the refinement round after `mesh` (docs/viscous.md, "Refinement rounds"): where the
// anisotropic wall layers are, the first round adds the near-wall zone at 2 (Ek d)^{1/3} (d the cavity's smallest
// dimension); each next round halves the zone while it is coarser than half of (Ek d)^{1/3} — what limits the decay
// at water's Ekman numbers; every later round (and every round without the layers) halves all sizes.
geometry::MeshOptions refined_viscous_mesh(const geometry::ShapeSpec& shape, double ekman,
                                           const geometry::MeshOptions& mesh);

// The same mesh family one level finer: every size (interior, first wall layer, near-wall zone, shear-layer bands)
// halved, the anisotropic layers as thick as the Ekman layer needs but at most half the new interior size — the
// convergence check's doubled mesh in the other direction, and the step of chain-rom confirm's mesh study
// (docs/viscous.md, "Mesh study of a response").
geometry::MeshOptions halved_viscous_mesh(double ekman, const geometry::MeshOptions& mesh);

// Defaults where the settings leave 0 (docs/viscous.md, "Discretisation and solver"): order 6, interior size d/8
// (d the smallest dimension; sections: the geometry's default), first wall layer Ek^{1/2} (capped at the interior
// size), anisotropic layers up to 10 Ek^{1/2} but at most half the interior size for spheres, spheroids and
// cylinders, isotropic grading otherwise. Throws std::runtime_error, with one line naming the limit, when Ek is
// outside [1e-8, 1e3] or a given wall size is coarser than 4 Ek^{1/2} (an unresolved Ekman layer).
geometry::MeshOptions viscous_mesh_defaults(const geometry::ShapeSpec& shape, double ekman,
                                            geometry::MeshOptions mesh);

// The viscous table. `ideal` supplies the targets (its rows, heaviest first) and the root attributes that do not
// depend on viscosity (volume, A_f, C_f, J_zh, sum_rule). Throws std::runtime_error on solver failure.
// With `fields` (cavity-modes --ekman --fields), also each damped mode's fields at the mesh nodes, on rank 0
// (viscous_fields.hpp).
ModeTable compute_viscous_table(const geometry::ShapeSpec& shape, const ViscousTableSettings& settings,
                                const ModeTable& ideal, const std::function<void(const std::string&)>& report,
                                ModeFields* fields = nullptr);

}  // namespace rc::modes
