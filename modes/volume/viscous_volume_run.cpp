#include "viscous_volume_run.hpp"

#include "mesh_broadcast.hpp"
#include "petsc_handles.hpp"
#include "volume_forms.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace rc::modes {

double volume_decay_guess(double ekman) { return std::min(2 * std::sqrt(ekman), 0.5); }

ViscousVolumeResult solve_viscous_volume(const ViscousVolumeRequest& request,
                                         const std::function<void(const std::string&)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto say = [&](const std::string& line) { if (progress) progress(line); };
  if (!(request.ekman > 0)) throw std::runtime_error("the Ekman number must be > 0");
  if (request.targets.empty()) throw std::runtime_error("no target frequency for the damped modes");
  const VolumeTaylorHoodSpace space(
      volume_mesh_on_root([&] { return geometry::mesh_volume(request.shape, request.mesh); }, PETSC_COMM_WORLD));
  say(fmt::format("3-D viscous: {} tetrahedra of order {}, {} unknowns ({} velocity, {} wall nodes)",
                  space.num_elements(), space.order(), space.size(), space.velocity_dofs(), space.wall_nodes()));
  // Lever arms from the centroid: the mesh's own (its volume integrals), as the ideal tables take them.
  const VolumeIntegrals fluid = integrate_volume(space.geometry());
  const auto forms = assemble_viscous_volume_forms(space, fluid.centroid, request.ekman, PETSC_COMM_WORLD);
  ViscousVolumeResult out;
  for (double lambda0 : request.targets) {
    say(fmt::format("3-D viscous: the damped mode near lambda = {:.6f}", lambda0));
    out.modes.push_back(damped_volume_modes(forms, {lambda0, volume_decay_guess(request.ekman)}, 1).at(0));
  }
  out.unknowns = space.size();
  out.velocity_unknowns = space.velocity_dofs();
  out.wall_nodes = space.wall_nodes();
  out.elements = space.num_elements();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace rc::modes
