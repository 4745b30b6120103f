// cut_to_fill: b by bisection on the liquid's volume (OpenCASCADE's cut and mass), then the cut itself.
#include "partial_volume.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rc::geometry {
namespace {

namespace occ = gmsh::model::occ;

constexpr double kFillTolerance = 1e-11;  // relative to the cavity's volume: b to about this over the surface's slope
constexpr int kMaxBisections = 80;

struct Box {
  double x0, y0, z0, x1, y1, z1;
};

Box bounding_box(int tag) {
  Box b{};
  occ::getBoundingBox(3, tag, b.x0, b.y0, b.z0, b.x1, b.y1, b.z1);
  return b;
}

// The cylinder ρ < b about the axis, longer than the box.
int gas_cylinder(const Box& box, const std::array<double, 2>& axis, double radius) {
  const double h = box.z1 - box.z0;
  return occ::addCylinder(axis[0], axis[1], box.z0 - 0.5 * h - 1, 0, 0, 2 * h + 2, radius);
}

double volume_of(const gmsh::vectorpair& parts) {
  double v = 0;
  for (const auto& [dim, tag] : parts) {
    double m = 0;
    if (dim == 3) occ::getMass(3, tag, m);
    v += m;
  }
  return v;
}

// The liquid's volume beyond the cylinder of this radius; the cavity kept. Each cut takes a copy of the cavity:
// OpenCASCADE's cut of a sphere two radii off the axis by the cylinder of radius 1.185854 returns nothing and leaves
// the cavity unusable for every later cut (2026-12-07), so a cut that returns nothing is tried again on a fresh copy
// with the radius moved by 1e-9 of itself, which changes the volume far below the bisection's tolerance.
double liquid_volume(int tag, const Box& box, const std::array<double, 2>& axis, double radius) {
  if (radius <= 0) {
    double v = 0;
    occ::getMass(3, tag, v);
    return v;
  }
  for (int attempt = 0; attempt < 4; ++attempt) {
    gmsh::vectorpair copy, out;
    std::vector<gmsh::vectorpair> map;
    occ::copy({{3, tag}}, copy);
    occ::cut(copy, {{3, gas_cylinder(box, axis, radius * (1 + 1e-9 * attempt))}}, out, map, -1, true, true);
    if (out.empty()) continue;
    const double v = volume_of(out);
    occ::remove(out, true);
    return v;
  }
  throw std::runtime_error("OpenCASCADE's cut of the tank by the cylinder of radius " + std::to_string(radius) +
                           " about the spin axis failed: try a slightly different --fill or --axis-distance");
}

// The distance from the axis to the farthest corner of the box (in x, y): every point of the cavity is nearer.
double outer_radius(const Box& b, const std::array<double, 2>& axis) {
  const double dx = std::max(std::abs(b.x0 - axis[0]), std::abs(b.x1 - axis[0]));
  const double dy = std::max(std::abs(b.y0 - axis[1]), std::abs(b.y1 - axis[1]));
  return std::hypot(dx, dy);
}

}  // namespace

LiquidCut cut_to_fill(int tag, double fill, const std::array<double, 2>& spin_axis) {
  if (!(fill > 0 && fill < 1))
    throw std::runtime_error("a partial fill must lie in (0, 1), got " + std::to_string(fill));
  if (!std::isfinite(spin_axis[0]) || !std::isfinite(spin_axis[1]))
    throw std::runtime_error("the spin axis's position must be finite");
  const Box box = bounding_box(tag);
  double full = 0;
  occ::getMass(3, tag, full);
  const double target = fill * full;
  double lo = 0, hi = outer_radius(box, spin_axis);  // liquid_volume(lo) >= target > liquid_volume(hi) = 0
  for (int i = 0; i < kMaxBisections && (hi - lo) > kFillTolerance * std::max(1.0, hi); ++i) {
    const double mid = 0.5 * (lo + hi);
    (liquid_volume(tag, box, spin_axis, mid) > target ? lo : hi) = mid;
  }
  LiquidCut cut;
  cut.radius = 0.5 * (lo + hi);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  occ::cut({{3, tag}}, {{3, gas_cylinder(box, spin_axis, cut.radius)}}, out, map, -1, true, true);
  if (out.size() != 1 || out[0].first != 3)
    throw std::runtime_error("the liquid at fill " + std::to_string(fill) + " is not one volume (" +
                             std::to_string(out.size()) + " pieces): a tank whose liquid splits is not modelled");
  cut.tag = out[0].second;
  return cut;
}

bool on_free_surface(const std::array<double, 3>& x, double radius, const std::array<double, 2>& spin_axis,
                     double tolerance) {
  return std::abs(std::hypot(x[0] - spin_axis[0], x[1] - spin_axis[1]) - radius) <= tolerance * std::max(1.0, radius);
}

}  // namespace rc::geometry
