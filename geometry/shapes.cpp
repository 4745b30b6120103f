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

// Dimensions a shape may take besides its required ones: the cylinder's coaxial rod (an annular cavity, no axis),
// and the free surface r = free_radius of a partially filled tank (geometry/free_surface.hpp; the liquid is the part
// of the cavity with r >= free_radius).
const std::map<std::string, std::vector<std::string>>& optional_dims() {
  static const std::map<std::string, std::vector<std::string>> dims = {{"cylinder", {"inner_radius", "free_radius"}},
                                                                       {"sphere", {"free_radius"}},
                                                                       {"spheroid", {"free_radius"}},
                                                                       {"cone", {"free_radius"}},
                                                                       {"section", {"free_radius"}}};
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

// Physical groups as the solver expects them: the fluid surfaces, wall curves, axis curves, free-surface curves.
void add_groups(const std::vector<int>& fluid, const std::vector<int>& wall, const std::vector<int>& axis,
                const std::vector<int>& free = {}) {
  geo::synchronize();
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, fluid), "fluid");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, wall), "wall");
  if (!axis.empty()) gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, axis), "axis");
  if (!free.empty()) gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, free), "free");
}

// Counter-clockwise loop of curves -> plane surface (positively oriented triangles).
int surface(const std::vector<int>& curves) { return geo::addPlaneSurface({geo::addCurveLoop(curves)}); }

// Two arcs of the ellipse r²/a² + z²/c² = 1 from the south to the north pole (circle arcs when a == c: gmsh's
// ellipse needs distinct axes), then the axis back down. free > 0: the arcs start and end on the free surface
// r = free, z = ±c √(1 − free²/a²), and its line closes the section instead of the axis.
void build_ellipse(double a, double c, double h, double free) {
  const int centre = geo::addPoint(0, 0, 0, h);
  const double zf = c * std::sqrt(std::max(0.0, 1 - free * free / (a * a)));
  const int south = geo::addPoint(free, -zf, 0, h), equator = geo::addPoint(a, 0, 0, h),
            north = geo::addPoint(free, zf, 0, h);
  int lower, upper;
  if (a == c) {
    lower = geo::addCircleArc(south, centre, equator);
    upper = geo::addCircleArc(equator, centre, north);
  } else {
    // Any point on the major axis (with a free surface the pole is no point of the section).
    const int major = a > c ? equator : free > 0 ? geo::addPoint(0, c, 0, h) : north;
    lower = geo::addEllipseArc(south, centre, major, equator);
    upper = geo::addEllipseArc(equator, centre, major, north);
  }
  const int closing = geo::addLine(north, south);
  if (free > 0) add_groups({surface({lower, upper, closing})}, {lower, upper}, {}, {closing});
  else add_groups({surface({lower, upper, closing})}, {lower, upper}, {closing});
}

// inner > 0: the liquid around a coaxial rod of that radius; the rod's line is wall and there is no axis.
// free > 0: the liquid outside the free surface r = free (beyond any rod), whose line is "free".
void build_cylinder(double radius, double height, double h, double radial_size, double rod, double free) {
  const double inner = std::max(rod, free);
  const double z0 = -0.5 * height, z1 = 0.5 * height;
  const int p0 = geo::addPoint(inner, z0, 0, h), p1 = geo::addPoint(radius, z0, 0, h),
            p2 = geo::addPoint(radius, z1, 0, h), p3 = geo::addPoint(inner, z1, 0, h);
  const int bottom = geo::addLine(p0, p1), side = geo::addLine(p1, p2), top = geo::addLine(p2, p3),
            axis = geo::addLine(p3, p0);
  const int fluid = surface({bottom, side, top, axis});
  if (radial_size > 0) {
    // Low-frequency inertial modes vary much faster in r than in z (Stewartson: ξ = k a √(κ² − 1)), so
    // the radial and axial sizes are set apart.
    const int nr = std::max(1, static_cast<int>(std::ceil((radius - inner) / radial_size - 1e-9)));
    const int nz = std::max(1, static_cast<int>(std::ceil(height / h - 1e-9)));
    for (int c : {bottom, top}) geo::mesh::setTransfiniteCurve(c, nr + 1);
    for (int c : {side, axis}) geo::mesh::setTransfiniteCurve(c, nz + 1);
    geo::mesh::setTransfiniteSurface(fluid, "Alternate");
  }
  if (free > 0) add_groups({fluid}, {bottom, side, top}, {}, {axis});
  else if (inner > 0) add_groups({fluid}, {bottom, side, top, axis}, {});
  else add_groups({fluid}, {bottom, side, top}, {axis});
}

// free > 0: the liquid outside the free surface r = free, which meets the slant at z = free·height/radius.
void build_cone(double radius, double height, double h, double free) {
  const int apex = geo::addPoint(free, free * height / radius, 0, h), rim = geo::addPoint(radius, height, 0, h),
            centre = geo::addPoint(free, height, 0, h);
  const int slant = geo::addLine(apex, rim), lid = geo::addLine(rim, centre), closing = geo::addLine(centre, apex);
  if (free > 0) add_groups({surface({slant, lid, closing})}, {slant, lid}, {}, {closing});
  else add_groups({surface({slant, lid, closing})}, {slant, lid}, {closing});
}

// Nodes across a wall layer of thickness t whose cells start at `first` and grow by `ratio`: the smallest count
// whose geometric cells reach t (gmsh then scales the progression to t exactly, so the first cell is <= first).
int layer_nodes(double t, double first, double ratio) {
  return 2 + static_cast<int>(std::ceil(std::log1p(t * (ratio - 1) / first) / std::log(ratio) - 1 - 1e-9));
}

// The cone with its Ekman layers built in (docs/geometry.md, "Wall-refined meshes"): a strip of thickness t along
// the slant and one along the lid, each a structured (transfinite) grid whose cells grow geometrically from the
// wall, and an unstructured interior triangle. gmsh's BoundaryLayer field crashed or inverted where the slant meets
// the axis at the apex; here the slant strip simply ends on the axis: its last column of cells joins the apex to
// the point of the axis at distance t from the slant, z_a = t L / R (L the slant's length).
//
//   centre (0,H) ---- lid ---- rim (R,H)         strips: slant (apex, rim, inner corner, inner apex)
//   (0,H-t) ---- inner lid ---- inner corner              lid   (rim, centre, (0,H-t), inner corner)
//   |  interior  /                               corner diagonal rim -> inner corner, shared by both
//   (0,z_a) ---/ inner slant                      interior: the triangle (0,z_a), inner corner, (0,H-t)
//   apex (0,0)
void build_layered_cone(double R, double H, double h, const MeshOptions& o) {
  const double L = std::hypot(R, H), t = o.wall_layer;
  const double r_inner = (R * (H - t) - t * L) / H, z_a = t * L / R;
  if (!(r_inner > 2 * t && z_a < H - 2 * t))
    throw std::runtime_error("cone: wall layers " + number(t) + " thick do not fit in the cone (radius " + number(R) +
                             ", height " + number(H) + ")");
  const int apex = geo::addPoint(0, 0, 0, h), rim = geo::addPoint(R, H, 0, h), centre = geo::addPoint(0, H, 0, h),
            inner_centre = geo::addPoint(0, H - t, 0, h), inner_corner = geo::addPoint(r_inner, H - t, 0, h),
            inner_apex = geo::addPoint(0, z_a, 0, h);
  const int slant = geo::addLine(apex, rim), lid = geo::addLine(rim, centre);
  const int diagonal = geo::addLine(rim, inner_corner);         // from the wall inwards
  const int axis_lid = geo::addLine(centre, inner_centre);      // from the wall inwards
  const int axis_apex = geo::addLine(apex, inner_apex);         // from the wall inwards
  const int inner_slant = geo::addLine(inner_corner, inner_apex), inner_lid = geo::addLine(inner_centre, inner_corner);
  const int axis_interior = geo::addLine(inner_centre, inner_apex);
  const int slant_strip = surface({slant, diagonal, inner_slant, -axis_apex});
  const int lid_strip = surface({lid, axis_lid, inner_lid, -diagonal});
  const int interior = surface({-inner_slant, -inner_lid, axis_interior});
  // Across the layers: geometric cells from the wall (first o.wall_size, ratio 1 + o.wall_growth).
  const double ratio = 1 + o.wall_growth;
  const int across = layer_nodes(t, o.wall_size, ratio);
  for (int c : {diagonal, axis_lid, axis_apex}) geo::mesh::setTransfiniteCurve(c, across, "Progression", ratio);
  // Along the walls: the interior size h.
  const int along_slant = 1 + std::max(2, static_cast<int>(std::ceil(L / h - 1e-9)));
  const int along_lid = 1 + std::max(2, static_cast<int>(std::ceil(R / h - 1e-9)));
  for (int c : {slant, inner_slant}) geo::mesh::setTransfiniteCurve(c, along_slant);
  for (int c : {lid, inner_lid}) geo::mesh::setTransfiniteCurve(c, along_lid);
  geo::mesh::setTransfiniteSurface(slant_strip, "Alternate", {apex, rim, inner_corner, inner_apex});
  geo::mesh::setTransfiniteSurface(lid_strip, "Alternate", {rim, centre, inner_centre, inner_corner});
  add_groups({slant_strip, lid_strip, interior}, {slant, lid}, {axis_apex, axis_interior, axis_lid});
}

// Along a wall strip near a contact line: cells from h/8 at the free surface growing by kContactGrowth, over the
// length they take to reach about h (the other shapes' contact-line field: size/8 at the contact points, the interior
// size 2 h away; geometry/meridian_mesh.cpp). The count of cells over `length`.
constexpr double kContactGrowth = 1.3;
int contact_cells(double length, double h) {
  return std::max(2, static_cast<int>(std::ceil(std::log1p(length / (h / 8) * (kContactGrowth - 1)) /
                                                std::log(kContactGrowth) - 1e-9)));
}

// The partially filled cone (the liquid at r >= free): the same triangle as build_layered_cone's, scaled by
// 1 - free/R, with its corner at the lower contact point c0 = (free, free H/R) instead of the apex and its side
// r = free the free surface instead of the axis, so the strips end on the free surface at both contact lines (the
// BoundaryLayer field's PointsList does so for the other shapes: docs/viscous.md, "Contact lines and the wall
// layers"). The flow is singular at the contact lines, so each strip is split a length l from its contact line, the
// part next to it graded along the wall from h/8 (contact_cells):
//
//   (free,H) l1 ------ lid ------ rim        strips: slant near c0 (c0, s1, s1', inner apex), slant (s1, rim, inner
//   |   C    |          D         |                  corner, s1'), lid near (free,H) C, lid D; interior unstructured
//   inner centre, l1', inner corner (H - t)
//   inner apex, s1' on the inner slant (distance t from the slant); s1 on the slant at l from c0
//   c0
void build_layered_partial_cone(double R, double H, double h, const MeshOptions& o, double free) {
  const double r0 = free, z0 = free * H / R, Rl = R - r0, Hl = H - z0;  // the liquid triangle's legs
  const double L = std::hypot(Rl, Hl), t = o.wall_layer;
  const double r_inner = (Rl * (Hl - t) - t * L) / Hl, z_a = t * L / Rl;
  const double l = std::min({2 * h, L / 3, r_inner / 3});
  if (!(r_inner > 2 * t && z_a < Hl - 2 * t && l > 1.5 * z_a * Hl / L))
    throw std::runtime_error("cone: wall layers " + number(t) + " thick do not fit in the liquid of the cone (radius " +
                             number(R) + ", height " + number(H) + ", free surface radius " + number(free) +
                             "); use a smaller --mesh-size (the layers are at most half an interior element thick)");
  const double er = Rl / L, ez = Hl / L;  // the slant's direction; its inward normal (−ez, er)
  const auto point = [&](double r, double z) { return geo::addPoint(r, z, 0, h); };
  const int c0 = point(r0, z0), rim = point(R, H), centre = point(r0, H), inner_centre = point(r0, H - t),
            inner_corner = point(r0 + r_inner, H - t), inner_apex = point(r0, z0 + z_a),
            s1 = point(r0 + l * er, z0 + l * ez), s1_in = point(r0 + l * er - t * ez, z0 + l * ez + t * er),
            l1 = point(r0 + l, H), l1_in = point(r0 + l, H - t);
  const auto line = [](int a, int b) { return geo::addLine(a, b); };
  // Walls, the free surface's pieces and the cross lines; every cross line from the wall inwards.
  const int slant_near = line(c0, s1), slant_far = line(s1, rim), lid_far = line(rim, l1), lid_near = line(centre, l1);
  const int free_slant = line(c0, inner_apex), free_lid = line(centre, inner_centre),
            free_interior = line(inner_centre, inner_apex);
  const int cross_s = line(s1, s1_in), diagonal = line(rim, inner_corner), cross_l = line(l1, l1_in);
  const int inner_slant_near = line(inner_apex, s1_in), inner_slant_far = line(inner_corner, s1_in),
            inner_lid_near = line(inner_centre, l1_in), inner_lid_far = line(l1_in, inner_corner);
  const int strip_a = surface({slant_near, cross_s, -inner_slant_near, -free_slant});
  const int strip_b = surface({slant_far, diagonal, inner_slant_far, -cross_s});
  const int strip_c = surface({-lid_near, free_lid, inner_lid_near, -cross_l});
  const int strip_d = surface({lid_far, cross_l, inner_lid_far, -diagonal});
  const int interior = surface({inner_slant_near, -inner_slant_far, -inner_lid_far, -inner_lid_near, free_interior});
  const double ratio = 1 + o.wall_growth;
  const int across = layer_nodes(t, o.wall_size, ratio);
  for (int c : {free_slant, free_lid, cross_s, diagonal, cross_l})
    geo::mesh::setTransfiniteCurve(c, across, "Progression", ratio);
  const int near = 1 + contact_cells(l, h);  // from the free surface outwards, on the wall and the inner line alike
  for (int c : {slant_near, inner_slant_near, lid_near, inner_lid_near})
    geo::mesh::setTransfiniteCurve(c, near, "Progression", kContactGrowth);
  const auto uniform = [&](double length) { return 1 + std::max(2, static_cast<int>(std::ceil(length / h - 1e-9))); };
  for (int c : {slant_far, inner_slant_far}) geo::mesh::setTransfiniteCurve(c, uniform(L - l));
  for (int c : {lid_far, inner_lid_far}) geo::mesh::setTransfiniteCurve(c, uniform(Rl - l));
  geo::mesh::setTransfiniteSurface(strip_a, "Alternate", {c0, s1, s1_in, inner_apex});
  geo::mesh::setTransfiniteSurface(strip_b, "Alternate", {s1, rim, inner_corner, s1_in});
  geo::mesh::setTransfiniteSurface(strip_c, "Alternate", {l1, centre, inner_centre, l1_in});
  geo::mesh::setTransfiniteSurface(strip_d, "Alternate", {rim, l1, l1_in, inner_corner});
  add_groups({strip_a, strip_b, strip_c, strip_d, interior}, {slant_near, slant_far, lid_far, lid_near}, {},
             {free_slant, free_interior, free_lid});
}

}  // namespace

void validate_shape(const ShapeSpec& shape) {
  const auto it = required_dims().find(shape.kind);
  if (it == required_dims().end())
    throw std::runtime_error("unknown shape kind '" + shape.kind +
                             "' (expected sphere, spheroid, cylinder, cone or section)");
  const auto& names = it->second;
  std::vector<std::string> allowed = names;
  if (const auto opt = optional_dims().find(shape.kind); opt != optional_dims().end())
    allowed.insert(allowed.end(), opt->second.begin(), opt->second.end());
  for (const auto& [name, value] : shape.dims) {
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
      throw std::runtime_error(shape.kind + ": unknown dimension '" + name + "' (expected: " + join(allowed) + ")");
    if (!std::isfinite(value) || value <= 0)
      throw std::runtime_error(shape.kind + ": dimension " + name + " = " + number(value) +
                               " must be positive and finite");
  }
  for (const auto& name : names)
    if (!shape.dims.count(name)) throw std::runtime_error(shape.kind + ": missing dimension '" + name + "'");
  if (shape.dims.count("inner_radius") && !(shape.dims.at("inner_radius") < shape.dims.at("radius")))
    throw std::runtime_error(shape.kind + ": inner radius " + number(shape.dims.at("inner_radius")) +
                             " must be below the radius " + number(shape.dims.at("radius")));
  // A section's free radius is checked where its file is cut (section_cut.hpp).
  if (shape.dims.count("free_radius") && shape.kind != "section") {
    const double b = shape.dims.at("free_radius"), outer = shape.kind == "spheroid" ? dim(shape, "a") : dim(shape, "radius");
    const double inner = shape.dims.count("inner_radius") ? dim(shape, "inner_radius") : 0.0;
    if (!(b > inner && b < outer))
      throw std::runtime_error(shape.kind + ": free surface radius " + number(b) + " must lie between " +
                               number(inner) + " and " + number(outer));
  }
  if (shape.kind == "section" && shape.file.empty())
    throw std::runtime_error("section: no file given (a .geo or .msh meridian section)");
}

double smallest_dimension(const ShapeSpec& shape) {
  const double free = shape.dims.count("free_radius") ? dim(shape, "free_radius") : 0.0;
  if (shape.kind == "sphere") return dim(shape, "radius") - free;
  if (shape.kind == "spheroid") return std::min(dim(shape, "a") - free, dim(shape, "c"));
  const double inner = std::max(free, shape.dims.count("inner_radius") ? dim(shape, "inner_radius") : 0.0);
  return std::min(dim(shape, "radius") - inner, dim(shape, "height"));
}

bool build_shape(const ShapeSpec& shape, double size, double radial_size, const MeshOptions* layers) {
  if (radial_size > 0 && shape.kind != "cylinder")
    throw std::runtime_error(shape.kind + ": a radial mesh size (structured mesh) is only available for the cylinder");
  const double free = shape.dims.count("free_radius") ? dim(shape, "free_radius") : 0.0;
  if (shape.kind == "sphere") {
    const double r = dim(shape, "radius");
    build_ellipse(r, r, size, free);
  } else if (shape.kind == "spheroid") {
    build_ellipse(dim(shape, "a"), dim(shape, "c"), size, free);
  } else if (shape.kind == "cylinder") {
    build_cylinder(dim(shape, "radius"), dim(shape, "height"), size, radial_size,
                   shape.dims.count("inner_radius") ? dim(shape, "inner_radius") : 0.0, free);
  } else if (shape.kind == "cone") {
    if (layers && layers->wall_size > 0 && layers->wall_layer > layers->wall_size) {
      if (free > 0) build_layered_partial_cone(dim(shape, "radius"), dim(shape, "height"), size, *layers, free);
      else build_layered_cone(dim(shape, "radius"), dim(shape, "height"), size, *layers);
      return true;
    }
    build_cone(dim(shape, "radius"), dim(shape, "height"), size, free);
  } else {
    throw std::logic_error("build_shape: not a built-in shape: " + shape.kind);
  }
  return false;
}

}  // namespace rc::geometry::detail
