// mesh_meridian: build or read the CAD model, mesh it with gmsh, then turn gmsh's tagged data into
// the compact, checked MeridianMesh the FE solver consumes.
#include "meridian_mesh.hpp"

#include "gmsh_session.hpp"
#include "section_cut.hpp"
#include "shapes.hpp"
#include "size_fields.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace rc::geometry {
namespace {

constexpr int kMaxOrder = 6;
constexpr double kDefaultSizeFraction = 1.0 / 8.0;  // default size = this × smallest dimension
constexpr double kMaxCellsPerExtent = 1e4;         // larger ratios would mean >~1e8 triangles
constexpr double kAxisTolerance = 1e-12;            // relative to max(1, model extent)

std::string number(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

int nodes_per_triangle(int order) { return (order + 1) * (order + 2) / 2; }

void check_options(const MeshOptions& options) {
  if (options.order < 1 || options.order > kMaxOrder)
    throw std::runtime_error("mesh order " + std::to_string(options.order) + " is outside 1.." +
                             std::to_string(kMaxOrder));
  if (!std::isfinite(options.size) || options.size < 0)
    throw std::runtime_error("mesh size " + number(options.size) + " must be positive and finite (0 = default)");
  if (!std::isfinite(options.radial_size) || options.radial_size < 0)
    throw std::runtime_error("radial mesh size " + number(options.radial_size) +
                             " must be positive and finite (0 = unstructured)");
  if (!std::isfinite(options.wall_size) || options.wall_size < 0)
    throw std::runtime_error("wall mesh size " + number(options.wall_size) + " must be positive and finite (0 = none)");
  if (!std::isfinite(options.wall_growth) || options.wall_growth <= 0 || options.wall_growth > 10)
    throw std::runtime_error("wall size growth " + number(options.wall_growth) + " must be in (0, 10]");
  if (!std::isfinite(options.wall_layer) || options.wall_layer < 0)
    throw std::runtime_error("wall layer thickness " + number(options.wall_layer) + " must be >= 0 and finite");
  if (!std::isfinite(options.near_wall_size) || options.near_wall_size < 0)
    throw std::runtime_error("near-wall size " + number(options.near_wall_size) + " must be positive and finite (0 = none)");
  if (!std::isfinite(options.near_wall_growth) || options.near_wall_growth <= 0 || options.near_wall_growth > 10)
    throw std::runtime_error("near-wall growth " + number(options.near_wall_growth) + " must be in (0, 10]");
  if (options.wall_size > 0 && options.radial_size > 0)
    throw std::runtime_error("a wall-graded mesh cannot also be structured (give either the wall size or the radial size)");
}

// ---------------------------------------------------------------------------------------------
// gmsh side: everything here runs inside a GmshSession.

// What gmsh returns, still in gmsh node tags.
struct GmshMesh {
  int order = 0;
  double size = 0;
  std::unordered_map<std::size_t, std::array<double, 2>> coords;  // node tag -> (r, z)
  std::vector<std::size_t> triangles, wall_edges, axis_nodes, free_edges;
  std::vector<double> local_nodes;  // (u, v) of the triangle's local nodes
  double extent = 1;                // largest |coordinate| of the model, for tolerances
};

double model_extent() {
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  return std::max({std::abs(x0), std::abs(y0), std::abs(x1), std::abs(y1)});
}

// Smallest side of the model's bounding box: the characteristic length of a user section.
double model_smallest_side() {
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  return std::min(x1 - x0, y1 - y0);
}

std::vector<int> group_entities(int dim, int tag);
int physical_tag(int dim, const std::string& name, const std::string& where);
int find_physical_tag(int dim, const std::string& name);

// The tags of the points where a partially filled tank's free surface (the 'free' curves) meets the wall: its contact
// lines. None without a free surface.
std::vector<double> contact_points() {
  const int free = find_physical_tag(1, "free");
  if (free < 0) return {};
  gmsh::vectorpair curves, ends;
  for (int c : group_entities(1, free)) curves.push_back({1, c});
  gmsh::model::getBoundary(curves, ends, false, false, false);
  std::vector<double> points;
  for (const auto& [dim, tag] : ends) points.push_back(tag);
  return points;
}

// Whether a wall curve meets the axis obliquely (a cone's apex: its tangent there more than 1e-6 off the radial
// direction). gmsh 4.8's BoundaryLayer field does not mesh such a point reliably: carried on through it, it
// crashed (a segmentation fault in its Delaunay, DocRecord, on data/sections/cone.geo at Ek = 1e-3, 2026-12-02) or
// inverted elements; ended there (PointsList), two runs of three fell back to the grading and the third hung in gmsh. So a section
// with such a point gets the isotropic grading (grade_towards_wall). A wall meeting the axis at a right angle (a
// sphere's poles) keeps its layers through the axis; the built-in cone builds its layers into its CAD model.
bool wall_meets_axis_obliquely() {
  const int axis = find_physical_tag(1, "axis"), wall = find_physical_tag(1, "wall");
  if (axis < 0 || wall < 0) return false;
  gmsh::vectorpair axis_curves, axis_ends;
  for (int c : group_entities(1, axis)) axis_curves.push_back({1, c});
  gmsh::model::getBoundary(axis_curves, axis_ends, true, false, false);
  for (int c : group_entities(1, wall)) {
    gmsh::vectorpair ends;
    gmsh::model::getBoundary({{1, c}}, ends, false, false, false);
    std::vector<double> lo, hi;
    gmsh::model::getParametrizationBounds(1, c, lo, hi);
    for (std::size_t e = 0; e < ends.size() && e < 2; ++e) {
      const int tag = std::abs(ends[e].second);
      if (std::none_of(axis_ends.begin(), axis_ends.end(), [&](const auto& p) { return std::abs(p.second) == tag; }))
        continue;
      std::vector<double> d;
      gmsh::model::getDerivative(1, c, {e == 0 ? lo[0] : hi[0]}, d);
      const double norm = std::hypot(d[0], d[1]);
      if (norm > 0 && std::abs(d[1]) > 1e-6 * norm) return true;
    }
  }
  return false;
}

// Anisotropic layers along the wall (gmsh BoundaryLayer field), or isotropic elements of size wall_size at the
// wall growing linearly with the distance d from it, size(d) = wall_size + growth · (d − wall_size), up to `size`
// (gmsh Distance + Threshold fields; the wall sampled finely enough that the distance is accurate there).
// A partially filled tank's contact lines, where its free surface (the 'free' curves) meets a no-slip wall: the viscous
// flow is singular there and the damped modes converged only like h^1.3 with the interior size h (docs/viscous.md,
// "Partially filled tanks"). A Threshold field refines towards those points: size/8 within size/8 of them, growing to
// `size` at 2 size. Returns the field, or -1 without a free surface.
int contact_line_field(double size) {
  DistanceTo points;
  points.points = contact_points();
  if (points.points.empty()) return -1;
  return distance_threshold(points, size / 8, size, size / 8, 2 * size);
}

void use_as_background(int field_tag) {
  gmsh::model::mesh::field::setAsBackgroundMesh(field_tag);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
}

// Elements of `fine` within `from` of the wall curves, growing by `growth` per unit distance beyond up to `size`: a gmsh
// Threshold on the distance to the wall (sampled at 1/8 of `fine`). Returns the field's tag.
int wall_distance_field(const std::vector<double>& curves, double extent, double fine, double from, double growth,
                        double size) {
  DistanceTo walls{{}, curves, {}, std::min(1e5, std::ceil(8 * extent / fine))};
  return distance_threshold(walls, fine, size, from, from + (size - fine) / std::max(growth, 1e-3));
}

// The background size: the smaller of the given fields (−1: none), or gmsh's own rules when there is none.
void use_smallest(int a, int b) {
  if (a >= 0 && b >= 0) {
    const int finer = gmsh::model::mesh::field::add("Min");
    gmsh::model::mesh::field::setNumbers(finer, "FieldsList", {static_cast<double>(a), static_cast<double>(b)});
    use_as_background(finer);
  } else if (a >= 0 || b >= 0) {
    use_as_background(std::max(a, b));
  }
}

void grade_towards_wall(const MeshOptions& options, double size, const std::string& where) {
  if (options.wall_size <= 0 || options.wall_size >= size) return;
  const double extent = model_extent();
  if (extent / options.wall_size > kMaxCellsPerExtent)
    throw std::runtime_error(where + ": wall mesh size " + number(options.wall_size) +
                             " is too small for a model of extent " + number(extent));
  std::vector<double> curves;
  for (int c : group_entities(1, physical_tag(1, "wall", where))) curves.push_back(c);
  namespace field = gmsh::model::mesh::field;
  const int contact = contact_line_field(size);
  if (options.wall_layer > 0) {
    if (wall_meets_axis_obliquely())  // viscous_mesh falls back to the grading
      throw std::runtime_error(where + ": gmsh's wall layers do not pass a point where the wall meets the axis "
                               "obliquely (an apex); the isotropic grading meshes it");
    const int layers = field::add("BoundaryLayer");
    field::setNumbers(layers, "EdgesList", curves);
    field::setNumber(layers, "hwall_n", options.wall_size);
    field::setNumber(layers, "ratio", 1 + options.wall_growth);
    field::setNumber(layers, "thickness", options.wall_layer);
    field::setNumber(layers, "hfar", size);
    field::setNumber(layers, "Quads", 0);
    // The layers end at a partially filled tank's contact lines. Left to continue through them, gmsh carried the
    // layer on along the free surface as slivers (triangles of quality 0.005 against 0.2 and more elsewhere), and the
    // forced flow there went wrong by far more than any resolution could explain: at Ek = 9e-7 the 60 %-full
    // sphere's Im R at the nutation was 45 times too large on the default mesh (docs/viscous.md, "Contact lines and
    // the wall layers").
    if (const std::vector<double> ends = contact_points(); !ends.empty()) field::setNumbers(layers, "PointsList", ends);
    field::setAsBoundaryLayer(layers);
    // The near-wall zone (MeshOptions::near_wall_size): from the layers' edge outwards.
    const bool near = options.near_wall_size > 0 && options.near_wall_size < size;
    use_smallest(near ? wall_distance_field(curves, extent, options.near_wall_size, options.wall_layer,
                                            options.near_wall_growth, size)
                      : -1,
                 contact);
    return;
  }
  use_smallest(wall_distance_field(curves, extent, options.wall_size, options.wall_size, options.wall_growth, size),
               contact);
}

// Distance from (r, z) to the segment (r0, z0)–(r1, z1).
double segment_distance(const std::array<double, 4>& s, double r, double z) {
  const double dr = s[2] - s[0], dz = s[3] - s[1], len2 = dr * dr + dz * dz;
  const double t = len2 > 0 ? std::clamp(((r - s[0]) * dr + (z - s[1]) * dz) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(r - s[0] - t * dr, z - s[1] - t * dz);
}

// The bands of MeshOptions as gmsh's size callback (the smaller of it and the fields' size rules): band_size within
// band_width of a segment, growing linearly with the distance beyond.
void refine_along_bands(const MeshOptions& options, double size) {
  if (options.bands.empty() || !(options.band_size > 0) || options.band_size >= size) return;
  const auto bands = options.bands;
  const double fine = options.band_size, width = options.band_width, growth = options.band_growth;
  gmsh::model::mesh::setSizeCallback([bands, fine, width, growth, size](int, int, double x, double y, double) {
    double d = 1e300;
    for (const auto& b : bands) d = std::min(d, segment_distance(b, x, y));
    return std::min(size, fine + growth * std::max(0.0, d - width));
  });
}

// `grading`: grade towards the wall with gmsh fields (none when the CAD model already holds the wall layers).
void generate(int order, double size, const std::string& where, double radial_size = 0,
              const MeshOptions* grading = nullptr) {
  if (model_extent() / size > kMaxCellsPerExtent || (radial_size > 0 && model_extent() / radial_size > kMaxCellsPerExtent))
    throw std::runtime_error(where + ": mesh size " + number(size) + " is too small for a model of extent " +
                             number(model_extent()));
  if (grading) grade_towards_wall(*grading, size, where);
  if (grading) refine_along_bands(*grading, size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  // The options rule, not the sizes a .geo file gives its points (docs/geometry.md): with gmsh's default the file's
  // `lc` caps the size, so that a coarser mesh asked for (the convergence check doubles the size) came out
  // identical and every cluster was flagged converged (measured: data/sections/capsule.geo, lc = 0.25, at
  // --mesh-size 0.25 against 0.5).
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::removeSizeCallback();
  // Only after the linear mesh exists: setOrder places the new edge nodes on the CAD curves
  // (exact arcs) by their parametrisation; interior nodes are interpolated.
  gmsh::model::mesh::setOrder(order);
}

// The tag of the physical group `name` of dimension `dim`, or -1 when there is none.
int find_physical_tag(int dim, const std::string& name) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim);
  for (const auto& [d, tag] : groups) {
    std::string n;
    gmsh::model::getPhysicalName(d, tag, n);
    if (n == name) return tag;
  }
  return -1;
}

int physical_tag(int dim, const std::string& name, const std::string& where) {
  const int tag = find_physical_tag(dim, name);
  if (tag >= 0) return tag;
  throw std::runtime_error(where + ": no " + std::to_string(dim) + "D physical group named '" + name +
                           "' (a section needs 2D \"fluid\", 1D \"wall\", and 1D \"axis\" where it touches r = 0)");
}

// The one element type of dimension `dim` over the entities of a physical group.
int single_element_type(int dim, const std::vector<int>& entities, const std::string& group,
                        const std::string& where) {
  std::vector<int> all;
  for (int e : entities) {
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, dim, e);
    all.insert(all.end(), types.begin(), types.end());
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  if (all.empty()) throw std::runtime_error(where + ": physical group '" + group + "' has no elements");
  if (all.size() > 1) throw std::runtime_error(where + ": physical group '" + group + "' mixes element types");
  return all.front();
}

std::vector<std::size_t> element_nodes(int type, const std::vector<int>& entities) {
  std::vector<std::size_t> nodes;
  for (int e : entities) {
    std::vector<std::size_t> tags, n;
    gmsh::model::mesh::getElementsByType(type, tags, n, e);
    nodes.insert(nodes.end(), n.begin(), n.end());
  }
  return nodes;
}

std::vector<int> group_entities(int dim, int tag) {
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
  return entities;
}

// Triangles of "fluid": one complete Lagrange order, returned with their local node coordinates.
void read_triangles(GmshMesh& m, const std::string& where) {
  const auto entities = group_entities(2, physical_tag(2, "fluid", where));
  const int type = single_element_type(2, entities, "fluid", where);
  std::string name;
  int dim = 0, order = 0, num_nodes = 0, num_primary = 0;
  std::vector<double> local;  // must be empty: gmsh 4.8 appends to it
  gmsh::model::mesh::getElementProperties(type, name, dim, order, num_nodes, local, num_primary);
  if (name.rfind("Triangle", 0) != 0 || order < 1 || order > kMaxOrder || num_nodes != nodes_per_triangle(order))
    throw std::runtime_error(where + ": 'fluid' elements are '" + name +
                             "', expected complete Lagrange triangles of order 1.." + std::to_string(kMaxOrder));
  m.order = order;
  m.local_nodes.clear();
  for (int a = 0; a < num_nodes; ++a) {
    m.local_nodes.push_back(local[2 * a]);
    m.local_nodes.push_back(local[2 * a + 1]);
  }
  m.triangles = element_nodes(type, entities);
  if (m.triangles.empty()) throw std::runtime_error(where + ": no triangles in physical group 'fluid'");
}

void read_wall_and_axis(GmshMesh& m, const std::string& where) {
  const auto wall = group_entities(1, physical_tag(1, "wall", where));
  const int type = single_element_type(1, wall, "wall", where);
  if (type != gmsh::model::mesh::getElementType("Line", m.order))
    throw std::runtime_error(where + ": 'wall' elements are not lines of the triangles' order " +
                             std::to_string(m.order));
  m.wall_edges = element_nodes(type, wall);
  // A partially filled tank's free surface (built-in shapes with a free_radius).
  if (const int free = find_physical_tag(1, "free"); free >= 0) {
    const auto entities = group_entities(1, free);
    if (single_element_type(1, entities, "free", where) != type)
      throw std::runtime_error(where + ": 'free' elements are not lines of the triangles' order");
    m.free_edges = element_nodes(type, entities);
  }
  // A ring-shaped section (annulus, torus) has no axis: its wall is its whole boundary (checked by add_axis).
  const int axis = find_physical_tag(1, "axis");
  if (axis < 0) return;
  std::vector<double> coord;
  gmsh::model::mesh::getNodesForPhysicalGroup(1, axis, m.axis_nodes, coord);
  if (m.axis_nodes.empty()) throw std::runtime_error(where + ": physical group 'axis' has no nodes");
}

GmshMesh read_mesh(const std::string& where) {
  GmshMesh m;
  read_triangles(m, where);
  read_wall_and_axis(m, where);
  std::vector<std::size_t> tags;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, false, false);
  for (std::size_t i = 0; i < tags.size(); ++i) m.coords[tags[i]] = {xyz[3 * i], xyz[3 * i + 1]};
  m.extent = std::max(1.0, model_extent());
  return m;
}

GmshMesh mesh_builtin(const ShapeSpec& shape, const MeshOptions& options) {
  const std::string where = shape.kind;
  return detail::with_gmsh(where, [&](detail::GmshSession& session) {
    const double size = options.size > 0 ? options.size : kDefaultSizeFraction * detail::smallest_dimension(shape);
    gmsh::model::add("meridian");
    const bool layered = detail::build_shape(shape, size, options.radial_size, &options);
    session.throw_if_error(where);
    generate(options.order, size, where, options.radial_size, layered ? nullptr : &options);
    session.throw_if_error(where);
    GmshMesh m = read_mesh(where);
    m.size = size;
    return m;
  });
}

// Longest straight side over all triangles: the "h" of a mesh we did not generate.
double longest_side(const GmshMesh& m) {
  const std::size_t npe = nodes_per_triangle(m.order);
  double h = 0;
  for (std::size_t t = 0; t < m.triangles.size(); t += npe)
    for (int i = 0; i < 3; ++i) {
      const auto& p = m.coords.at(m.triangles[t + i]);
      const auto& q = m.coords.at(m.triangles[t + (i + 1) % 3]);
      h = std::max(h, std::hypot(p[0] - q[0], p[1] - q[1]));
    }
  return h;
}

// Opens a section's file in gmsh and checks its groups; with a free_radius (--fill), the model becomes the liquid's
// part r >= free_radius (section_cut.hpp), its line the group 'free'.
void open_section(const ShapeSpec& shape, const std::string& where, detail::GmshSession& session) {
  const std::string ext = shape.file.extension().string();
  if (ext != ".geo" && ext != ".msh") throw std::runtime_error(where + ": expected a .geo or .msh file");
  // gmsh::open silently ignores a missing file, so check first.
  if (std::filesystem::is_directory(shape.file) || !std::ifstream(shape.file))
    throw std::runtime_error(where + ": cannot read the file");
  gmsh::open(shape.file.string());
  session.throw_if_error(where);
  for (const auto& [dim, name] : {std::pair{2, "fluid"}, {1, "wall"}}) physical_tag(dim, name, where);
  // A section's own free surface: the table's fill (against the cavity's volume) would be unknown, and the filled
  // solvers downstream would take it for a wall (its condition is natural); --fill cuts the section instead.
  detail::refuse_drawn_free_surface(where);
  if (!shape.dims.count("free_radius")) return;
  if (ext == ".msh")
    throw std::runtime_error(where + ": --fill cuts a section's geometry, which a .msh file does not hold (give its .geo)");
  detail::cut_section(shape.dims.at("free_radius"), where);
  session.throw_if_error(where);
}

GmshMesh mesh_section(const ShapeSpec& shape, const MeshOptions& options) {
  const std::string where = "section '" + shape.file.string() + "'";
  return detail::with_gmsh(where, [&](detail::GmshSession& session) {
    open_section(shape, where, session);
    if (shape.file.extension() == ".msh") {
      GmshMesh m = read_mesh(where);
      m.size = longest_side(m);
      return m;
    }
    const double size = options.size > 0 ? options.size : kDefaultSizeFraction * model_smallest_side();
    generate(options.order, size, where, 0, &options);
    session.throw_if_error(where);
    GmshMesh m = read_mesh(where);
    m.size = size;
    return m;
  });
}

// ---------------------------------------------------------------------------------------------
// Plain C++ side: compact numbering and checks.

// Nodes numbered 0.. in order of first use by the triangles (good locality for assembly).
MeridianMesh compact(const GmshMesh& g, std::unordered_map<std::size_t, int>& index, const std::string& where) {
  MeridianMesh m;
  m.order = g.order;
  m.nodes_per_element = nodes_per_triangle(g.order);
  m.size = g.size;
  const double tol = kAxisTolerance * g.extent;
  for (std::size_t tag : g.triangles) {
    auto [it, is_new] = index.try_emplace(tag, static_cast<int>(m.nodes.size()));
    if (is_new) {
      auto p = g.coords.at(tag);
      if (p[0] < -tol)
        throw std::runtime_error(where + ": node at r = " + number(p[0]) + ", z = " + number(p[1]) + " has r < 0");
      p[0] = std::max(p[0], 0.0);
      m.nodes.push_back(p);
    }
    m.triangles.push_back(it->second);
  }
  return m;
}

int mapped(const std::unordered_map<std::size_t, int>& index, std::size_t tag, const char* group,
           const std::string& where) {
  const auto it = index.find(tag);
  if (it == index.end())
    throw std::runtime_error(where + ": a node of '" + group + "' belongs to no 'fluid' triangle");
  return it->second;
}

// Axis nodes must lie on r = 0 up to rounding; they are snapped to exactly 0. Without an axis group (a ring-shaped
// section) no node may lie there: the m = 1 fields need the axis conditions wherever the section touches r = 0.
void add_axis(MeridianMesh& m, const GmshMesh& g, const std::unordered_map<std::size_t, int>& index,
              const std::string& where) {
  const double tol = kAxisTolerance * g.extent;
  if (g.axis_nodes.empty()) {
    for (const auto& node : m.nodes)
      if (node[0] <= tol)
        throw std::runtime_error(where + ": the section reaches r = 0 (a node at z = " + number(node[1]) +
                                 ") but has no 1D physical group named 'axis' there");
    return;
  }
  for (std::size_t tag : g.axis_nodes) {
    const int i = mapped(index, tag, "axis", where);
    if (std::abs(m.nodes[i][0]) > tol)
      throw std::runtime_error(where + ": 'axis' has a node at r = " + number(m.nodes[i][0]) + ", not on r = 0");
    m.nodes[i][0] = 0.0;
    m.axis_nodes.push_back(i);
  }
  std::sort(m.axis_nodes.begin(), m.axis_nodes.end());
  m.axis_nodes.erase(std::unique(m.axis_nodes.begin(), m.axis_nodes.end()), m.axis_nodes.end());
}

// Local node permutation of the reflection (u, v) -> (v, u), which swaps vertices 1 and 2 and so
// reverses the orientation while keeping gmsh's local order.
std::vector<int> flip_permutation(const std::vector<double>& local) {
  const int n = static_cast<int>(local.size() / 2);
  std::vector<int> perm(n, -1);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      if (std::abs(local[2 * b] - local[2 * a + 1]) < 1e-9 && std::abs(local[2 * b + 1] - local[2 * a]) < 1e-9)
        perm[a] = b;
  return perm;
}

double signed_area(const MeridianMesh& m, std::size_t t) {
  const int* v = &m.triangles[t * m.nodes_per_element];
  const auto &a = m.nodes[v[0]], &b = m.nodes[v[1]], &c = m.nodes[v[2]];
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
}

// gmsh orients triangles by the surface normal, which for a user section may point along -z.
void orient_triangles(MeridianMesh& m, const std::vector<double>& local) {
  const auto perm = flip_permutation(local);
  const int npe = m.nodes_per_element;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    if (signed_area(m, t) >= 0) continue;
    int* v = &m.triangles[t * npe];
    const std::vector<int> old(v, v + npe);
    for (int a = 0; a < npe; ++a) v[a] = old[perm[a]];
  }
}

// det(d(r,z)/d(u,v)) > 0 at every quadrature point of a rule finer than any FE use.
void check_jacobians(const MeridianMesh& m, const std::string& where) {
  const ReferenceTriangle ref = reference_triangle(m.order, 3 * m.order);
  const int npe = m.nodes_per_element;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const int* v = &m.triangles[t * npe];
    for (std::size_t q = 0; q < ref.weights.size(); ++q) {
      double j[2][2] = {{0, 0}, {0, 0}};
      for (int a = 0; a < npe; ++a)
        for (int c = 0; c < 2; ++c)
          for (int d = 0; d < 2; ++d) j[c][d] += m.nodes[v[a]][c] * ref.dN[(q * npe + a) * 2 + d];
      if (j[0][0] * j[1][1] - j[0][1] * j[1][0] <= 0)
        throw std::runtime_error(where + ": triangle " + std::to_string(t) + " near r = " +
                                 number(m.nodes[v[0]][0]) + ", z = " + number(m.nodes[v[0]][1]) +
                                 " is inverted (non-positive Jacobian); use a smaller mesh size or a lower order");
    }
  }
}

// Boundary edges (wall or free surface) run counter-clockwise around the fluid (fluid on the left), like the
// triangles' own edges; a reversed gmsh line [v0, v1, e1..e(p-1)] is [v1, v0, e(p-1)..e1].
std::vector<int> oriented_edges(const MeridianMesh& m, const GmshMesh& g, const std::vector<std::size_t>& raw,
                                const char* group, const std::unordered_map<std::size_t, int>& index,
                                const std::string& where) {
  std::map<std::pair<int, int>, bool> directed;  // vertex edges of the (counter-clockwise) triangles
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const int* v = &m.triangles[t * m.nodes_per_element];
    for (int i = 0; i < 3; ++i) directed[{v[i], v[(i + 1) % 3]}] = true;
  }
  const std::size_t npe = g.order + 1;
  std::vector<int> out;
  for (std::size_t e = 0; e < raw.size(); e += npe) {
    std::vector<int> edge;
    for (std::size_t a = 0; a < npe; ++a) edge.push_back(mapped(index, raw[e + a], group, where));
    if (!directed.count({edge[0], edge[1]})) {
      if (!directed.count({edge[1], edge[0]}))
        throw std::runtime_error(where + ": a '" + group + "' edge is not a side of a 'fluid' triangle");
      std::swap(edge[0], edge[1]);
      std::reverse(edge.begin() + 2, edge.end());
    }
    out.insert(out.end(), edge.begin(), edge.end());
  }
  return out;
}

// The free surface must be one coaxial cylinder r = b (docs/physics.md §2): its nodes are snapped to b.
void add_free_surface(MeridianMesh& m, const GmshMesh& g, const std::unordered_map<std::size_t, int>& index,
                      const std::string& where) {
  if (g.free_edges.empty()) return;
  m.free_edges = oriented_edges(m, g, g.free_edges, "free", index, where);
  double lo = m.nodes[m.free_edges.front()][0], hi = lo;
  for (int n : m.free_edges) lo = std::min(lo, m.nodes[n][0]), hi = std::max(hi, m.nodes[n][0]);
  if (hi - lo > 1e-9 * g.extent)
    throw std::runtime_error(where + ": the free surface 'free' is not one coaxial cylinder (r from " + number(lo) +
                             " to " + number(hi) + ")");
  m.free_radius = 0.5 * (lo + hi);
  for (int n : m.free_edges) m.nodes[n][0] = m.free_radius;
}

}  // namespace

void check_shape(const ShapeSpec& shape) { detail::validate_shape(shape); }

double smallest_dimension(const ShapeSpec& shape) {
  detail::validate_shape(shape);
  return shape.kind != "section" ? detail::smallest_dimension(shape) : default_mesh_size(shape) / kDefaultSizeFraction;
}

double default_mesh_size(const ShapeSpec& shape) {
  detail::validate_shape(shape);
  if (shape.kind != "section") return kDefaultSizeFraction * detail::smallest_dimension(shape);
  const std::string where = "section '" + shape.file.string() + "'";
  return detail::with_gmsh(where, [&](detail::GmshSession& session) {
    open_section(shape, where, session);
    return kDefaultSizeFraction * model_smallest_side();
  });
}

MeridianMesh mesh_meridian(const ShapeSpec& shape, const MeshOptions& options) {
  detail::validate_shape(shape);
  check_options(options);
  const bool section = shape.kind == "section";
  const std::string where = section ? "section '" + shape.file.string() + "'" : shape.kind;
  const GmshMesh g = section ? mesh_section(shape, options) : mesh_builtin(shape, options);
  std::unordered_map<std::size_t, int> index;  // gmsh node tag -> our node
  MeridianMesh m = compact(g, index, where);
  add_axis(m, g, index, where);
  orient_triangles(m, g.local_nodes);
  check_jacobians(m, where);
  m.wall_edges = oriented_edges(m, g, g.wall_edges, "wall", index, where);
  add_free_surface(m, g, index, where);
  return m;
}

}  // namespace rc::geometry
