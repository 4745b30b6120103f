// A 3-D cavity's viscous response table (docs/volume.md §7, "The response table"): the fluid's 3 × 3 response R(σ) on
// a window of frequencies, reduced on rational Krylov spaces (viscous_volume_krylov.hpp) and written as a viscous 3-D
// table whose rows are the reduced model's poles — one per real motion, each with its rank-one residue as the row's
// coupling tensor — so that chain-rom takes it as it takes the damped modes' table, with the whole response in the
// window rather than a few modes. The cavity's tensors come from its ideal table; the λ = 0 weight is 0, because the
// rows hold the fluid's viscous spin-up (purely damped poles near σ = 0) that the ideal fluid's steady weight stands
// for in the damped modes' table.
#pragma once

#include "mode_table.hpp"
#include "viscous_volume_krylov.hpp"
#include "volume_mesh.hpp"

#include <functional>
#include <string>
#include <vector>

namespace rc::modes {

struct VolumeResponseTableRequest {
  geometry::VolumeShapeSpec shape;
  geometry::MeshOptions mesh;  // resolved by the command, as for the damped modes
  double ekman = 0;            // > 0
  std::vector<double> window;  // real frequencies >= 0, increasing, at least 3 (the estimate is scanned between them)
  VolumeKrylovOptions krylov;
};

struct VolumeResponseTableResult {
  ModeTable table;  // empty where no ideal table was given
  VolumeKrylovReduction reduction;
  std::vector<VolumePole> poles;  // the rows, as the reduction gave them
  double rows_error = 0;          // the rows' R (pole_sum) against the reduced model's, on the scanned frequencies
  int unknowns = 0;
  double seconds = 0;
};

// `ideal`: the ideal 3-D table of the same cavity (its tensors), where the table is wanted (rank 0): the reduction is
// collective on PETSC_COMM_WORLD, and a rank given no ideal table returns no table. Throws std::runtime_error with a
// one-line cause.
VolumeResponseTableResult viscous_volume_response_table(const ModeTable* ideal,
                                                        const VolumeResponseTableRequest& request,
                                                        const std::function<void(const std::string&)>& progress = {});

// The rows of a 3-D response table started by viscous_volume_table_start: one per pole, its rank-one residue H as the
// row's coupling tensor (a partially filled tank's 5 × 5 H into /volume_free_surface), with the normalisation line and
// the rows' coverage of the sum rule. Shared by the Krylov table above and the boundary-layer one
// (boundary_layer_table.hpp).
void add_response_table_rows(ModeTable& t, const std::vector<VolumePole>& poles);

}  // namespace rc::modes
