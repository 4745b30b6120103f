#include "wall_layer_builder.hpp"

#include "tetrahedron_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rc::geometry::detail {
namespace {

double signed_volume(const std::array<Point, 4>& x) {
  double e[3][3];
  for (int i = 0; i < 3; ++i)
    for (int d = 0; d < 3; ++d) e[i][d] = x[i + 1][d] - x[0][d];
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
         e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

// Builds the layers' tetrahedra onto the core mesh m (nodes appended).
class LayerBuilder {
 public:
  LayerBuilder(VolumeMesh& m, const CoreWall& wall, const std::vector<double>& depths, const RayOf& ray)
      : wall_(wall), m_(m), ray_of_(ray), k_(m.order), ref_(tetrahedron_nodes(m.order)) {
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
  // side's diagonal runs from the lower-numbered vertex's bottom to the other's top, so neighbours agree. The three
  // must turn the way the face and its rays do; a prism whose rays cross (layers too thick for the wall's bends)
  // has one of them reversed or flat.
  void prism(const std::array<int, 3>& face, int layer) {
    std::array<int, 3> s = face;
    std::sort(s.begin(), s.end());
    const int b = layer * k_, t = (layer + 1) * k_;
    std::array<std::array<V, 4>, 3> tets = {{{{{s[0], b}, {s[1], b}, {s[2], b}, {s[2], t}}},
                                             {{{s[0], b}, {s[1], b}, {s[1], t}, {s[2], t}}},
                                             {{{s[0], b}, {s[0], t}, {s[1], t}, {s[2], t}}}}};
    // The second tetrahedron, as listed, turns the other way round from the first and the third.
    constexpr std::array<double, 3> kParity = {1.0, -1.0, 1.0};
    const double sense = face_sense(s);
    for (int i = 0; i < 3; ++i) {
      auto& tet = tets[i];
      std::array<Point, 4> x;
      for (int j = 0; j < 4; ++j) x[j] = vertex_position(tet[j]);
      if (!(signed_volume(x) * sense * kParity[i] > 0))
        throw std::runtime_error("wall layers fold near " + place(x[0]) + ": make them thinner (--wall-layer) than "
                                 "the wall's radius of curvature and half the cavity's narrowest gap");
      if (sense * kParity[i] < 0) std::swap(tet[1], tet[2]);
      add_tetrahedron(tet);
    }
  }

  // +1 if the sorted face's normal points along its rays (outwards), −1 if against.
  double face_sense(const std::array<int, 3>& s) {
    std::array<Point, 3> x;
    Point direction{};
    for (int i = 0; i < 3; ++i) {
      x[i] = vertex_position({s[i], 0});
      const WallRay& r = ray({{s[i], k_}});
      for (int d = 0; d < 3; ++d) direction[d] += r.direction[d];
    }
    double e[2][3];
    for (int i = 0; i < 2; ++i)
      for (int d = 0; d < 3; ++d) e[i][d] = x[i + 1][d] - x[0][d];
    const Point n = {e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                     e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    return n[0] * direction[0] + n[1] * direction[1] + n[2] * direction[2] >= 0 ? 1.0 : -1.0;
  }

  double level_fraction(int level) const {
    const int layer = level / k_, m = level % k_;
    if (layer + 1 >= static_cast<int>(fraction_.size())) return 1.0;
    return fraction_[layer] + (fraction_[layer + 1] - fraction_[layer]) * m / k_;
  }

  const WallRay& ray(const SurfaceKey& key) {
    auto it = rays_.find(key);
    if (it == rays_.end()) it = rays_.emplace(key, ray_of_(key, m_.nodes.at(wall_.node_of.at(key)))).first;
    return it->second;
  }

  Point position(const SurfaceKey& key, int level) {
    const WallRay& r = ray(key);
    const double f = level_fraction(level) * r.length;
    return {r.start[0] + f * r.direction[0], r.start[1] + f * r.direction[1], r.start[2] + f * r.direction[2]};
  }

  Point vertex_position(const V& v) { return position({{v.first, k_}}, v.second); }

  int node(const SurfaceKey& key, int level) {
    if (level == 0) return wall_.node_of.at(key);
    const auto [it, is_new] = made_.try_emplace({key, level}, static_cast<int>(m_.nodes.size()));
    if (is_new) m_.nodes.push_back(position(key, level));
    return it->second;
  }

  void add_tetrahedron(const std::array<V, 4>& v) {
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

  const CoreWall& wall_;
  VolumeMesh& m_;
  const RayOf& ray_of_;
  int k_;
  TetrahedronNodes ref_;
  std::vector<double> fraction_;
  std::map<SurfaceKey, WallRay> rays_;
  std::map<std::pair<SurfaceKey, int>, int> made_;
};

}  // namespace

std::string place(const Point& p) {
  std::ostringstream os;
  os.precision(4);
  os << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return os.str();
}

WallRay ray_between(const Point& start, const Point& end) {
  WallRay r;
  r.start = start;
  for (int d = 0; d < 3; ++d) r.direction[d] = end[d] - start[d];
  r.length = std::sqrt(r.direction[0] * r.direction[0] + r.direction[1] * r.direction[1] +
                       r.direction[2] * r.direction[2]);
  if (r.length > 0)
    for (double& v : r.direction) v /= r.length;
  return r;
}

std::vector<double> layer_depths(const MeshOptions& o) {
  std::vector<double> d = {0.0};
  double t = o.wall_size;
  while (d.back() < o.wall_layer * (1 - 1e-9) && d.size() < 60) {
    d.push_back(d.back() + t);
    t *= 1 + o.wall_growth;
  }
  return d;
}

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

void add_wall_layers(VolumeMesh& core, const CoreWall& wall, const std::vector<double>& depths, const RayOf& ray) {
  LayerBuilder builder(core, wall, depths, ray);
  builder.build(static_cast<int>(depths.size()) - 1);
}

}  // namespace rc::geometry::detail
