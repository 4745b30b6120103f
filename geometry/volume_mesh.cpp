// mesh_volume: build (OpenCASCADE kernel) or read the 3-D cavity, mesh it into high-order tetrahedra, and turn
// gmsh's tagged data into the compact, checked VolumeMesh the 3-D solver consumes.
#include "volume_mesh.hpp"

#include "gmsh_session.hpp"
#include "partial_volume.hpp"
#include "size_fields.hpp"
#include "volume_wall_layers.hpp"

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

namespace occ = gmsh::model::occ;

constexpr int kMaxOrder = 6;
constexpr double kDefaultSizeFraction = 0.4;  // default size = this × smallest dimension (or half-side of a file)
constexpr double kMaxCellsPerExtent = 400;      // finer would mean > ~1e8 tetrahedra

std::string number(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

const std::map<std::string, std::vector<std::string>>& required_dims() {
  static const std::map<std::string, std::vector<std::string>> dims = {
      {"ellipsoid", {"a", "b", "c"}}, {"volume", {}}};
  return dims;
}

double smallest_dimension(const VolumeShapeSpec& shape) {
  double d = INFINITY;
  for (const auto& [name, v] : shape.dims) d = std::min(d, v);
  return d;
}

// gmsh::model::getBoundingBox over the whole model.
double model_extent() {
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  return std::max({x1 - x0, y1 - y0, z1 - z0});
}

double model_smallest_side() {
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  return std::min({x1 - x0, y1 - y0, z1 - z0}) / 2;
}

void check_options(const MeshOptions& options) {
  if (options.order < 1 || options.order > kMaxOrder)
    throw std::runtime_error("3-D mesh order " + std::to_string(options.order) + " is outside 1.." +
                             std::to_string(kMaxOrder));
  if (!std::isfinite(options.size) || options.size < 0)
    throw std::runtime_error("mesh size " + number(options.size) + " must be positive and finite (0 = default)");
  if (!std::isfinite(options.wall_size) || options.wall_size < 0)
    throw std::runtime_error("wall mesh size " + number(options.wall_size) + " must be positive and finite (0 = none)");
  if (!std::isfinite(options.wall_growth) || options.wall_growth <= 0 || options.wall_growth > 10)
    throw std::runtime_error("wall size growth " + number(options.wall_growth) + " must be in (0, 10]");
  if (!std::isfinite(options.wall_layer) || options.wall_layer < 0)
    throw std::runtime_error("wall layer thickness " + number(options.wall_layer) + " must be positive and finite (0 = none)");
  if (options.wall_layer > 0 && !(options.wall_size > 0 && options.wall_size <= options.wall_layer))
    throw std::runtime_error("wall layers need a first layer (--wall-size) in (0, " + number(options.wall_layer) + "]");
  if (!std::isfinite(options.near_wall_size) || options.near_wall_size < 0)
    throw std::runtime_error("near-wall size " + number(options.near_wall_size) + " must be positive and finite (0 = none)");
  if (options.near_wall_size > 0 && !(options.wall_layer > 0))
    throw std::runtime_error("a near-wall size (--near-wall-size) goes with wall layers (--wall-layer)");
}

// The spheroid x² + y² over a², z² over c² ≤ 1 as the revolution of its half-ellipse about z (a sphere: addSphere).
// gmsh's ellipse takes its major radius first, so an oblate one (a > c) is drawn with its axis along y and revolved
// about it, a prolate one with its axis along x; either is then turned so that its axis is z.
int revolved_spheroid(double a, double c) {
  if (a == c) return occ::addSphere(0, 0, 0, a);
  const bool oblate = a > c;
  const int arc = oblate ? occ::addEllipse(0, 0, 0, a, c, -1, -M_PI / 2, M_PI / 2)  // x >= 0, the axis y
                         : occ::addEllipse(0, 0, 0, c, a, -1, 0, M_PI);           // y >= 0, the axis x
  const int axis = oblate ? occ::addLine(occ::addPoint(0, c, 0), occ::addPoint(0, -c, 0))
                          : occ::addLine(occ::addPoint(-c, 0, 0), occ::addPoint(c, 0, 0));
  const int face = occ::addPlaneSurface({occ::addCurveLoop({arc, axis})});
  gmsh::vectorpair out;
  occ::revolve({{2, face}}, 0, 0, 0, oblate ? 0 : 1, oblate ? 1 : 0, 0, 2 * M_PI, out);
  for (const auto& [dim, tag] : out)
    if (dim == 3) {
      if (oblate)
        occ::rotate({{3, tag}}, 0, 0, 0, 1, 0, 0, M_PI / 2);   // y → z
      else
        occ::rotate({{3, tag}}, 0, 0, 0, 0, 1, 0, -M_PI / 2);  // x → z
      return tag;
    }
  throw std::runtime_error("the spheroid's revolution made no volume");
}

// The fluid volume of a built-in shape, with its own axis along z, then tilted about x, then (partially filled) cut
// to its liquid; returns the free surface's radius (0 when full).
double build_shape(const VolumeShapeSpec& shape) {
  const auto& d = shape.dims;
  const bool round = d.at("a") == d.at("b");
  // A partially filled spheroid is revolved from its half-ellipse: an exact surface, whose volume OpenCASCADE gives to
  // rounding, so that the fill is exact (a scaled sphere is a B-spline whose volume it gives to ~4e-4, measured
  // 2026-12-02 on c/a = 0.8). The full ellipsoid keeps the scaled sphere its tables were measured on.
  int tag = shape.fill < 1 && round ? revolved_spheroid(d.at("a"), d.at("c")) : occ::addSphere(0, 0, 0, 1);
  if (!(shape.fill < 1 && round)) occ::dilate({{3, tag}}, 0, 0, 0, d.at("a"), d.at("b"), d.at("c"));
  if (shape.tilt != 0) occ::rotate({{3, tag}}, 0, 0, 0, 1, 0, 0, shape.tilt);
  double radius = 0;
  if (shape.fill < 1) {
    occ::synchronize();
    const LiquidCut cut = cut_to_fill(tag, shape.fill, shape.spin_axis);
    tag = cut.tag;
    radius = cut.radius;
  }
  occ::synchronize();
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {tag}), "fluid");
  return radius;
}

// A user's file: .geo/.msh with a 3-D group "fluid", or CAD whose every volume is fluid.
void open_volume(const VolumeShapeSpec& shape, const std::string& where, detail::GmshSession& session) {
  const std::string ext = shape.file.extension().string();
  const bool cad = ext == ".step" || ext == ".stp" || ext == ".brep";
  if (!cad && ext != ".geo" && ext != ".msh")
    throw std::runtime_error(where + ": expected a .geo, .msh, .step, .stp or .brep file");
  if (std::filesystem::is_directory(shape.file) || !std::ifstream(shape.file))
    throw std::runtime_error(where + ": cannot read the file");
  if (cad) {
    std::vector<std::pair<int, int>> volumes;
    occ::importShapes(shape.file.string(), volumes);
    occ::synchronize();
    std::vector<int> tags;
    for (const auto& [dim, tag] : volumes)
      if (dim == 3) tags.push_back(tag);
    if (tags.empty()) throw std::runtime_error(where + ": the file holds no volume");
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, tags), "fluid");
  } else {
    gmsh::open(shape.file.string());
  }
  session.throw_if_error(where);
}

int fluid_group(const std::string& where) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 3);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (name == "fluid") return tag;
  }
  throw std::runtime_error(where + ": no 3D physical group named 'fluid'");
}

// Isotropic grading towards the wall (MeshOptions::wall_size, wall_growth): elements of wall_size on the wall
// surfaces, growing by wall_growth per unit distance up to `size`. The geometry error of isoparametric elements
// lives on the wall, so this buys accuracy at the cost of surface, not volume, elements. Returns the size field, or −1.
// A partially filled tank (`filled` false) has no wall layers yet: its refusal names the lowest Ekman number its
// default wall size 2 Ek^(1/2) reaches and what takes a lower one.
int grade_towards_wall(const MeshOptions& options, double size, const std::string& where, bool filled) {
  if (options.wall_size <= 0 || options.wall_size >= size) return -1;
  const double smallest = model_extent() / kMaxCellsPerExtent;
  if (options.wall_size < smallest) {
    const std::string head = where + ": wall mesh size " + number(options.wall_size) + " is too small for isotropic "
                             "grading (at least the model's extent / " + number(kMaxCellsPerExtent) + " = " +
                             number(smallest) + ")";
    if (filled)
      throw std::runtime_error(head + "; thinner walls take anisotropic layers (--wall-layer with --wall-size, "
                                      "docs/volume.md §7)");
    throw std::runtime_error(head + "; a partially filled tank has no wall layers yet, so its mesh grades down to "
                             "Ek = " + number(0.25 * smallest * smallest) + " at most here (--ekman's wall size is "
                             "2 Ek^(1/2); the memory may stop it sooner); "
                             "a lower Ek takes the ideal table (without --ekman) or, on the spin axis, the "
                             "axisymmetric fill (cavity-modes response SHAPE --fill F --ekman Ek; docs/volume.md §8)");
  }
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  DistanceTo walls;
  for (const auto& [dim, tag] : surfaces) walls.surfaces.push_back(tag);
  return distance_threshold(walls, options.wall_size, size, 0,
                            (size - options.wall_size) / std::max(options.wall_growth, 1e-3));
}

// True when the CAD surface `tag` is a piece of the free surface ρ = b (its parametric middle lies on the cylinder).
bool is_free_surface_entity(int tag, double radius, const std::array<double, 2>& axis) {
  std::vector<double> lo, hi, xyz;
  gmsh::model::getParametrizationBounds(2, tag, lo, hi);
  gmsh::model::getValue(2, tag, {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])}, xyz);
  return on_free_surface({xyz[0], xyz[1], xyz[2]}, radius, axis);
}

// A partially filled tank's free surface as OpenCASCADE has it: the area of its faces on the cylinder ρ = b (the mesh's
// faces found there must cover it: modes/volume/volume_free_surface.cpp).
double free_surface_cad_area(double radius, const std::array<double, 2>& axis) {
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  double area = 0;
  for (const auto& [dim, tag] : surfaces) {
    if (!is_free_surface_entity(tag, radius, axis)) continue;
    double mass = 0;
    gmsh::model::occ::getMass(2, tag, mass);
    area += mass;
  }
  return area;
}

// A partially filled tank's contact lines: the curves where its free surface ρ = b meets the wall (those that bound
// both a surface on the cylinder and one off it, not the cylinder's seam).
std::vector<double> contact_curves(double radius, const std::array<double, 2>& axis) {
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::map<int, int> on_free, on_wall;  // curve -> how many free / wall surfaces it bounds
  for (const auto& [dim, tag] : surfaces) {
    const bool free = is_free_surface_entity(tag, radius, axis);
    gmsh::vectorpair boundary;
    gmsh::model::getBoundary({{2, tag}}, boundary, false, false, false);
    for (const auto& [d, c] : boundary) ++(free ? on_free : on_wall)[std::abs(c)];
  }
  std::vector<double> out;
  for (const auto& [curve, count] : on_free)
    if (on_wall.count(curve)) out.push_back(curve);
  return out;
}

// Where no-slip meets the stress-free surface the viscous flow is singular, and a response converges slowly with the
// interior size (docs/volume.md §8; the meridian solver refines towards its contact points the same way,
// meridian_mesh.cpp): size/8 within size/8 of the contact lines, growing to `size` at 2 size. Returns the field, or −1.
int refine_contact_lines(double size, double radius, const std::array<double, 2>& axis) {
  DistanceTo lines;
  lines.curves = contact_curves(radius, axis);
  if (lines.curves.empty()) return -1;
  lines.points_per_curve = 400;  // sampled finely: the distance is accurate near them
  return distance_threshold(lines, size / 8, size, size / 8, 2 * size);
}

// The background size: the smallest of the fields given (none: the uniform `size`).
void use_smallest(const std::vector<int>& fields) {
  namespace field = gmsh::model::mesh::field;
  if (fields.empty()) return;
  if (fields.size() == 1) {
    field::setAsBackgroundMesh(fields.front());
    return;
  }
  const int smallest = field::add("Min");
  field::setNumbers(smallest, "FieldsList", std::vector<double>(fields.begin(), fields.end()));
  field::setAsBackgroundMesh(smallest);
}

// The linear mesh of the 'fluid' group, counted (linear_tet_counts.hpp).
LinearTetCounts count_fluid_tets(const std::string& where) {
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(3, fluid_group(where), entities);
  std::vector<std::array<std::size_t, 4>> tets;
  for (int e : entities) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(4, tags, nodes, e);  // 4: gmsh's linear tetrahedron
    for (std::size_t i = 0; i + 3 < nodes.size(); i += 4) tets.push_back({nodes[i], nodes[i + 1], nodes[i + 2], nodes[i + 3]});
  }
  return count_linear_tets(tets);
}

// A viscous mesh of a partially filled tank (wall_size > 0 and a free surface of `surface_radius` about `axis`) is
// refined towards its contact lines too.
void generate(detail::GmshSession& session, int order, double size, const std::string& where,
              const MeshOptions& options, const LinearMeshCheck& check, double surface_radius = 0,
              const std::array<double, 2>& axis = {}) {
  if (model_extent() / size > kMaxCellsPerExtent)
    throw std::runtime_error(where + ": mesh size " + number(size) + " is too small for a model of extent " +
                             number(model_extent()));
  std::vector<int> fields;
  if (const int wall = grade_towards_wall(options, size, where, !(surface_radius > 0)); wall >= 0)
    fields.push_back(wall);
  if (surface_radius > 0 && options.wall_size > 0)
    if (const int contact = refine_contact_lines(size, surface_radius, axis); contact >= 0) fields.push_back(contact);
  use_smallest(fields);
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::model::mesh::generate(3);
  session.throw_if_error(where);
  if (check) check(count_fluid_tets(where));
  // After the linear mesh: setOrder puts the new boundary nodes on the CAD surfaces. A coarse mesh's curved
  // elements can fold where a boundary face bends into a thin element; gmsh's high-order optimiser (elastic
  // analogy, then untangling; boundary nodes stay on the surfaces) unfolds them. It logs an error when some element's
  // quality stays below its target ("failed to reach critical value ... ScaledJac": a half-full sphere off the axis
  // at P4 h 0.45, 2026-12-07), yet what it leaves is often valid: check_jacobians judges the mesh itself.
  gmsh::model::mesh::setOrder(order);
  session.throw_if_error(where);
  if (order > 1) {
    gmsh::model::mesh::optimize("HighOrder");
    session.forgive_logged();
  }
}

struct GmshTets {
  int order = 0;
  std::vector<std::size_t> tets;
  std::unordered_map<std::size_t, std::array<double, 3>> coords;
};

GmshTets read_tets(const std::string& where) {
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(3, fluid_group(where), entities);
  GmshTets g;
  int type = -1;
  for (int e : entities) {
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, 3, e);
    for (int t : types) {
      std::string name;
      int dim = 0, order = 0, num_nodes = 0, num_primary = 0;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(t, name, dim, order, num_nodes, local, num_primary);
      if (name.rfind("Tetrahedron", 0) != 0 || order < 1 || order > kMaxOrder ||
          num_nodes != (order + 1) * (order + 2) * (order + 3) / 6 || (type >= 0 && t != type))
        throw std::runtime_error(where + ": 'fluid' elements are '" + name +
                                 "', expected complete Lagrange tetrahedra of one order 1.." + std::to_string(kMaxOrder));
      type = t;
      g.order = order;
    }
    std::vector<std::size_t> tags, nodes;
    if (type >= 0) gmsh::model::mesh::getElementsByType(type, tags, nodes, e);
    g.tets.insert(g.tets.end(), nodes.begin(), nodes.end());
  }
  if (g.tets.empty()) throw std::runtime_error(where + ": no tetrahedra in physical group 'fluid'");
  std::vector<std::size_t> tags;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, false, false);
  for (std::size_t i = 0; i < tags.size(); ++i) g.coords[tags[i]] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  return g;
}

GmshTets mesh_in_gmsh(const VolumeShapeSpec& shape, const MeshOptions& options, const std::string& where,
                      double& size, double& surface_radius, double& surface_area, const LinearMeshCheck& check) {
  return detail::with_gmsh(where, [&](detail::GmshSession& session) {
    gmsh::model::add("volume");
    if (shape.kind == "volume")
      open_volume(shape, where, session);
    else
      surface_radius = build_shape(shape);
    session.throw_if_error(where);
    if (surface_radius > 0) surface_area = free_surface_cad_area(surface_radius, shape.spin_axis);
    if (shape.kind == "volume" && shape.file.extension() == ".msh") {
      size = 0;
      return read_tets(where);
    }
    size = options.size > 0 ? options.size
                            : kDefaultSizeFraction * (shape.kind == "volume" ? model_smallest_side()
                                                                              : smallest_dimension(shape));
    generate(session, options.order, size, where, options, check, surface_radius, shape.spin_axis);
    session.throw_if_error(where);
    return read_tets(where);
  });
}

// det(d(x,y,z)/d(u,v,w)) > 0 at every point of a rule finer than any FE use.
void check_jacobians(const VolumeMesh& m, const std::string& where) {
  const ReferenceTetrahedron ref = reference_tetrahedron(m.order, 2 * m.order);
  const int npe = m.nodes_per_element;
  for (std::size_t t = 0; t < m.num_tetrahedra(); ++t) {
    const int* v = &m.tetrahedra[t * npe];
    for (std::size_t q = 0; q < ref.weights.size(); ++q) {
      double j[3][3] = {};
      for (int a = 0; a < npe; ++a)
        for (int c = 0; c < 3; ++c)
          for (int d = 0; d < 3; ++d) j[c][d] += m.nodes[v[a]][c] * ref.dN[(q * npe + a) * 3 + d];
      const double det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
                         j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                         j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
      if (!(det > 0))
        throw std::runtime_error(where + ": tetrahedron " + std::to_string(t) + " near (" + number(m.nodes[v[0]][0]) +
                                 ", " + number(m.nodes[v[0]][1]) + ", " + number(m.nodes[v[0]][2]) +
                                 ") is inverted; use a smaller mesh size or a lower order");
    }
  }
}

}  // namespace

void check_volume_shape(const VolumeShapeSpec& shape) {
  const auto it = required_dims().find(shape.kind);
  if (it == required_dims().end())
    throw std::runtime_error("unknown 3-D shape '" + shape.kind + "' (expected ellipsoid or volume)");
  for (const auto& name : it->second) {
    const auto d = shape.dims.find(name);
    if (d == shape.dims.end()) throw std::runtime_error(shape.kind + ": missing dimension '" + name + "'");
    if (!std::isfinite(d->second) || d->second <= 0)
      throw std::runtime_error(shape.kind + ": dimension '" + name + "' = " + number(d->second) +
                               " must be positive and finite");
  }
  if (!std::isfinite(shape.tilt)) throw std::runtime_error(shape.kind + ": the tilt must be finite");
  if (!(shape.fill > 0 && shape.fill <= 1))
    throw std::runtime_error(shape.kind + ": the fill " + number(shape.fill) + " must lie in (0, 1]");
  if (shape.fill < 1 && shape.kind != "ellipsoid")
    throw std::runtime_error(shape.kind + ": a partial fill in 3-D is built for the ellipsoid (and the sphere) only; "
                             "a file's cavity is taken full, or axisymmetric sections with --fill (docs/volume.md §8)");
  if (!std::isfinite(shape.spin_axis[0]) || !std::isfinite(shape.spin_axis[1]))
    throw std::runtime_error(shape.kind + ": the spin axis's position must be finite");
}

std::vector<std::pair<std::size_t, int>> wall_faces(const VolumeMesh& m) {
  const int npe = m.nodes_per_element;
  const auto face = [&](std::size_t e, int opposite) {
    std::array<int, 3> f{};
    for (int v = 0, i = 0; v < 4; ++v)
      if (v != opposite) f[i++] = m.tetrahedra[e * npe + v];
    std::sort(f.begin(), f.end());
    return f;
  };
  std::map<std::array<int, 3>, int> count;
  for (std::size_t e = 0; e < m.num_tetrahedra(); ++e)
    for (int o = 0; o < 4; ++o) ++count[face(e, o)];
  std::vector<std::pair<std::size_t, int>> wall;
  for (std::size_t e = 0; e < m.num_tetrahedra(); ++e)
    for (int o = 0; o < 4; ++o)
      if (count[face(e, o)] == 1) wall.emplace_back(e, o);
  return wall;
}

namespace {

// A file's cavity turned about x by `tilt` (the built-in shapes are turned before meshing): every node, the curved
// wall's high-order ones included, by the same rotation, so the isoparametric mesh is the turned one exactly.
void tilt_file_mesh(const VolumeShapeSpec& shape, VolumeMesh& m) {
  if (shape.kind != "volume" || shape.tilt == 0) return;
  const double c = std::cos(shape.tilt), s = std::sin(shape.tilt);
  for (auto& x : m.nodes) {
    const double y = x[1], z = x[2];
    x[1] = c * y - s * z;
    x[2] = s * y + c * z;
  }
}

}  // namespace

VolumeMesh mesh_volume(const VolumeShapeSpec& shape, const MeshOptions& options, const LinearMeshCheck& check) {
  check_volume_shape(shape);
  check_options(options);
  const std::string where = shape.kind == "volume" ? "volume '" + shape.file.string() + "'" : shape.kind;
  if (options.wall_layer > 0) {
    if (shape.fill < 1)
      throw std::runtime_error(where + ": wall layers on a partially filled 3-D tank are not built yet; the ideal "
                               "liquid's modes are (docs/volume.md §8)");
    VolumeMesh layered =
        shape.kind == "ellipsoid" ? layered_ellipsoid(shape, options) : layered_volume_file(shape, options);
    check_jacobians(layered, where);
    tilt_file_mesh(shape, layered);
    return layered;
  }
  double size = 0, surface_radius = 0, surface_area = 0;
  const GmshTets g = mesh_in_gmsh(shape, options, where, size, surface_radius, surface_area, check);
  VolumeMesh m;
  m.free_surface_radius = surface_radius;
  m.free_surface_area = surface_area;
  m.spin_axis = shape.spin_axis;
  m.order = g.order;
  m.nodes_per_element = (g.order + 1) * (g.order + 2) * (g.order + 3) / 6;
  m.size = size;
  std::unordered_map<std::size_t, int> index;  // nodes numbered in order of first use (assembly locality)
  for (std::size_t tag : g.tets) {
    auto [it, is_new] = index.try_emplace(tag, static_cast<int>(m.nodes.size()));
    if (is_new) m.nodes.push_back(g.coords.at(tag));
    m.tetrahedra.push_back(it->second);
  }
  check_jacobians(m, where);
  tilt_file_mesh(shape, m);
  return m;
}

}  // namespace rc::geometry
