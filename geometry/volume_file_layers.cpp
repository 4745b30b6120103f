// Wall layers for a user's `volume` file (docs/volume.md §7, "Wall layers"): the first mesh's curved wall, its
// vertices offset inwards, the core that gmsh fills inside the offset wall, and the rays back to the curved wall.
#include "gmsh_session.hpp"
#include "tetrahedron_nodes.hpp"
#include "volume_wall_layers.hpp"
#include "wall_layer_builder.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rc::geometry {
namespace {

using detail::Point;
using detail::SurfaceKey;
using detail::place;

// Above this the offset of a wall vertex is taken for a fold (a spike or a cusp of the wall), not a corner: a 90°
// edge needs √2 H, a cube's corner √3 H.
constexpr double kMaxOffsetPerThickness = 3.0;
// The pull of a vertex's offset towards H times its mean normal: it fixes the offset's tangential part on a smooth
// wall (where the faces' normals hardly differ) and hardly moves it at an edge or a corner.
constexpr double kNormalPull = 1e-3;

Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

std::string number(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

// The first mesh's wall: each face with its vertices ordered so that its normal points out of the fluid, and its
// lattice nodes (on the file's curved surfaces), keyed as the core's are.
struct OuterWall {
  std::vector<std::array<int, 3>> faces;  // first-mesh vertex indices
  std::map<SurfaceKey, int> node_of;      // lattice key on first-mesh vertices -> first-mesh node
};

OuterWall outer_wall(const VolumeMesh& m) {
  const detail::CoreWall wall = detail::core_wall(m);
  OuterWall w;
  w.node_of = wall.node_of;
  const int npe = m.nodes_per_element;
  for (const auto& [e, o] : wall_faces(m)) {
    std::array<int, 3> f{};
    for (int v = 0, i = 0; v < 4; ++v)
      if (v != o) f[i++] = m.tetrahedra[e * npe + v];
    const Point n = cross(minus(m.nodes[f[1]], m.nodes[f[0]]), minus(m.nodes[f[2]], m.nodes[f[0]]));
    if (dot(n, minus(m.nodes[f[0]], m.nodes[m.tetrahedra[e * npe + o]])) < 0) std::swap(f[1], f[2]);
    w.faces.push_back(f);
  }
  return w;
}

// Solves the symmetric 3 × 3 system G d = b (Cramer's rule).
Point solve3(const double G[3][3], const Point& b) {
  const auto det = [](const double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double D = det(G);
  Point d{};
  for (int c = 0; c < 3; ++c) {
    double Gc[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Gc[i][j] = j == c ? b[i] : G[i][j];
    d[c] = det(Gc) / D;
  }
  return d;
}

// The inward offset of every wall vertex: the least-squares d with n_f·d = H over the faces f round it (weighted by
// area), pulled slightly towards H n̄ — H along the normal on a smooth wall, H/cos(θ/2) along the bisector of an edge
// whose faces meet at θ, so that every face of the core's wall lies H inside the wall's.
std::map<int, Point> vertex_offsets(const VolumeMesh& m, const OuterWall& w, double H) {
  struct Sum {
    double G[3][3] = {};
    Point b{}, mean{};
    double area = 0;
  };
  std::map<int, Sum> sums;
  for (const auto& f : w.faces) {
    const Point n2 = cross(minus(m.nodes[f[1]], m.nodes[f[0]]), minus(m.nodes[f[2]], m.nodes[f[0]]));
    const double a = std::sqrt(dot(n2, n2));
    const Point n = {n2[0] / a, n2[1] / a, n2[2] / a};
    for (int v : f) {
      Sum& s = sums[v];
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) s.G[i][j] += a * n[i] * n[j];
        s.b[i] += a * H * n[i];
        s.mean[i] += a * n[i];
      }
      s.area += a;
    }
  }
  std::map<int, Point> offset;
  for (auto& [v, s] : sums) {
    const double norm = std::sqrt(dot(s.mean, s.mean));
    for (int i = 0; i < 3; ++i) {
      s.G[i][i] += kNormalPull * s.area;
      s.b[i] += kNormalPull * s.area * H * s.mean[i] / norm;
    }
    const Point d = solve3(s.G, s.b);
    if (!(std::sqrt(dot(d, d)) <= kMaxOffsetPerThickness * H))
      throw std::runtime_error("wall layers " + number(H) + " thick: the wall folds too sharply near " +
                               place(m.nodes[v]) + " (a cusp or a spike) for them");
    offset[v] = d;
  }
  return offset;
}

// Lagrange tetrahedra of `order` with straight sides on linear ones (4 vertex indices each), the new nodes numbered
// after the vertices and shared between neighbours through their lattice keys.
VolumeMesh raise_order(const std::vector<Point>& vertices, std::vector<int> tets, int order) {
  const TetrahedronNodes ref = tetrahedron_nodes(order);
  VolumeMesh m;
  m.order = order;
  m.nodes_per_element = ref.nodes_per_element;
  m.nodes = vertices;
  std::map<SurfaceKey, int> made;
  for (std::size_t t = 0; t + 3 < tets.size(); t += 4) {
    int* v = &tets[t];
    const Point& x0 = vertices[v[0]];
    if (dot(cross(minus(vertices[v[1]], x0), minus(vertices[v[2]], x0)), minus(vertices[v[3]], x0)) < 0)
      std::swap(v[1], v[2]);
    for (int a = 0; a < m.nodes_per_element; ++a) {
      const auto l = tetrahedron_lattice(ref.points[a], order);
      SurfaceKey key;
      for (int i = 0; i < 4; ++i)
        if (l[i] > 0) key.emplace_back(v[i], l[i]);
      if (key.size() == 1) {
        m.tetrahedra.push_back(key[0].first);
        continue;
      }
      std::sort(key.begin(), key.end());
      const auto [it, is_new] = made.try_emplace(key, static_cast<int>(m.nodes.size()));
      if (is_new) {
        Point x{};
        for (const auto& [vertex, weight] : key)
          for (int d = 0; d < 3; ++d) x[d] += weight * vertices[vertex][d] / order;
        m.nodes.push_back(x);
      }
      m.tetrahedra.push_back(it->second);
    }
  }
  return m;
}

// The core: gmsh's linear tetrahedra inside the offset wall (a discrete surface and volume), graded from the wall's
// size at its wall to `size` inside, raised to `order` with straight sides (its wall is inside the fluid, so flat
// faces cost no accuracy). The core's vertices 0..n−1 are the offset wall's, in the order given.
VolumeMesh core_inside(const std::vector<Point>& wall_points, const std::vector<std::array<int, 3>>& faces,
                       const MeshOptions& options, double size, int order, const std::string& where) {
  std::vector<Point> vertices;
  std::vector<int> tets;  // core vertex indices, 4 per tetrahedron
  detail::with_gmsh(where, [&](detail::GmshSession& session) {
    gmsh::model::add("wall layers' core");
    const int surface = gmsh::model::addDiscreteEntity(2);
    std::vector<std::size_t> tags(wall_points.size());
    std::vector<double> xyz;
    for (std::size_t i = 0; i < wall_points.size(); ++i) {
      tags[i] = i + 1;
      xyz.insert(xyz.end(), wall_points[i].begin(), wall_points[i].end());
    }
    gmsh::model::mesh::addNodes(2, surface, tags, xyz);
    std::vector<std::size_t> triangles;
    for (const auto& f : faces)
      for (int v : f) triangles.push_back(static_cast<std::size_t>(v) + 1);
    gmsh::model::mesh::addElementsByType(surface, 2, {}, triangles);
    // A volume of the built-in kernel bounded by the discrete surface: gmsh fills it and keeps the surface's mesh.
    const int volume = gmsh::model::geo::addVolume({gmsh::model::geo::addSurfaceLoop({surface})});
    gmsh::model::geo::synchronize();
    namespace field = gmsh::model::mesh::field;
    if (options.near_wall_size > 0 && options.near_wall_size < size) {
      const int distance = field::add("Distance");
      field::setNumbers(distance, "SurfacesList", {static_cast<double>(surface)});
      const int threshold = field::add("Threshold");
      field::setNumber(threshold, "InField", distance);
      field::setNumber(threshold, "SizeMin", options.near_wall_size);
      field::setNumber(threshold, "SizeMax", size);
      field::setNumber(threshold, "DistMin", 0);
      field::setNumber(threshold, "DistMax", (size - options.near_wall_size) / std::max(options.near_wall_growth, 1e-3));
      field::setAsBackgroundMesh(threshold);
    }
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::model::mesh::generate(3);
    session.throw_if_error(where + " (the wall layers' core)");
    std::vector<std::size_t> node_tags;
    std::vector<double> coords, param;
    gmsh::model::mesh::getNodes(node_tags, coords, param, -1, -1, false, false);
    std::unordered_map<std::size_t, int> index;
    vertices = wall_points;
    for (std::size_t i = 0; i < wall_points.size(); ++i) index[i + 1] = static_cast<int>(i);
    for (std::size_t i = 0; i < node_tags.size(); ++i)
      if (index.try_emplace(node_tags[i], static_cast<int>(vertices.size())).second)
        vertices.push_back({coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]});
    std::vector<std::size_t> element_tags, element_nodes;
    gmsh::model::mesh::getElementsByType(4, element_tags, element_nodes, volume);
    for (std::size_t t : element_nodes) tets.push_back(index.at(t));
  });
  if (tets.empty()) throw std::runtime_error(where + ": gmsh made no core inside the wall layers");
  return raise_order(vertices, std::move(tets), order);
}

}  // namespace

VolumeMesh layered_volume_file(const VolumeShapeSpec& shape, const MeshOptions& options) {
  const std::string where = "volume '" + shape.file.string() + "'";
  const std::vector<double> depths = detail::layer_depths(options);
  const double H = depths.back();
  // The first mesh: the file at the layers' along-wall size; its wall's curved faces are the layers' outer faces.
  MeshOptions first = options;
  first.wall_layer = 0;
  first.wall_size = options.near_wall_size;
  first.wall_growth = options.near_wall_growth;
  first.near_wall_size = 0;
  const VolumeMesh outer = mesh_volume(shape, first);
  const OuterWall wall = outer_wall(outer);
  const std::map<int, Point> offset = vertex_offsets(outer, wall, H);

  std::vector<Point> points;     // the core's wall vertices
  std::vector<int> outer_vertex;  // the first mesh's vertex each was offset from
  std::map<int, int> core_vertex;
  for (const auto& [v, d] : offset) {
    core_vertex[v] = static_cast<int>(points.size());
    outer_vertex.push_back(v);
    points.push_back(minus(outer.nodes[v], d));
  }
  std::vector<std::array<int, 3>> faces;
  double longest_edge = 0;
  for (const auto& f : wall.faces) {
    const std::array<int, 3> c = {core_vertex.at(f[0]), core_vertex.at(f[1]), core_vertex.at(f[2])};
    const Point n = cross(minus(outer.nodes[f[1]], outer.nodes[f[0]]), minus(outer.nodes[f[2]], outer.nodes[f[0]]));
    const Point nc = cross(minus(points[c[1]], points[c[0]]), minus(points[c[2]], points[c[0]]));
    if (!(dot(n, nc) > 0))
      throw std::runtime_error(where + ": wall layers " + number(H) + " thick fold near " +
                               place(outer.nodes[f[0]]) + ": make them thinner than the wall's radius of curvature");
    for (int i = 0; i < 3; ++i) {
      const Point e = minus(outer.nodes[f[(i + 1) % 3]], outer.nodes[f[i]]);
      longest_edge = std::max(longest_edge, std::sqrt(dot(e, e)));
    }
    faces.push_back(c);
  }
  const double size = outer.size > 0 ? outer.size : longest_edge;  // a .msh file's own mesh: its wall's edges
  VolumeMesh m = core_inside(points, faces, options, size, outer.order, where);
  m.size = outer.size;

  const detail::CoreWall core_wall = detail::core_wall(m);
  if (core_wall.faces.size() != wall.faces.size())
    throw std::runtime_error(where + ": gmsh changed the wall layers' core wall (" +
                             std::to_string(core_wall.faces.size()) + " faces for " +
                             std::to_string(wall.faces.size()) + ")");
  const auto ray = [&](const SurfaceKey& key, const Point& p) {
    SurfaceKey on_wall;
    for (const auto& [v, weight] : key) {
      if (v >= static_cast<int>(outer_vertex.size()))
        throw std::runtime_error(where + ": gmsh put a core vertex on the wall layers' core wall");
      on_wall.emplace_back(outer_vertex[v], weight);
    }
    std::sort(on_wall.begin(), on_wall.end());
    return detail::ray_between(p, outer.nodes[wall.node_of.at(on_wall)]);
  };
  detail::add_wall_layers(m, core_wall, depths, ray);
  return m;
}

}  // namespace rc::geometry
