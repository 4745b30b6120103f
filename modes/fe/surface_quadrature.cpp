#include "surface_quadrature.hpp"

#include <cmath>

namespace rc::modes {

std::vector<FreeSurfacePoint> free_surface_points(const geometry::MeridianMesh& mesh, const geometry::ReferenceEdge& edge) {
  const int nn = mesh.order + 1;
  std::vector<FreeSurfacePoint> out;
  for (std::size_t e = 0; e < mesh.free_edges.size(); e += nn) {
    const int* v = &mesh.free_edges[e];
    for (std::size_t q = 0; q < edge.weights.size(); ++q) {
      double z = 0, dz = 0;
      for (int a = 0; a < nn; ++a) {
        z += mesh.nodes[v[a]][1] * edge.N[q * nn + a];
        dz += mesh.nodes[v[a]][1] * edge.dN[q * nn + a];
      }
      out.push_back({z, edge.weights[q] * std::abs(dz), v, &edge.N[q * nn]});
    }
  }
  return out;
}

}  // namespace rc::modes
