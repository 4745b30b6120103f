#include "viscous_mesh.hpp"

#include "isolated_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace rc::modes {
namespace {

// A user's section meshes its layers in a child process, where a crash or a hang of gmsh's BoundaryLayer field
// becomes an error that the next attempt answers (geometry/isolated_mesh.hpp); the built-in shapes, measured over
// their whole range, in-process. A layered 2-D mesh takes seconds; a hang is given three minutes.
constexpr double kLayeredMeshSeconds = 180;

geometry::MeridianMesh layered_mesh(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh) {
  if (shape.kind == "section") return geometry::mesh_meridian_isolated(shape, mesh, kLayeredMeshSeconds);
  return geometry::mesh_meridian(shape, mesh);
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
