// Three-dimensional cavities (no axial symmetry), meshed with the gmsh C++ API into high-order isoparametric
// Lagrange tetrahedra. The spin axis is z. Coordinates are the shape's own; the solver measures every lever arm
// from the fluid's centroid afterwards.
//
//   ellipsoid  semi-axes a (x), b (y), c (z)      centre at the origin
//   volume     a user .geo/.msh file with a 3-D physical group "fluid", or a CAD .step/.stp/.brep file whose
//              every volume is fluid (gmsh's OpenCASCADE kernel)
// tilt rotates the ellipsoid's own axis about x by that angle (radians) against the spin axis z; a file's cavity is
// turned the same way about the file's origin.
#pragma once

#include "linear_tet_counts.hpp"
#include "meridian_mesh.hpp"

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rc::geometry {

struct VolumeShapeSpec {
  std::string kind;                    // ellipsoid | volume
  std::map<std::string, double> dims;  // ellipsoid: a, b, c
  std::filesystem::path file;          // volume only
  double tilt = 0.0;                   // radians, about x
  // A partially filled tank (ellipsoid only): the liquid fills this fraction of the cavity, pressed outwards by a
  // rapid spin about an axis parallel to z through (spin_axis[0], spin_axis[1]) — the craft's axis, which need not
  // cross the tank. Its free surface is the cylinder about that axis (geometry/partial_volume.hpp).
  double fill = 1.0;
  std::array<double, 2> spin_axis{};
};

struct VolumeMesh {
  int order = 0;                             // Lagrange order of every tetrahedron
  int nodes_per_element = 0;                 // (p+1)(p+2)(p+3)/6
  std::vector<std::array<double, 3>> nodes;  // (x, y, z) of every node, 0-based
  std::vector<int> tetrahedra;               // nodes_per_element node indices per tetrahedron, gmsh local order
  double size = 0.0;                         // element size requested
  // A partially filled tank's free surface: the cylinder of this radius about the spin axis through spin_axis
  // (parallel to z); 0 when the cavity is full.
  double free_surface_radius = 0.0;
  std::array<double, 2> spin_axis{};
  double free_surface_area = 0.0;  // OpenCASCADE's area of the free surface's faces (0: unknown), the mesh's check
  std::size_t num_tetrahedra() const { return tetrahedra.size() / nodes_per_element; }
};

// Builds, meshes and returns the cavity. Throws std::runtime_error with a one-line cause on bad input (unknown kind,
// a missing or non-positive dimension, an unreadable file, no 3-D "fluid", an inverted element).
// options.order 1..6, options.size 0 = 0.4 of the smallest dimension (semi-axis; a file's
// smallest half-side of its bounding box), options.wall_size > 0 grades the size towards the wall, or with
// options.wall_layer > 0 is the first of the anisotropic wall layers (volume_wall_layers.hpp).
// `check`, if given, sees the linear mesh's counts before the high-order nodes are placed (not on a read .msh file or
// with wall layers) and may throw to refuse it.
VolumeMesh mesh_volume(const VolumeShapeSpec& shape, const MeshOptions& options, const LinearMeshCheck& check = {});

// The checks of mesh_volume on the shape alone.
void check_volume_shape(const VolumeShapeSpec& shape);

// The cavity's wall in a mesh: every face that one tetrahedron alone has, as (tetrahedron, its local vertex opposite
// the face).
std::vector<std::pair<std::size_t, int>> wall_faces(const VolumeMesh& m);

// The reference tetrahedron (0,0,0),(1,0,0),(0,1,0),(0,0,1) of a given order with a Gauss rule exact to `degree`,
// in the local node order of VolumeMesh::tetrahedra.
struct ReferenceTetrahedron {
  int order = 0;
  int nodes_per_element = 0;
  std::vector<std::array<double, 3>> points;  // (u, v, w)
  std::vector<double> weights;                // sum = 1/6
  std::vector<double> N;                      // N[q * nodes_per_element + a]
  std::vector<double> dN;                     // dN[(q * nodes_per_element + a) * 3 + d]
};
ReferenceTetrahedron reference_tetrahedron(int order, int quadrature_degree);

// The Lagrange basis of `order` on the reference tetrahedron at given points (u, v, w), in the local node order of
// VolumeMesh::tetrahedra: N[i * nodes_per_element + a] and dN[(i * nodes_per_element + a) * 3 + d] (d/du, d/dv, d/dw).
// For integrals over a tetrahedron's face with its volume basis (the wall's boundary layer, wall_quadrature.hpp).
struct TetrahedronBasis {
  std::vector<double> N, dN;
};
TetrahedronBasis tetrahedron_basis_at(int order, const std::vector<std::array<double, 3>>& points);

}  // namespace rc::geometry
