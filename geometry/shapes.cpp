// Built-in shapes in gmsh's built-in ("geo") CAD kernel: exact circle and ellipse arcs, so that
// setOrder() puts the high-order boundary nodes on the true wall.
#include "shapes.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rc::geometry::detail {
namespace {

namespace geo = gmsh::model::geo;

const std::map<std::string, std::vector<std::string>>& required_dims() {
  static const std::map<std::string, std::vector<std::string>> dims = {
      {"sphere", {"radius"}},
      {"spheroid", {"a", "c"}},
      {"cylinder", {"radius", "height"}},
      {"cone", {"radius", "height"}},
      {"section", {}},
  };
  return dims;
}

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "none" : s;
}

std::string number(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

double dim(const ShapeSpec& shape, const std::string& name) { return shape.dims.at(name); }

// Physical groups as the solver expects them: one fluid surface, wall curves, axis curves.
void add_groups(int surface, const std::vector<int>& wall, const std::vector<int>& axis) {
  geo::synchronize();
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}), "fluid");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, wall), "wall");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, axis), "axis");
}

// Counter-clockwise loop of curves -> plane surface (positively oriented triangles).
int surface(const std::vector<int>& curves) { return geo::addPlaneSurface({geo::addCurveLoop(curves)}); }

// Two quarter arcs of the ellipse r²/a² + z²/c² = 1 from the south to the north pole (circle
// arcs when a == c: gmsh's ellipse needs distinct axes), then the axis back down.
void build_ellipse(double a, double c, double h) {
  const int centre = geo::addPoint(0, 0, 0, h);
  const int south = geo::addPoint(0, -c, 0, h), equator = geo::addPoint(a, 0, 0, h),
            north = geo::addPoint(0, c, 0, h);
  int lower, upper;
  if (a == c) {
    lower = geo::addCircleArc(south, centre, equator);
    upper = geo::addCircleArc(equator, centre, north);
  } else {
    const int major = a > c ? equator : north;  // any point on the major axis
    lower = geo::addEllipseArc(south, centre, major, equator);
    upper = geo::addEllipseArc(equator, centre, major, north);
  }
  const int axis = geo::addLine(north, south);
  add_groups(surface({lower, upper, axis}), {lower, upper}, {axis});
}

void build_cylinder(double radius, double height, double h, double radial_size) {
  const double z0 = -0.5 * height, z1 = 0.5 * height;
  const int p0 = geo::addPoint(0, z0, 0, h), p1 = geo::addPoint(radius, z0, 0, h),
            p2 = geo::addPoint(radius, z1, 0, h), p3 = geo::addPoint(0, z1, 0, h);
  const int bottom = geo::addLine(p0, p1), side = geo::addLine(p1, p2), top = geo::addLine(p2, p3),
            axis = geo::addLine(p3, p0);
  const int fluid = surface({bottom, side, top, axis});
  if (radial_size > 0) {
    // Low-frequency inertial modes vary much faster in r than in z (Stewartson: ξ = k a √(κ² − 1)), so
    // the radial and axial sizes are set apart.
    const int nr = std::max(1, static_cast<int>(std::ceil(radius / radial_size - 1e-9)));
    const int nz = std::max(1, static_cast<int>(std::ceil(height / h - 1e-9)));
    for (int c : {bottom, top}) geo::mesh::setTransfiniteCurve(c, nr + 1);
    for (int c : {side, axis}) geo::mesh::setTransfiniteCurve(c, nz + 1);
    geo::mesh::setTransfiniteSurface(fluid, "Alternate");
  }
  add_groups(fluid, {bottom, side, top}, {axis});
}

void build_cone(double radius, double height, double h) {
  const int apex = geo::addPoint(0, 0, 0, h), rim = geo::addPoint(radius, height, 0, h),
            centre = geo::addPoint(0, height, 0, h);
  const int slant = geo::addLine(apex, rim), lid = geo::addLine(rim, centre), axis = geo::addLine(centre, apex);
  add_groups(surface({slant, lid, axis}), {slant, lid}, {axis});
}

}  // namespace

void validate_shape(const ShapeSpec& shape) {
  const auto it = required_dims().find(shape.kind);
  if (it == required_dims().end())
    throw std::runtime_error("unknown shape kind '" + shape.kind +
                             "' (expected sphere, spheroid, cylinder, cone or section)");
  const auto& names = it->second;
  for (const auto& [name, value] : shape.dims) {
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw std::runtime_error(shape.kind + ": unknown dimension '" + name + "' (expected: " + join(names) + ")");
    if (!std::isfinite(value) || value <= 0)
      throw std::runtime_error(shape.kind + ": dimension " + name + " = " + number(value) +
                               " must be positive and finite");
  }
  for (const auto& name : names)
    if (!shape.dims.count(name)) throw std::runtime_error(shape.kind + ": missing dimension '" + name + "'");
  if (shape.kind == "section" && shape.file.empty())
    throw std::runtime_error("section: no file given (a .geo or .msh meridian section)");
}

double smallest_dimension(const ShapeSpec& shape) {
  if (shape.kind == "sphere") return dim(shape, "radius");
  if (shape.kind == "spheroid") return std::min(dim(shape, "a"), dim(shape, "c"));
  return std::min(dim(shape, "radius"), dim(shape, "height"));
}

void build_shape(const ShapeSpec& shape, double size, double radial_size) {
  if (radial_size > 0 && shape.kind != "cylinder")
    throw std::runtime_error(shape.kind + ": a radial mesh size (structured mesh) is only available for the cylinder");
  if (shape.kind == "sphere") {
    const double r = dim(shape, "radius");
    build_ellipse(r, r, size);
  } else if (shape.kind == "spheroid") {
    build_ellipse(dim(shape, "a"), dim(shape, "c"), size);
  } else if (shape.kind == "cylinder") {
    build_cylinder(dim(shape, "radius"), dim(shape, "height"), size, radial_size);
  } else if (shape.kind == "cone") {
    build_cone(dim(shape, "radius"), dim(shape, "height"), size);
  } else {
    throw std::logic_error("build_shape: not a built-in shape: " + shape.kind);
  }
}

}  // namespace rc::geometry::detail
