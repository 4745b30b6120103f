#include "shear_layers.hpp"

#include <algorithm>
#include <cmath>

namespace rc::modes {
namespace {

struct Vec2 {
  double r, z;
};
Vec2 operator+(Vec2 a, Vec2 b) { return {a.r + b.r, a.z + b.z}; }
Vec2 operator*(double s, Vec2 a) { return {s * a.r, s * a.z}; }
double dot(Vec2 a, Vec2 b) { return a.r * b.r + a.z * b.z; }

// From p along d to the first crossing of the axis r = 0 or the sphere |x| = R beyond p.
double next_hit(Vec2 p, Vec2 d, double R, bool& axis, bool& wall) {
  const double t_axis = d.r < 0 ? -p.r / d.r : INFINITY;
  const double b = dot(p, d), c = dot(p, p) - R * R;
  const double t_wall = -b + std::sqrt(std::max(0.0, b * b - c));
  const double t = std::min(t_axis, t_wall), tol = 1e-9 * R;
  axis = std::abs(t - t_axis) <= tol;
  wall = std::abs(t - t_wall) <= tol;
  return t;
}

// One ray from p along d, reflected until it ends at a pole (axis and wall at once) or max_segments.
void trace(Vec2 p, Vec2 d, double R, int max_segments, std::vector<std::array<double, 4>>& out) {
  for (int i = 0; i < max_segments; ++i) {
    bool axis = false, wall = false;
    const Vec2 q = p + next_hit(p, d, R, axis, wall) * d;
    out.push_back({p.r, p.z, q.r, q.z});
    if (axis && wall) return;
    if (axis) {
      d.r = -d.r;
    } else {  // into the other family, back into the fluid
      const Vec2 inward = (-1.0 / std::sqrt(dot(q, q))) * q, a{-d.r, d.z}, b{d.r, -d.z};
      d = dot(a, inward) > dot(b, inward) ? a : b;
    }
    p = q;
  }
}

}  // namespace

std::vector<std::array<double, 4>> sphere_shear_layers(double radius, double lambda, int max_segments) {
  std::vector<std::array<double, 4>> out;
  const double s = std::abs(lambda) / 2;
  if (!(s > 0 && s < 1)) return out;
  const double phi = std::asin(s);
  // The critical points (R cos φ, ±R sin φ): there the family (∓sin φ, cos φ) is tangent to the wall; the layer leaves
  // along the other one, inward.
  trace({radius * std::cos(phi), radius * std::sin(phi)}, {-std::sin(phi), -std::cos(phi)}, radius, max_segments, out);
  trace({radius * std::cos(phi), -radius * std::sin(phi)}, {-std::sin(phi), std::cos(phi)}, radius, max_segments, out);
  return out;
}

void add_shear_layer_bands(const geometry::ShapeSpec& shape, double ekman, const std::vector<double>& lambdas,
                           geometry::MeshOptions& mesh) {
  if (shape.kind != "sphere" || ekman > kShearLayersFrom) return;
  const double R = shape.dims.at("radius"), scale = R * std::pow(ekman, 0.2);
  for (const double lambda : lambdas)
    for (const auto& segment : sphere_shear_layers(R, lambda)) mesh.bands.push_back(segment);
  mesh.band_size = kShearSize * scale;
  mesh.band_width = kShearWidth * scale;
  mesh.band_growth = kShearGrowth;
}

}  // namespace rc::modes
