#include "viscous_volume_run.hpp"

#include "machine_memory.hpp"
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

namespace {

// MUMPS's complex factors of a 3-D Taylor–Hood pencil: measured 2026-11-27/28 (docs/benchmarks.md, "Viscous 3-D"), 66
// to 89 kB per unknown serially on isotropic meshes (P3, P4), 125 kB with wall layers (P4: their thin elements fill
// more; a P4 layered mesh of 140 170 unknowns passed 22 GB), 63 kB per unknown and rank on two ranks (127 kB in all).
// A mesh beyond the machine's memory is refused after meshing in one line, rather than killed by the system half-way.
// Isotropic meshes: 60 kB per unknown measured at P3 (117 812 unknowns, 7.1 GB, 2026-11-28), 89 kB at P4.
void refuse_beyond_memory(std::size_t unknowns, bool layered) {
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  const double per_unknown = ranks == 1 ? (layered ? 1.3e5 : 9e4) : 9e4 * ranks;  // all ranks on this machine
  const double need = per_unknown * static_cast<double>(unknowns);
  const double have = machine_memory_bytes();
  if (have > 0 && need > 0.9 * have)
    throw std::runtime_error(fmt::format("the 3-D viscous mesh has {} unknowns, about {:.0f} GB for the factorisation "
                                         "on {} rank(s), more than this machine's {:.0f} GB: use a larger --mesh-size "
                                         "or --wall-size, or a lower --order",
                                         unknowns, need / 1e9, ranks, have / 1e9));
}

}  // namespace

ViscousVolumeSystem viscous_volume_system(const geometry::VolumeShapeSpec& shape, const geometry::MeshOptions& mesh,
                                          double ekman, const std::function<void(const std::string&)>& progress) {
  if (!(ekman > 0)) throw std::runtime_error("the Ekman number must be > 0");
  ViscousVolumeSystem out;
  // Refused on the linear mesh's counts already (VolumeTaylorHoodSpace's unknowns: three velocity components on every
  // node off the wall, the order k − 1 pressure on its nodes but one), before the high-order nodes are placed.
  const int k = mesh.order;
  const auto check = [k](const geometry::LinearTetCounts& c) {
    if (k >= 2) refuse_beyond_memory(3 * (c.nodes(k) - c.wall_nodes(k)) + c.nodes(k - 1) - 1, false);  // else the space refuses
  };
  out.space = std::make_unique<VolumeTaylorHoodSpace>(
      volume_mesh_on_root([&] { return geometry::mesh_volume(shape, mesh, check); }, PETSC_COMM_WORLD));
  const VolumeTaylorHoodSpace& space = *out.space;
  refuse_beyond_memory(static_cast<std::size_t>(space.size()), mesh.wall_layer > 0);
  if (progress)
    progress(fmt::format("3-D viscous: {} tetrahedra of order {}, {} unknowns ({} velocity, {} wall nodes)",
                         space.num_elements(), space.order(), space.size(), space.velocity_dofs(), space.wall_nodes()));
  // Lever arms from the centroid: the mesh's own (its volume integrals), as the ideal tables take them.
  const VolumeIntegrals fluid = integrate_volume(space.geometry());
  out.forms = assemble_viscous_volume_forms(space, fluid.centroid, ekman, PETSC_COMM_WORLD);
  return out;
}

ViscousVolumeResult solve_viscous_volume(const ViscousVolumeRequest& request,
                                         const std::function<void(const std::string&)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto say = [&](const std::string& line) { if (progress) progress(line); };
  if (request.targets.empty()) throw std::runtime_error("no target frequency for the damped modes");
  const ViscousVolumeSystem system = viscous_volume_system(request.shape, request.mesh, request.ekman, progress);
  const VolumeTaylorHoodSpace& space = *system.space;
  ViscousVolumeResult out;
  for (double lambda0 : request.targets) {
    say(fmt::format("3-D viscous: the damped mode near lambda = {:.6f}", lambda0));
    out.modes.push_back(damped_volume_modes(system.forms, {lambda0, volume_decay_guess(request.ekman)}, 1).at(0));
  }
  out.unknowns = space.size();
  out.velocity_unknowns = space.velocity_dofs();
  out.wall_nodes = space.wall_nodes();
  out.elements = space.num_elements();
  out.mesh_h = space.geometry().mesh().size;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace rc::modes
