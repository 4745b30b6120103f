// The wall of a 3-D cavity as Gauss points on its faces, each with the basis of the tetrahedron the face belongs to:
// surface integrals of the interior field's gradient, such as the Ekman layer's (boundary_layer_response.hpp). The
// faces on a partially filled tank's free surface (geometry/partial_volume.hpp) are not wall and are left out.
#pragma once

#include "volume_space.hpp"

#include <array>
#include <vector>

namespace rc::modes {

struct WallQuadraturePoint {
  std::array<double, 3> x{};       // position
  std::array<double, 3> normal{};  // unit normal into the liquid
  double w = 0;                    // Gauss weight × dS
  std::size_t element = 0;         // the tetrahedron (its dofs: VolumeSpace::element_dofs)
  std::vector<double> grad;        // its basis functions' physical gradients at x: grad[a * 3 + d]
};

// Gauss points exact to degree 2 · order + 2 on the reference triangle of every wall face. Throws std::runtime_error
// on a face whose tetrahedron is inverted at a point.
std::vector<WallQuadraturePoint> wall_quadrature(const VolumeSpace& space);

}  // namespace rc::modes
