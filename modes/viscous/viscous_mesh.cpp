#include "viscous_mesh.hpp"

#include <algorithm>
#include <stdexcept>

namespace rc::modes {

geometry::MeridianMesh viscous_mesh(const geometry::ShapeSpec& shape, geometry::MeshOptions& mesh) {
  geometry::MeshOptions tried = mesh;
  for (int attempt = 0; attempt < 7 && tried.wall_layer > tried.wall_size && tried.size > 0; ++attempt) {
    try {
      geometry::MeridianMesh layered = geometry::mesh_meridian(shape, tried);
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

}  // namespace rc::modes
