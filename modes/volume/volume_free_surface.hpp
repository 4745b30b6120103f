// The free surface of a partially filled 3-D tank (docs/volume.md §8): the faces of the mesh on the cylinder ρ = b
// about the craft's spin axis (geometry/partial_volume.hpp), their Gauss points, and the surface forms the free
// surface adds to the Poincaré problem — the trace of the pressure space on the surface, its mass matrix
// M_s = ∫_Σ q p dS and loads ∫_Σ q f dS.
#pragma once

#include "volume_space.hpp"

#include <Eigen/Sparse>

#include <array>
#include <functional>
#include <vector>

namespace rc::modes {

class VolumeFreeSurface {
 public:
  // Throws std::runtime_error when the mesh has no free surface (free_surface_radius 0) or no face on it.
  explicit VolumeFreeSurface(const VolumeSpace& space);

  double radius() const { return radius_; }                      // b
  const std::array<double, 2>& spin_axis() const { return axis_; }
  double area() const { return area_; }
  // The pressure dofs on the surface, ascending; surface_index(d) their rank among them (−1 off the surface).
  const std::vector<int>& dofs() const { return dofs_; }
  int surface_index(int dof) const { return index_[dof]; }
  // M_s over the surface dofs.
  const Eigen::SparseMatrix<double>& mass() const { return mass_; }
  // ∫_Σ φ_i f dS for each surface dof i.
  Eigen::VectorXd load(const std::function<double(const std::array<double, 3>&)>& f) const;
  // ∫_Σ f dS.
  double integral(const std::function<double(const std::array<double, 3>&)>& f) const;

  // The surface's quadrature points (the viscous pencil's surface terms assemble on them: viscous_fill_surface.hpp).
  struct Point {
    std::array<double, 3> x{};
    double w = 0;                    // weight × dS
    std::vector<int> surface;        // the face's surface indices, one per trace basis function
    std::vector<double> N;           // the trace basis at the point
  };
  const std::vector<Point>& points() const { return points_; }

 private:
  double radius_ = 0, area_ = 0;
  std::array<double, 2> axis_{};
  std::vector<int> dofs_, index_;
  std::vector<Point> points_;
  Eigen::SparseMatrix<double> mass_;
};

}  // namespace rc::modes
