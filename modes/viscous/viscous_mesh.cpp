#include "viscous_mesh.hpp"

#include "isolated_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace rc::modes {
namespace {

// The layers are meshed in a child process of their own (geometry/isolated_mesh.hpp): there the same request gives
// the same mesh on every run, whatever this process's environment (in-process, gmsh's BoundaryLayer field made three
// different meshes of one command: docs/viscous.md, "Reproducible tables"), and a crash or a hang of that field on a
// user's section becomes an error that the next attempt answers. A layered 2-D mesh takes seconds; a hang is given
// three minutes.
constexpr double kLayeredMeshSeconds = 180;

geometry::MeridianMesh layered_mesh(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh) {
  return geometry::mesh_meridian_isolated(shape, mesh, kLayeredMeshSeconds);
}

}  // namespace

geometry::MeridianMesh viscous_mesh(const geometry::ShapeSpec& shape, geometry::MeshOptions& mesh) {
  geometry::MeshOptions tried = mesh;
  for (int attempt = 0; attempt < 7 && tried.wall_layer > tried.wall_size && tried.size > 0; ++attempt) {
    try {
      geometry::MeridianMesh layered = layered_mesh(shape, tried);
      mesh = tried;
      return layered;
    } catch (const std::runtime_error&) {
      tried.size *= 0.8;
      tried.wall_layer = std::min(tried.wall_layer, tried.size / 2);
    }
  }
  mesh.wall_layer = 0;
  return geometry::mesh_meridian(shape, mesh);
}

std::string mesh_text(const geometry::MeshOptions& m) {
  const std::string near = m.near_wall_size > 0 ? fmt::format(", near-wall {:.3g}", m.near_wall_size) : "";
  return fmt::format("order {}, h = {:.3g}, wall {:.3g}{}", m.order, m.size, m.wall_size, near);
}

}  // namespace rc::modes
