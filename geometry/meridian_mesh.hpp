// Meridian half-sections (r >= 0) of axisymmetric cavities, meshed with the gmsh C++ API into
// high-order isoparametric Lagrange triangles. Coordinates: x = r (distance from the axis), y = z.
//
// Placement conventions (the solver measures everything from the fluid centroid afterwards):
//   sphere    radius R            centre at the origin
//   spheroid  a (equatorial), c (polar)  centre at the origin
//   cylinder  radius R, height H (full)  z in [-H/2, H/2]
//   cone      radius R, height H  apex at z = 0 pointing down, flat lid at z = H
//   section   a user .geo or .msh file with physical groups "fluid" (2D), "wall" (1D), "axis" (1D)
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rc::geometry {

struct ShapeSpec {
  std::string kind;                      // sphere | spheroid | cylinder | cone | section
  std::map<std::string, double> dims;    // sphere: radius; spheroid: a, c; cylinder, cone: radius, height
  std::filesystem::path file;            // section only
};

struct MeshOptions {
  int order = 3;        // Lagrange order of the triangles (geometry and field), 1..6
  double size = 0.0;    // target element size in the shape's length unit; 0 = default (see docs)
  double radial_size = 0.0;  // cylinder only: > 0 makes a structured mesh with this element size along r
                             // and `size` along z (docs/geometry.md, "Structured cylinder meshes")
  // Meshes for viscous boundary layers (docs/geometry.md, "Wall-refined meshes"). wall_size > 0 refines towards
  // the wall in one of two ways:
  //   wall_layer > 0: anisotropic layers (gmsh BoundaryLayer field): the first layer wall_size thick, each next
  //                   one (1 + wall_growth) times thicker, up to wall_layer from the wall; along the wall the
  //                   elements keep `size`;
  //   wall_layer = 0: isotropic grading: elements of size wall_size at the wall, growing by wall_growth per
  //                   unit distance up to `size`.
  double wall_size = 0.0;
  double wall_growth = 0.25;
  double wall_layer = 0.0;
  // With the anisotropic layers: isotropic elements of near_wall_size from the layers' edge outwards, growing by
  // near_wall_growth per unit distance up to `size` (0 = none: the interior size right beyond the layers). The viscous
  // flow just outside the Ekman layers needs them at Ek ≤ 1e-5 (docs/viscous.md, "Near-wall zone").
  double near_wall_size = 0.0;
  double near_wall_growth = 1.0;
  // Refinement along segments of the meridian half-plane, each (r0, z0, r1, z1): elements of band_size within
  // band_width of a segment, growing by band_growth per unit distance beyond it up to `size` (the internal shear
  // layers of a viscous mode: modes/viscous/shear_layers.hpp). None when empty.
  std::vector<std::array<double, 4>> bands = {};
  double band_size = 0.0, band_width = 0.0, band_growth = 0.25;
};

struct MeridianMesh {
  int order = 0;                                // Lagrange order of every triangle
  int nodes_per_element = 0;                    // (order+1)(order+2)/2
  std::vector<std::array<double, 2>> nodes;     // (r, z) of every node, 0-based
  std::vector<int> triangles;                   // nodes_per_element node indices per triangle, gmsh local order
  std::vector<int> axis_nodes;                  // nodes on r = 0 (sorted, unique)
  std::vector<int> wall_edges;                  // (order+1) node indices per wall edge, gmsh local order
  std::vector<int> free_edges;                  // the same for the free surface r = free_radius (partial fill)
  double free_radius = 0.0;                     // > 0 only with free edges
  double size = 0.0;                            // element size actually requested
  std::size_t num_triangles() const { return triangles.size() / nodes_per_element; }
};

// Builds, meshes and returns the meridian half-section. Throws std::runtime_error with a one-line cause
// on bad input: unknown kind, a missing, zero, negative or non-finite dimension, an unreadable file, a
// section without the three physical groups, with nodes at r < 0, or with no triangles.
MeridianMesh mesh_meridian(const ShapeSpec& shape, const MeshOptions& options);

// The shape checks of mesh_meridian alone (kind and dimensions), for solvers that need no mesh.
void check_shape(const ShapeSpec& shape);

// The element size mesh_meridian takes when MeshOptions::size is 0 (docs/geometry.md, "Mesh options and
// defaults"): 1/8 of a built-in shape's smallest dimension, or of the smallest side of a section's bounding box (the
// file is opened for it). Throws what mesh_meridian throws for an unreadable shape.
double default_mesh_size(const ShapeSpec& shape);

// The liquid's smallest dimension, the length the mesh defaults scale with: a built-in shape's (a partially filled
// tank's is the layer outside its free surface, a rod's the gap around it), a section's the smallest side of its
// bounding box (the file is opened for it).
double smallest_dimension(const ShapeSpec& shape);

// The reference triangle of a given order with a Gauss rule exact to `degree`: basis values and
// gradients at the quadrature points, in the same local node order as MeridianMesh::triangles.
struct ReferenceTriangle {
  int order = 0;
  int nodes_per_element = 0;
  std::vector<std::array<double, 2>> points;   // (u, v) on the reference triangle (0,0),(1,0),(0,1)
  std::vector<double> weights;                 // sum of weights = 1/2 (reference area)
  std::vector<double> N;                       // N[q * nodes_per_element + a]
  std::vector<double> dN;                      // dN[(q * nodes_per_element + a) * 2 + d], d = du, dv
};
ReferenceTriangle reference_triangle(int order, int quadrature_degree);

// The Lagrange basis of `order` (gmsh's local node order) at given reference points: N[i * nodes_per_element + a].
// E.g. a pressure of order k − 1 evaluated at the nodes of order k.
std::vector<double> triangle_basis_at(int order, const std::vector<std::array<double, 2>>& points);

// The same for a reference edge [0, 1] of the wall (for boundary integrals).
struct ReferenceEdge {
  int order = 0;
  std::vector<double> points, weights;   // on [0, 1], weights sum to 1
  std::vector<double> N, dN;             // N[q * (order+1) + a], dN likewise (d/ds)
};
ReferenceEdge reference_edge(int order, int quadrature_degree);

}  // namespace rc::geometry
