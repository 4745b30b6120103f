// The damped modes of a 3-D cavity at an Ekman number, end to end (docs/volume.md §7): mesh (on rank 0, shared with
// the others) → Taylor–Hood forms distributed over the ranks → the damped mode nearest each target with its coupling
// tensor. The request is resolved once by the command (modes/app/volume_command.*); this layer takes what it needs.
#pragma once

#include "viscous_volume_modes.hpp"
#include "volume_mesh.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rc::modes {

struct ViscousVolumeRequest {
  geometry::VolumeShapeSpec shape;
  geometry::MeshOptions mesh;   // order >= 2, size, wall_size, wall_growth: resolved by the command
  double ekman = 0;             // > 0
  std::vector<double> targets;  // the ideal frequencies λ0 > 0 of the modes wanted (one damped mode each)
};

struct ViscousVolumeResult {
  std::vector<DampedVolumeMode> modes;  // one per target, in the targets' order
  int unknowns = 0, velocity_unknowns = 0, wall_nodes = 0;
  std::size_t elements = 0;
  double mesh_h = 0;  // the mesh's element size (the mesher's, when the request left it 0)
  double seconds = 0;
};

// The decay rate guessed for a target (Im τ): the Ekman layers' order of magnitude, 2 Ek^{1/2} (at most 0.5), as the
// meridian tables guess it (viscous_table.cpp).
double volume_decay_guess(double ekman);

// A request's Taylor–Hood space and forms: meshed on rank 0 and shared, refused in one line when its factorisation
// would not fit in memory, assembled over PETSC_COMM_WORLD with the lever arms from the mesh's own centroid. Both the
// damped modes and the forced response (viscous_volume_response.hpp) start from it.
struct ViscousVolumeSystem {
  std::unique_ptr<VolumeTaylorHoodSpace> space;
  ViscousVolumeForms forms;
};
ViscousVolumeSystem viscous_volume_system(const geometry::VolumeShapeSpec& shape, const geometry::MeshOptions& mesh,
                                          double ekman, const std::function<void(const std::string&)>& progress);

// Throws std::runtime_error with a one-line cause (bad mesh, solver failure). Collective on PETSC_COMM_WORLD.
ViscousVolumeResult solve_viscous_volume(const ViscousVolumeRequest& request,
                                         const std::function<void(const std::string&)>& progress = {});

}  // namespace rc::modes
