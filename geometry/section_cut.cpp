#include "section_cut.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace rc::geometry::detail {
namespace {

namespace occ = gmsh::model::occ;
using Point3 = std::array<double, 3>;

// A boundary curve of the section, oriented along its loop: gmsh's type name and its points from start to end —
// 2 for a line, 3 (start, middle, end) for a circular arc, kSplinePoints for any other curve.
struct CurveShape {
  std::string type;
  std::vector<Point3> points;
};
using Loop = std::vector<CurveShape>;

std::string number(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

bool same_point(const Point3& p, const Point3& q, double tol) {
  return std::hypot(p[0] - q[0], p[1] - q[1]) <= tol;
}

CurveShape read_curve(int tag) {
  CurveShape c;
  gmsh::model::getType(1, tag, c.type);
  std::vector<double> lo, hi;
  gmsh::model::getParametrizationBounds(1, tag, lo, hi);
  const int n = c.type == "Line" ? 2 : c.type == "Circle" ? 3 : kSplinePoints;
  for (int i = 0; i < n; ++i) {
    std::vector<double> xyz;
    gmsh::model::getValue(1, tag, {lo[0] + (hi[0] - lo[0]) * i / (n - 1)}, xyz);
    c.points.push_back({xyz[0], xyz[1], 0.0});
  }
  return c;
}

// The closed loops bounding one 'fluid' surface, each curve oriented to follow the previous one.
std::vector<Loop> surface_loops(int surface, double tol, const std::string& where) {
  gmsh::vectorpair boundary;
  gmsh::model::getBoundary({{2, surface}}, boundary, false, false, false);
  std::vector<CurveShape> pending;
  for (const auto& [dim, tag] : boundary) pending.push_back(read_curve(std::abs(tag)));
  std::vector<Loop> loops;
  while (!pending.empty()) {
    Loop loop{pending.front()};
    pending.erase(pending.begin());
    while (!same_point(loop.back().points.back(), loop.front().points.front(), tol)) {
      const Point3 end = loop.back().points.back();
      const auto next = std::find_if(pending.begin(), pending.end(), [&](const CurveShape& c) {
        return same_point(c.points.front(), end, tol) || same_point(c.points.back(), end, tol);
      });
      if (next == pending.end()) throw std::runtime_error(where + ": the boundary of 'fluid' is not closed");
      if (!same_point(next->points.front(), end, tol)) std::reverse(next->points.begin(), next->points.end());
      loop.push_back(*next);
      pending.erase(next);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

// The centre of the circle through three points.
Point3 circumcentre(const Point3& a, const Point3& b, const Point3& c) {
  const double d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
  const auto n = [](const Point3& p) { return p[0] * p[0] + p[1] * p[1]; };
  return {(n(a) * (b[1] - c[1]) + n(b) * (c[1] - a[1]) + n(c) * (a[1] - b[1])) / d,
          (n(a) * (c[0] - b[0]) + n(b) * (a[0] - c[0]) + n(c) * (b[0] - a[0])) / d, 0.0};
}

// Builds loops as OpenCASCADE wires, sharing the vertices where curves meet.
class OccBuilder {
 public:
  explicit OccBuilder(double tol) : tol_(tol) {}

  int wire(const Loop& loop) {
    std::vector<int> curves;
    for (const auto& c : loop) add_curve(c, curves);
    return occ::addCurveLoop(curves);
  }

 private:
  int vertex(const Point3& p) {
    for (const auto& [q, tag] : vertices_)
      if (same_point(p, q, tol_)) return tag;
    vertices_.push_back({p, occ::addPoint(p[0], p[1], 0)});
    return vertices_.back().second;
  }

  // A construction point (an arc's centre, a spline's inner point), removed once its curve exists.
  static int helper(const Point3& p) { return occ::addPoint(p[0], p[1], 0); }

  void add_curve(const CurveShape& c, std::vector<int>& curves) {
    const auto& p = c.points;
    if (c.type == "Line") {
      curves.push_back(occ::addLine(vertex(p.front()), vertex(p.back())));
    } else if (c.type == "Circle") {
      // Two halves through the middle point: each is below π however long the arc (a full circle included).
      const int centre = helper(circumcentre(p[0], p[1], p[2])), middle = vertex(p[1]);
      curves.push_back(occ::addCircleArc(vertex(p[0]), centre, middle));
      curves.push_back(occ::addCircleArc(middle, centre, vertex(p[2])));
      occ::remove({{0, centre}});
    } else {
      std::vector<int> tags{vertex(p.front())};
      for (std::size_t i = 1; i + 1 < p.size(); ++i) tags.push_back(helper(p[i]));
      tags.push_back(vertex(p.back()));
      curves.push_back(occ::addSpline(tags));
      for (std::size_t i = 1; i + 1 < tags.size(); ++i) occ::remove({{0, tags[i]}});
    }
  }

  double tol_;
  std::vector<std::pair<Point3, int>> vertices_;
};

double loop_extent(const Loop& loop) {
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto& c : loop)
    for (const auto& p : c.points)
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  return (hi[0] - lo[0]) + (hi[1] - lo[1]);
}

// The section's 'fluid' as read from the model open now, loops per surface.
struct SectionOutline {
  std::vector<std::vector<Loop>> surfaces;
  double box[4] = {0, 0, 0, 0};  // r_min, z_min, r_max, z_max
};

SectionOutline read_outline(const std::string& where) {
  SectionOutline s;
  double z0, z1;
  gmsh::model::getBoundingBox(-1, -1, s.box[0], s.box[1], z0, s.box[2], s.box[3], z1);
  const double tol = 1e-9 * std::max({1.0, std::abs(s.box[0]), std::abs(s.box[1]), std::abs(s.box[2]), std::abs(s.box[3])});
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  for (const auto& [dim, group] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, group, name);
    if (name != "fluid") continue;
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(2, group, entities);
    for (int e : entities) s.surfaces.push_back(surface_loops(e, tol, where));
  }
  return s;
}

// The outline rebuilt in the current (OpenCASCADE) model: its plane surfaces, the largest loop outside.
gmsh::vectorpair build_outline(const SectionOutline& s) {
  OccBuilder builder(1e-9 * std::max({1.0, std::abs(s.box[1]), s.box[2], std::abs(s.box[3])}));
  gmsh::vectorpair surfaces;
  for (auto loops : s.surfaces) {
    std::stable_sort(loops.begin(), loops.end(),
                     [](const Loop& a, const Loop& b) { return loop_extent(a) > loop_extent(b); });
    std::vector<int> wires;
    for (const auto& loop : loops) wires.push_back(builder.wire(loop));
    surfaces.push_back({2, occ::addPlaneSurface(wires)});
  }
  return surfaces;
}

// The part r >= b of `surfaces` (kept when keep_original), as new surfaces.
gmsh::vectorpair cut_at(const gmsh::vectorpair& surfaces, const SectionOutline& s, double b, bool keep_original) {
  const double margin = 1 + (s.box[2] - s.box[0]) + (s.box[3] - s.box[1]);
  const int tool = occ::addRectangle(s.box[0] - margin, s.box[1] - margin, 0, b - s.box[0] + margin,
                                     s.box[3] - s.box[1] + 2 * margin);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  occ::cut(surfaces, {{2, tool}}, out, map, -1, !keep_original, true);
  gmsh::vectorpair kept;
  for (const auto& dt : out)
    if (dt.first == 2) kept.push_back(dt);
  return kept;
}

// ∫∫ r dA over the surfaces: area times the centroid's r (Pappus), both from OpenCASCADE's exact properties.
double r_moment(const gmsh::vectorpair& surfaces) {
  double sum = 0;
  for (const auto& [dim, tag] : surfaces) {
    double area = 0, x = 0, y = 0, z = 0;
    occ::getMass(dim, tag, area);
    occ::getCenterOfMass(dim, tag, x, y, z);
    sum += area * x;
  }
  return sum;
}

// Connected components of items linked when they share a key (union-find over a key → item list).
int component_count(const std::vector<std::vector<int>>& keys_of_item) {
  std::vector<int> parent(keys_of_item.size());
  std::iota(parent.begin(), parent.end(), 0);
  const std::function<int(int)> root = [&](int i) { return parent[i] == i ? i : parent[i] = root(parent[i]); };
  for (std::size_t i = 0; i < keys_of_item.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      for (int k : keys_of_item[i])
        if (std::count(keys_of_item[j].begin(), keys_of_item[j].end(), k)) parent[root(int(i))] = root(int(j));
  int count = 0;
  for (std::size_t i = 0; i < parent.size(); ++i) count += root(int(i)) == int(i);
  return count;
}

std::vector<int> boundary_tags(int dim, int tag) {
  gmsh::vectorpair boundary;
  gmsh::model::getBoundary({{dim, tag}}, boundary, false, false, false);
  std::vector<int> tags;
  for (const auto& [d, t] : boundary) tags.push_back(std::abs(t));
  return tags;
}

bool on_free_surface(int curve, double b, double tol) {
  std::vector<double> lo, hi;
  gmsh::model::getParametrizationBounds(1, curve, lo, hi);
  for (double f : {0.0, 0.5, 1.0}) {
    std::vector<double> xyz;
    gmsh::model::getValue(1, curve, {lo[0] + f * (hi[0] - lo[0])}, xyz);
    if (std::abs(xyz[0] - b) > tol) return false;
  }
  return true;
}

// The synchronised cut's surfaces and boundary curves.
struct CutParts {
  std::vector<int> surfaces, wall, free;
};

// Sorts the cut's curves into wall and free surface; refuses a liquid in pieces or a free surface in several segments.
CutParts classify_cut(const gmsh::vectorpair& liquid, double b, double tol, const std::string& where) {
  CutParts parts;
  std::vector<std::vector<int>> curves_of_surface;
  for (const auto& [dim, tag] : liquid) parts.surfaces.push_back(tag), curves_of_surface.push_back(boundary_tags(2, tag));
  if (const int pieces = component_count(curves_of_surface); pieces > 1)
    throw std::runtime_error(where + ": the free surface r = " + number(b) + " cuts the liquid into " +
                             std::to_string(pieces) + " pieces (a fill needs one liquid region outside it)");
  gmsh::vectorpair boundary;
  gmsh::model::getBoundary(liquid, boundary, true, false, false);
  std::vector<std::vector<int>> points_of_free;
  for (const auto& [dim, tag] : boundary) {
    const int c = std::abs(tag);
    if (!on_free_surface(c, b, tol)) {
      parts.wall.push_back(c);
      continue;
    }
    parts.free.push_back(c);
    points_of_free.push_back(boundary_tags(1, c));
  }
  if (const int segments = component_count(points_of_free); segments != 1)
    throw std::runtime_error(where + ": the free surface r = " + number(b) + " meets the section in " +
                             std::to_string(segments) + " separate segments (it must be one coaxial cylinder)");
  return parts;
}

// The part r >= b of the outline, built in the current model and synchronised, its parts sorted.
CutParts cut_outline(const SectionOutline& s, double b, const std::string& where) {
  gmsh::vectorpair liquid = cut_at(build_outline(s), s, b, false);
  if (liquid.size() > 1) {
    gmsh::vectorpair fragments;
    std::vector<gmsh::vectorpair> map;
    occ::fragment(liquid, {}, fragments, map);
    liquid = fragments;
  }
  occ::synchronize();
  return classify_cut(liquid, b, 1e-9 * std::max({1.0, std::abs(s.box[1]), s.box[2], std::abs(s.box[3])}), where);
}

}  // namespace

void refuse_drawn_free_surface(const std::string& where) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 1);
  for (const auto& [dim, group] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, group, name);
    if (name == "free")
      throw std::runtime_error(where + ": a 1D physical group 'free' (a free surface) is not read: draw the whole "
                               "cavity and give --fill, which cuts it at its free surface (docs/modes.md, \"Partially "
                               "filled tanks\")");
  }
}

double section_free_radius(double fill, const std::string& where) {
  refuse_drawn_free_surface(where);
  const SectionOutline s = read_outline(where);
  std::string section;
  gmsh::model::getCurrent(section);
  gmsh::model::add("fill");
  const gmsh::vectorpair whole = build_outline(s);
  const double total = r_moment(whole);
  // The fraction beyond b falls from 1 at r_min to 0 at r_max.
  double lo = s.box[0], hi = s.box[2];
  for (int i = 0; i < 200 && hi - lo > 4e-16 * hi; ++i) {
    const double b = 0.5 * (lo + hi);
    (r_moment(cut_at(whole, s, b, true)) > fill * total ? lo : hi) = b;
  }
  const double b = 0.5 * (lo + hi);
  gmsh::model::add("check");
  try {
    cut_outline(s, b, where);  // refuses a cut the solvers cannot take, before any mesh is made
  } catch (...) {
    gmsh::model::setCurrent(section);
    throw;
  }
  gmsh::model::remove();
  gmsh::model::setCurrent("fill");
  gmsh::model::remove();
  gmsh::model::setCurrent(section);
  return b;
}

void cut_section(double b, const std::string& where) {
  const SectionOutline s = read_outline(where);
  gmsh::model::add("liquid");
  const CutParts parts = cut_outline(s, b, where);
  for (const auto& [dim, group, name] :
       {std::tuple{2, &parts.surfaces, "fluid"}, {1, &parts.wall, "wall"}, {1, &parts.free, "free"}})
    gmsh::model::setPhysicalName(dim, gmsh::model::addPhysicalGroup(dim, *group), name);
}

}  // namespace rc::geometry::detail
