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

void add_shear_layer_bands(const geometry::ShapeSpec& shape, double ekman, const std::vector<double>& lambdas,
                           geometry::MeshOptions& mesh) {
  // Spheroids: traced (spheroid_shear_layers) but not applied — measured at Ek = 1e-6 on a = 1, c = 0.5 the bands'
  // decay moved by 3e-4 when the interior was halved (docs/benchmarks.md, "Internal shear layers"): not understood yet.
  if (shape.kind != "sphere" || ekman > kShearLayersFrom) return;
  const double a = shape.dims.at("radius"), c = a;
  // Ek = ν/(ω0 L²) with L the table's unit: a layer Ek_D^{1/5} D wide in a cavity of size D = max(a, c) is
  // D^{3/5} Ek^{1/5} in those units.
  const double scale = std::pow(std::max(a, c), 0.6) * std::pow(ekman, 0.2);
  for (const double lambda : lambdas)
    for (const auto& segment : spheroid_shear_layers(a, c, lambda)) mesh.bands.push_back(segment);
  mesh.band_size = kShearSize * scale;
  mesh.band_width = kShearWidth * scale;
  mesh.band_growth = kShearGrowth;
}

}  // namespace rc::modes
