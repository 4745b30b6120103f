#include "volume_free_surface.hpp"

#include "partial_volume.hpp"
#include "tetrahedron_nodes.hpp"

#include <algorithm>
#include <stdexcept>

namespace rc::modes {
namespace {

// The faces found must cover the CAD surface (`cad`, 0 when unknown) to the curved faces' geometric error: a face
// missed is a piece of surface treated as a wall. Measured on half-full spheres (2026-12-07): P1 h 0.5 1.8e-2, P2 h 0.8
// 1.1e-3, P3 h 0.8 4.4e-4, P4 h 0.8 1.8e-4; the fault this guards against lost a third of the surface.
void require_covered(double area, double cad, int order) {
  const double tolerance = order == 1 ? 5e-2 : order == 2 ? 5e-3 : 2e-3;
  if (cad > 0 && std::abs(area - cad) > tolerance * cad)
    throw std::runtime_error("the mesh's faces on the free surface cover an area of " + std::to_string(area) +
                             " where the surface has " + std::to_string(cad) + ": some of its faces were not found "
                             "(try another --mesh-size)");
}

}  // namespace

VolumeFreeSurface::VolumeFreeSurface(const VolumeSpace& space)
    : radius_(space.mesh().free_surface_radius), axis_(space.mesh().spin_axis) {
  const auto& m = space.mesh();
  if (!(radius_ > 0)) throw std::runtime_error("the 3-D mesh has no free surface (a completely filled cavity)");
  const int npe = m.nodes_per_element, p = m.order;
  const auto tri = geometry::reference_triangle(p, 2 * p + 2);
  std::array<std::vector<int>, 4> local;
  for (int o = 0; o < 4; ++o) local[o] = geometry::tetrahedron_face_nodes(p, o);
  index_.assign(space.ndof(), -1);
  for (const auto& [e, o] : geometry::wall_faces(m)) {
    const int* v = &m.tetrahedra[e * npe];
    // Every node of the face, not only its vertices: a wall face whose three vertices sit on the contact line has its
    // edge nodes on the wall, off the cylinder (gmsh puts the high-order nodes on the CAD surfaces).
    bool on = true;
    for (int a : local[o])
      if (!geometry::on_free_surface(m.nodes[v[a]], radius_, axis_)) on = false;
    if (!on) continue;
    const auto dofs = space.element_dofs(e);
    for (std::size_t q = 0; q < tri.weights.size(); ++q) {
      Point pt;
      std::array<double, 3> xu{}, xv{};
      for (int t = 0; t < tri.nodes_per_element; ++t) {
        const int a = local[o][t];
        const auto& X = m.nodes[v[a]];
        const double N = tri.N[q * tri.nodes_per_element + t];
        const double du = tri.dN[(q * tri.nodes_per_element + t) * 2], dv = tri.dN[(q * tri.nodes_per_element + t) * 2 + 1];
        for (int c = 0; c < 3; ++c) {
          pt.x[c] += N * X[c];
          xu[c] += du * X[c];
          xv[c] += dv * X[c];
        }
        if (dofs[a] < 0) throw std::runtime_error("a free surface needs a pressure space without a pinned node");
        pt.surface.push_back(dofs[a]);  // dofs for now; surface indices below
        pt.N.push_back(N);
      }
      const double nx = xu[1] * xv[2] - xu[2] * xv[1], ny = xu[2] * xv[0] - xu[0] * xv[2], nz = xu[0] * xv[1] - xu[1] * xv[0];
      pt.w = tri.weights[q] * std::sqrt(nx * nx + ny * ny + nz * nz);
      area_ += pt.w;
      points_.push_back(std::move(pt));
    }
  }
  if (points_.empty()) throw std::runtime_error("no face of the 3-D mesh lies on its free surface");
  require_covered(area_, m.free_surface_area, p);
  for (const auto& pt : points_)
    for (int d : pt.surface) index_[d] = 0;
  for (int d = 0; d < space.ndof(); ++d)
    if (index_[d] == 0) {
      index_[d] = static_cast<int>(dofs_.size());
      dofs_.push_back(d);
    }
  std::vector<Eigen::Triplet<double>> t;
  for (auto& pt : points_) {
    for (int& d : pt.surface) d = index_[d];
    for (std::size_t i = 0; i < pt.N.size(); ++i)
      for (std::size_t j = 0; j < pt.N.size(); ++j) t.emplace_back(pt.surface[i], pt.surface[j], pt.w * pt.N[i] * pt.N[j]);
  }
  const auto n = static_cast<Eigen::Index>(dofs_.size());
  mass_.resize(n, n);
  mass_.setFromTriplets(t.begin(), t.end());
}

Eigen::VectorXd VolumeFreeSurface::load(const std::function<double(const std::array<double, 3>&)>& f) const {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(dofs_.size()));
  for (const auto& pt : points_) {
    const double fw = f(pt.x) * pt.w;
    for (std::size_t i = 0; i < pt.N.size(); ++i) out(pt.surface[i]) += fw * pt.N[i];
  }
  return out;
}

double VolumeFreeSurface::integral(const std::function<double(const std::array<double, 3>&)>& f) const {
  double s = 0;
  for (const auto& pt : points_) s += f(pt.x) * pt.w;
  return s;
}

}  // namespace rc::modes
