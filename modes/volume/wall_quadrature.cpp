#include "wall_quadrature.hpp"

#include "meridian_mesh.hpp"  // reference_triangle
#include "partial_volume.hpp"
#include "tetrahedron_nodes.hpp"

#include <Eigen/Dense>

#include <stdexcept>

namespace rc::modes {
namespace {

constexpr std::array<std::array<double, 3>, 4> kVertex = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

// The face opposite `o`'s Gauss points in the tetrahedron's reference coordinates, and the basis there.
struct FaceRule {
  std::vector<int> nodes;               // the face's local nodes (for the free-surface test)
  std::array<int, 3> vertices{};
  geometry::TetrahedronBasis basis;
};

FaceRule face_rule(int order, int o, const geometry::ReferenceTriangle& tri) {
  FaceRule r;
  r.nodes = geometry::tetrahedron_face_nodes(order, o);
  r.vertices = geometry::face_vertices(o);
  std::vector<std::array<double, 3>> points;
  for (const auto& [u, v] : tri.points) {
    std::array<double, 3> p{};
    for (int d = 0; d < 3; ++d)
      p[d] = (1 - u - v) * kVertex[r.vertices[0]][d] + u * kVertex[r.vertices[1]][d] + v * kVertex[r.vertices[2]][d];
    points.push_back(p);
  }
  r.basis = geometry::tetrahedron_basis_at(order, points);
  return r;
}

Eigen::Vector3d reference_edge(int from, int to) {
  return Eigen::Vector3d(kVertex[to][0] - kVertex[from][0], kVertex[to][1] - kVertex[from][1],
                         kVertex[to][2] - kVertex[from][2]);
}

}  // namespace

std::vector<WallQuadraturePoint> wall_quadrature(const VolumeSpace& space) {
  const auto& m = space.mesh();
  const int p = m.order, npe = m.nodes_per_element;
  const auto tri = geometry::reference_triangle(p, 2 * p + 2);
  std::array<FaceRule, 4> rules;
  for (int o = 0; o < 4; ++o) rules[o] = face_rule(p, o, tri);
  std::vector<WallQuadraturePoint> out;
  for (const auto& [e, o] : geometry::wall_faces(m)) {
    const int* v = &m.tetrahedra[e * npe];
    const FaceRule& r = rules[o];
    if (m.free_surface_radius > 0) {
      bool on = true;  // every node of the face, as VolumeFreeSurface finds the surface's faces
      for (int a : r.nodes)
        if (!geometry::on_free_surface(m.nodes[v[a]], m.free_surface_radius, m.spin_axis)) on = false;
      if (on) continue;
    }
    for (std::size_t q = 0; q < tri.weights.size(); ++q) {
      Eigen::Matrix3d J = Eigen::Matrix3d::Zero();  // J(i, j) = ∂x_i/∂u_j
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (int a = 0; a < npe; ++a) {
        const Eigen::Vector3d X(m.nodes[v[a]][0], m.nodes[v[a]][1], m.nodes[v[a]][2]);
        x += r.basis.N[q * npe + a] * X;
        for (int j = 0; j < 3; ++j) J.col(j) += r.basis.dN[(q * npe + a) * 3 + j] * X;
      }
      const double det = J.determinant();
      if (!(det > 0)) throw std::runtime_error("wall quadrature: a tetrahedron on the wall is inverted at a face point");
      const Eigen::Vector3d t1 = J * reference_edge(r.vertices[0], r.vertices[1]);
      const Eigen::Vector3d t2 = J * reference_edge(r.vertices[0], r.vertices[2]);
      Eigen::Vector3d n = t1.cross(t2);
      const double area = n.norm();
      // Into the liquid: towards the opposite vertex.
      if (n.dot(J * reference_edge(r.vertices[0], o)) < 0) n = -n;
      WallQuadraturePoint pt;
      pt.element = e;
      pt.w = tri.weights[q] * area;
      for (int d = 0; d < 3; ++d) {
        pt.x[d] = x(d);
        pt.normal[d] = n(d) / area;
      }
      const Eigen::Matrix3d JinvT = J.inverse().transpose();
      pt.grad.resize(static_cast<std::size_t>(npe) * 3);
      for (int a = 0; a < npe; ++a) {
        const Eigen::Vector3d g = JinvT * Eigen::Vector3d(r.basis.dN[(q * npe + a) * 3], r.basis.dN[(q * npe + a) * 3 + 1],
                                                          r.basis.dN[(q * npe + a) * 3 + 2]);
        for (int d = 0; d < 3; ++d) pt.grad[a * 3 + d] = g(d);
      }
      out.push_back(std::move(pt));
    }
  }
  if (out.empty()) throw std::runtime_error("wall quadrature: the mesh has no wall face");
  return out;
}

}  // namespace rc::modes
