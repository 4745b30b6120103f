#include "shear_layers.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace rc::modes {
namespace {

struct Vec2 {
  double r, z;
};
Vec2 operator+(Vec2 a, Vec2 b) { return {a.r + b.r, a.z + b.z}; }
Vec2 operator*(double s, Vec2 a) { return {s * a.r, s * a.z}; }
double dot(Vec2 a, Vec2 b) { return a.r * b.r + a.z * b.z; }

// The meridian half-ellipse r²/a² + z²/c² = 1 (a sphere when a = c).
struct Wall {
  double a, c;
  Vec2 inward(Vec2 q) const { return {-q.r / (a * a), -q.z / (c * c)}; }
  // From p (on or inside the wall) along d to the wall: the positive root of |(p + t d)/(a, c)|² = 1.
  double hit(Vec2 p, Vec2 d) const {
    const double A = d.r * d.r / (a * a) + d.z * d.z / (c * c);
    const double B = 2 * (p.r * d.r / (a * a) + p.z * d.z / (c * c));
    const double C = p.r * p.r / (a * a) + p.z * p.z / (c * c) - 1;
    return (-B + std::sqrt(std::max(0.0, B * B - 4 * A * C))) / (2 * A);
  }
};

// From p along d to the first crossing of the axis r = 0 or the wall beyond p.
double next_hit(Vec2 p, Vec2 d, const Wall& w, bool& axis, bool& wall) {
  const double t_axis = d.r < 0 ? -p.r / d.r : INFINITY, t_wall = w.hit(p, d);
  const double t = std::min(t_axis, t_wall), tol = 1e-9 * std::max(w.a, w.c);
  axis = std::abs(t - t_axis) <= tol;
  wall = std::abs(t - t_wall) <= tol;
  return t;
}

// One ray from p along d, reflected until it ends at a pole (axis and wall at once) or max_segments.
void trace(Vec2 p, Vec2 d, const Wall& w, int max_segments, std::vector<std::array<double, 4>>& out) {
  for (int i = 0; i < max_segments; ++i) {
    bool axis = false, wall = false;
    const Vec2 q = p + next_hit(p, d, w, axis, wall) * d;
    out.push_back({p.r, p.z, q.r, q.z});
    if (axis && wall) return;
    if (axis) {
      d.r = -d.r;
    } else {  // into the other family, back into the fluid
      const Vec2 in = w.inward(q), a{-d.r, d.z}, b{d.r, -d.z};
      d = dot(a, in) > dot(b, in) ? a : b;
    }
    p = q;
  }
}

}  // namespace

std::vector<std::array<double, 4>> spheroid_shear_layers(double a, double c, double lambda, int max_segments) {
  std::vector<std::array<double, 4>> out;
  const double s = std::abs(lambda) / 2;
  if (!(s > 0 && s < 1)) return out;
  const double phi = std::asin(s);
  const Wall w{a, c};
  // The critical points (a sin θ, ±c cos θ), tan θ = a / (c tan φ): there the family (∓sin φ, cos φ) is tangent to the
  // wall; the layer leaves along the other one, inward.
  const double theta = std::atan2(a, c * std::tan(phi));
  for (const double side : {1.0, -1.0}) {
    const Vec2 p{a * std::sin(theta), side * c * std::cos(theta)};
    Vec2 d{-std::sin(phi), -side * std::cos(phi)};
    if (dot(d, w.inward(p)) < 0) d = -1.0 * d;
    trace(p, d, w, max_segments, out);
  }
  return out;
}

std::vector<std::array<double, 4>> sphere_shear_layers(double radius, double lambda, int max_segments) {
  return spheroid_shear_layers(radius, radius, lambda, max_segments);
}

namespace {

// A section's wall as straight pieces, each with its inward normal.
struct Piece {
  Vec2 a, b, inward;
};

// From p along d: the nearest wall piece ahead (index, distance), or −1.
std::pair<int, double> nearest_piece(const std::vector<Piece>& wall, Vec2 p, Vec2 d, double tol) {
  int best = -1;
  double t_best = INFINITY;
  for (std::size_t k = 0; k < wall.size(); ++k) {
    const Vec2 e{wall[k].b.r - wall[k].a.r, wall[k].b.z - wall[k].a.z}, w{wall[k].a.r - p.r, wall[k].a.z - p.z};
    const double den = d.r * e.z - d.z * e.r;
    if (std::abs(den) < 1e-14) continue;
    const double t = (w.r * e.z - w.z * e.r) / den, u = (w.r * d.z - w.z * d.r) / den;
    if (t > tol && t < t_best && u >= -1e-9 && u <= 1 + 1e-9) { t_best = t; best = static_cast<int>(k); }
  }
  return {best, t_best};
}

double distance_to_wall(const std::vector<Piece>& wall, Vec2 q) {
  double best = INFINITY;
  for (const Piece& p : wall) {
    const Vec2 e{p.b.r - p.a.r, p.b.z - p.a.z}, w{q.r - p.a.r, q.z - p.a.z};
    const double u = std::clamp(dot(w, e) / std::max(dot(e, e), 1e-300), 0.0, 1.0);
    best = std::min(best, std::hypot(w.r - u * e.r, w.z - u * e.z));
  }
  return best;
}

// One ray through a polyline wall: reflected at the wall into the other family, at the axis by symmetry; ended where
// it meets the wall on the axis (a pole), leaves the section, or after max_segments.
void trace_polyline(Vec2 p, Vec2 d, const std::vector<Piece>& wall, double extent, int max_segments,
                    std::vector<std::array<double, 4>>& out) {
  const double tol = 1e-9 * extent;
  for (int i = 0; i < max_segments; ++i) {
    const auto [k, t_wall] = nearest_piece(wall, p, d, tol);
    const double t_axis = d.r < 0 ? -p.r / d.r : INFINITY, t = std::min(t_axis, t_wall);
    if (!std::isfinite(t)) return;
    const Vec2 q = p + t * d;
    out.push_back({p.r, p.z, q.r, q.z});
    // A pole: the axis where the wall meets it (within 1 % of the section: the pieces only approximate the wall).
    const bool axis = t_axis <= t;
    if (axis && distance_to_wall(wall, q) <= 1e-2 * extent) return;
    if (axis) {
      d.r = -d.r;
    } else {
      const Vec2 a{-d.r, d.z}, b{d.r, -d.z};
      d = dot(a, wall[k].inward) > dot(b, wall[k].inward) ? a : b;
    }
    p = q;
  }
}

}  // namespace

std::vector<std::array<double, 4>> polyline_shear_layers(const std::vector<std::array<double, 6>>& pieces, double lambda,
                                                         int max_segments) {
  std::vector<std::array<double, 4>> out;
  const double s = std::abs(lambda) / 2;
  if (!(s > 0 && s < 1) || pieces.empty()) return out;
  const double phi = std::asin(s);
  std::vector<Piece> wall;
  double extent = 0;
  for (const auto& q : pieces) {
    wall.push_back({{q[0], q[1]}, {q[2], q[3]}, {q[4], q[5]}});
    extent = std::max({extent, std::abs(q[0]), std::abs(q[1]), std::abs(q[2]), std::abs(q[3])});
  }
  // A critical point: where the wall's tangent turns through a characteristic direction c between two consecutive
  // pieces (sharing an end). The layer leaves along the other family, into the fluid.
  const Vec2 families[2] = {{std::sin(phi), std::cos(phi)}, {-std::sin(phi), std::cos(phi)}};
  const double join = 1e-9 * extent;
  const auto same = [join](Vec2 x, Vec2 y) { return std::hypot(x.r - y.r, x.z - y.z) <= join; };
  for (std::size_t i = 0; i < wall.size(); ++i)
    for (std::size_t j = i + 1; j < wall.size(); ++j) {
      // The shared end p; t1 arrives at it along piece i, t2 leaves it along piece j.
      const Piece &u = wall[i], &v = wall[j];
      Vec2 p, from, to;
      if (same(u.b, v.a)) { p = u.b; from = u.a; to = v.b; }
      else if (same(u.b, v.b)) { p = u.b; from = u.a; to = v.a; }
      else if (same(u.a, v.a)) { p = u.a; from = u.b; to = v.b; }
      else if (same(u.a, v.b)) { p = u.a; from = u.b; to = v.a; }
      else continue;
      const Vec2 t1{p.r - from.r, p.z - from.z}, t2{to.r - p.r, to.z - p.z};
      for (int f = 0; f < 2; ++f) {
        const Vec2 c = families[f];
        if (!((t1.r * c.z - t1.z * c.r) * (t2.r * c.z - t2.z * c.r) < 0)) continue;
        Vec2 d = families[1 - f];
        if (dot(d, u.inward + v.inward) < 0) d = -1.0 * d;
        trace_polyline(p, d, wall, extent, max_segments, out);
      }
    }
  return out;
}

std::vector<std::array<double, 6>> section_wall_pieces(const geometry::ShapeSpec& shape) {
  geometry::MeshOptions fine;
  fine.order = 1;
  fine.size = geometry::default_mesh_size(shape) / 8;
  const geometry::MeridianMesh m = geometry::mesh_meridian(shape, fine);
  // Each wall edge's triangle: its third vertex is on the fluid's side.
  std::map<std::pair<int, int>, int> third;
  for (std::size_t e = 0; e < m.num_triangles(); ++e)
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[3 * e + k], b = m.triangles[3 * e + (k + 1) % 3], c = m.triangles[3 * e + (k + 2) % 3];
      third[{std::min(a, b), std::max(a, b)}] = c;
    }
  std::vector<std::array<double, 6>> out;
  for (std::size_t k = 0; k + 1 < m.wall_edges.size(); k += 2) {
    const int a = m.wall_edges[k], b = m.wall_edges[k + 1];
    const auto it = third.find({std::min(a, b), std::max(a, b)});
    if (it == third.end()) continue;
    const auto &A = m.nodes[a], &B = m.nodes[b], &C = m.nodes[it->second];
    Vec2 n{-(B[1] - A[1]), B[0] - A[0]};
    if (n.r * (C[0] - A[0]) + n.z * (C[1] - A[1]) < 0) n = -1.0 * n;
    const double len = std::hypot(n.r, n.z);
    out.push_back({A[0], A[1], B[0], B[1], n.r / len, n.z / len});
  }
  return out;
}

void add_shear_layer_bands(const geometry::ShapeSpec& shape, double ekman, const std::vector<double>& lambdas,
                           geometry::MeshOptions& mesh) {
  // Spheroids: traced (spheroid_shear_layers) but not applied — measured at Ek = 1e-6 on a = 1, c = 0.5 the bands'
  // decay moved by 3e-4 when the interior was halved (docs/benchmarks.md, "Internal shear layers"): not understood yet.
  const bool section = shape.kind == "section";
  if (!(shape.kind == "sphere" || section) || ekman > (section ? kSectionShearLayersFrom : kShearLayersFrom)) return;
  double size = 0;  // the cavity's size D: the sphere's radius, the section's largest |r| or |z|
  std::vector<std::array<double, 6>> pieces;
  if (section) {
    pieces = section_wall_pieces(shape);
    for (const auto& q : pieces) size = std::max({size, q[0], q[2], std::abs(q[1]), std::abs(q[3])});
  } else {
    size = shape.dims.at("radius");
  }
  // Ek = ν/(ω0 L²) with L the table's unit: a layer Ek_D^{1/5} D wide in a cavity of size D is D^{3/5} Ek^{1/5} in
  // those units.
  const double scale = std::pow(size, 0.6) * std::pow(ekman, 0.2);
  for (const double lambda : lambdas)
    for (const auto& segment : section ? polyline_shear_layers(pieces, lambda) : sphere_shear_layers(size, lambda))
      mesh.bands.push_back(segment);
  mesh.band_size = kShearSize * scale;
  mesh.band_width = kShearWidth * scale;
  mesh.band_growth = kShearGrowth;
}

}  // namespace rc::modes
