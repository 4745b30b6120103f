#include "volume_wall_layers.hpp"

#include "wall_layer_builder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace rc::geometry {
namespace {

using detail::Point;
using detail::WallRay;

// The ray from a core wall node p along the core ellipsoid's normal to the ellipsoid with semi-axes A.
WallRay wall_ray(const Point& p, const Point& core, const Point& A) {
  WallRay r;
  r.start = p;
  double n2 = 0;
  for (int d = 0; d < 3; ++d) {
    r.direction[d] = p[d] / (core[d] * core[d]);
    n2 += r.direction[d] * r.direction[d];
  }
  for (double& v : r.direction) v /= std::sqrt(n2);
  double qa = 0, qb = 0, qc = -1;  // Σ (p + t d)²/A² = 1
  for (int d = 0; d < 3; ++d) {
    qa += r.direction[d] * r.direction[d] / (A[d] * A[d]);
    qb += 2 * p[d] * r.direction[d] / (A[d] * A[d]);
    qc += p[d] * p[d] / (A[d] * A[d]);
  }
  r.length = (-qb + std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  return r;
}

}  // namespace

VolumeMesh layered_ellipsoid(const VolumeShapeSpec& shape, const MeshOptions& options) {
  if (shape.kind != "ellipsoid")
    throw std::runtime_error(shape.kind + ": not an ellipsoid (layered_volume_file takes a file)");
  const Point A = {shape.dims.at("a"), shape.dims.at("b"), shape.dims.at("c")};
  const std::vector<double> depths = detail::layer_depths(options);
  const double H = depths.back();
  if (!(H < 0.5 * std::min({A[0], A[1], A[2]})))
    throw std::runtime_error("ellipsoid: wall layers " + std::to_string(H) + " thick do not fit in half the smallest "
                             "semi-axis");
  VolumeShapeSpec inner = shape;
  inner.dims = {{"a", A[0] - H}, {"b", A[1] - H}, {"c", A[2] - H}};
  inner.tilt = 0;
  // The core is graded towards its wall from near_wall_size (0: the interior size), and its wall triangles are the
  // layers' along-wall size: the Ekman layers' structure along the wall (their critical latitudes) wants it finer
  // than the interior.
  MeshOptions core = options;
  core.wall_layer = 0;
  core.wall_size = options.near_wall_size;
  core.wall_growth = options.near_wall_growth;
  core.near_wall_size = 0;
  VolumeMesh m = mesh_volume(inner, core);
  const Point core_axes = {A[0] - H, A[1] - H, A[2] - H};
  detail::add_wall_layers(m, detail::core_wall(m), depths,
                          [&](const detail::SurfaceKey&, const Point& p) { return wall_ray(p, core_axes, A); });
  if (shape.tilt != 0) {  // as the built shape turns: about x by the tilt
    const double c = std::cos(shape.tilt), s = std::sin(shape.tilt);
    for (auto& p : m.nodes) p = {p[0], c * p[1] - s * p[2], s * p[1] + c * p[2]};
  }
  return m;
}

}  // namespace rc::geometry
