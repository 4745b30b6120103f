#include "volume_wall_layers.hpp"

#include "tetrahedron_nodes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rc::geometry {
namespace {

using Point = std::array<double, 3>;
// A point of the core's wall lattice: its barycentric lattice weights on the core's global vertices, sorted.
using SurfaceKey = std::vector<std::pair<int, int>>;

// Distances from the wall of the layers' boundaries: 0, wall_size, wall_size (2 + g), ... up to wall_layer.
std::vector<double> layer_depths(const MeshOptions& o) {
  std::vector<double> d = {0.0};
  double t = o.wall_size;
  while (d.back() < o.wall_layer * (1 - 1e-9) && d.size() < 60) {
    d.push_back(d.back() + t);
    t *= 1 + o.wall_growth;
  }
  return d;
}

struct WallRay {
  Point start{}, direction{};  // a core wall node and the core's exact unit outward normal there
  double length = 0;           // to the true wall along it
};

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

// The core's wall: each face that one tetrahedron alone has, with its three vertices and, for every core node on it,
// the node's lattice key.
struct CoreWall {
  std::vector<std::array<int, 3>> faces;  // core vertex indices
  std::map<SurfaceKey, int> node_of;      // lattice key -> core node
};

CoreWall core_wall(const VolumeMesh& m) {
  const int npe = m.nodes_per_element, k = m.order;
  const auto nodes = tetrahedron_nodes(k);
  CoreWall w;
  for (const auto& [e, o] : wall_faces(m)) {
    std::array<int, 3> f{};
    for (int v = 0, i = 0; v < 4; ++v)
      if (v != o) f[i++] = m.tetrahedra[e * npe + v];
    w.faces.push_back(f);
    for (int a = 0; a < npe; ++a) {
      const auto l = tetrahedron_lattice(nodes.points[a], k);
      if (l[o] != 0) continue;
      SurfaceKey key;
      for (int v = 0; v < 4; ++v)
        if (l[v] > 0) key.emplace_back(m.tetrahedra[e * npe + v], l[v]);
      std::sort(key.begin(), key.end());
      w.node_of[key] = m.tetrahedra[e * npe + a];
    }
  }
  return w;
}

// Builds the layers' tetrahedra onto the core mesh m (nodes appended).
class LayerBuilder {
 public:
  LayerBuilder(VolumeMesh& m, CoreWall wall, const Point& core, const Point& A, const std::vector<double>& depths)
      : wall_(std::move(wall)), m_(m), core_(core), A_(A), k_(m.order), ref_(tetrahedron_nodes(m.order)) {
    const double H = depths.back();
    for (std::size_t j = depths.size(); j-- > 0;) fraction_.push_back(1 - depths[j] / H);  // core side first
  }

  // Every prism of every layer (0 at the core) on every core wall face.
  void build(int layers) {
    for (const auto& f : wall_.faces)
      for (int j = 0; j < layers; ++j) prism(f, j);
  }

 private:
  using V = std::pair<int, int>;  // a prism's vertex: (core wall vertex, level: k per layer, 0 on the core)

  // The prism over `face` in `layer` as three tetrahedra: with the vertices sorted by number (s0 < s1 < s2), every
  // side's diagonal runs from the lower-numbered vertex's bottom to the other's top, so neighbours agree.
  void prism(const std::array<int, 3>& face, int layer) {
    std::array<int, 3> s = face;
    std::sort(s.begin(), s.end());
    const int b = layer * k_, t = (layer + 1) * k_;
    const std::array<std::array<V, 4>, 3> tets = {{{{{s[0], b}, {s[1], b}, {s[2], b}, {s[2], t}}},
                                                   {{{s[0], b}, {s[1], b}, {s[1], t}, {s[2], t}}},
                                                   {{{s[0], b}, {s[0], t}, {s[1], t}, {s[2], t}}}}};
    for (auto tet : tets) add_tetrahedron(tet);
  }

  double level_fraction(int level) const {
    const int layer = level / k_, m = level % k_;
    if (layer + 1 >= static_cast<int>(fraction_.size())) return 1.0;
    return fraction_[layer] + (fraction_[layer + 1] - fraction_[layer]) * m / k_;
  }

  Point position(const SurfaceKey& key, int level) {
    auto it = rays_.find(key);
    if (it == rays_.end()) it = rays_.emplace(key, wall_ray(m_.nodes.at(wall_.node_of.at(key)), core_, A_)).first;
    const WallRay& r = it->second;
    const double f = level_fraction(level) * r.length;
    return {r.start[0] + f * r.direction[0], r.start[1] + f * r.direction[1], r.start[2] + f * r.direction[2]};
  }

  int node(const SurfaceKey& key, int level) {
    if (level == 0) return wall_.node_of.at(key);
    const auto [it, is_new] = made_.try_emplace({key, level}, static_cast<int>(m_.nodes.size()));
    if (is_new) m_.nodes.push_back(position(key, level));
    return it->second;
  }

  static double volume(const std::array<Point, 4>& x) {
    double e[3][3];
    for (int i = 0; i < 3; ++i)
      for (int d = 0; d < 3; ++d) e[i][d] = x[i + 1][d] - x[0][d];
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  }

  void add_tetrahedron(std::array<V, 4> v) {
    std::array<Point, 4> x;
    for (int i = 0; i < 4; ++i) x[i] = position({{v[i].first, k_}}, v[i].second);
    if (volume(x) < 0) std::swap(v[1], v[2]);
    for (int a = 0; a < m_.nodes_per_element; ++a) {
      const auto l = tetrahedron_lattice(ref_.points[a], k_);
      std::map<int, int> weight;  // surface vertex -> lattice weight (sum k)
      int level = 0;
      for (int i = 0; i < 4; ++i) {
        weight[v[i].first] += l[i];
        level += l[i] * v[i].second;
      }
      SurfaceKey key;
      for (const auto& [s, w] : weight)
        if (w > 0) key.emplace_back(s, w);
      m_.tetrahedra.push_back(node(key, level / k_));
    }
  }

  CoreWall wall_;
  VolumeMesh& m_;
  Point core_, A_;
  int k_;
  TetrahedronNodes ref_;
  std::vector<double> fraction_;
  std::map<SurfaceKey, WallRay> rays_;
  std::map<std::pair<SurfaceKey, int>, int> made_;
};

}  // namespace

VolumeMesh layered_ellipsoid(const VolumeShapeSpec& shape, const MeshOptions& options) {
  if (shape.kind != "ellipsoid")
    throw std::runtime_error(shape.kind + ": 3-D wall layers are built for the ellipsoid so far (use --wall-size alone)");
  const Point A = {shape.dims.at("a"), shape.dims.at("b"), shape.dims.at("c")};
  const std::vector<double> depths = layer_depths(options);
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
  LayerBuilder layers(m, core_wall(m), {A[0] - H, A[1] - H, A[2] - H}, A, depths);
  layers.build(static_cast<int>(depths.size()) - 1);
  if (shape.tilt != 0) {  // as the built shape turns: about x by the tilt
    const double c = std::cos(shape.tilt), s = std::sin(shape.tilt);
    for (auto& p : m.nodes) p = {p[0], c * p[1] - s * p[2], s * p[1] + c * p[2]};
  }
  return m;
}

}  // namespace rc::geometry
