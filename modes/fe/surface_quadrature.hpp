// Gauss points along a partially filled tank's free surface r = b (MeridianMesh::free_edges), shared by the ideal
// surface forms (freesurface/free_surface_forms.*) and the viscous ones (viscous/viscous_forms.*).
#pragma once

#include "meridian_mesh.hpp"

#include <vector>

namespace rc::modes {

struct FreeSurfacePoint {
  double z = 0;                  // height of the point
  double w = 0;                  // quadrature weight of dz (the surface is the line r = b)
  const int* nodes = nullptr;    // the edge's order + 1 mesh nodes
  const double* N = nullptr;     // the edge's basis at the point (into the ReferenceEdge given)
};

// Every Gauss point of `edge`'s rule on every free edge; `edge` must outlive the points (they point into it).
std::vector<FreeSurfacePoint> free_surface_points(const geometry::MeridianMesh& mesh, const geometry::ReferenceEdge& edge);

}  // namespace rc::modes
