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
};

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
