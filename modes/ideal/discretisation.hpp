// One discretisation of a cavity, everything the cluster search needs built once: the FE space, the
// frozen-fluid integrals, the forms of docs/physics.md §2, the stiffness factorisation, Zhukovsky's inertia, the
// quadrature-point velocity space and the solenoidal coupling vector w = P_H(e1 × r), whose spectral
// measure has mass π‖w‖² = A_f − J_zh (the sum rule). Used for the table and for its convergence check.
#pragma once

#include "fe_space.hpp"
#include "poincare_forms.hpp"
#include "stiffness_solver.hpp"
#include "velocity_space.hpp"
#include "zhukovsky.hpp"

#include <memory>

namespace rc::modes {

struct Discretisation {
  Discretisation(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh);
  Discretisation(const Discretisation&) = delete;
  Discretisation& operator=(const Discretisation&) = delete;

  FESpace space;
  FluidIntegrals fluid;
  PoincareForms forms;
  StiffnessSolver stiffness;
  ZhukovskyResult zhukovsky;
  double sum_rule;  // A_f − J_zh
  VelocitySpace velocity;
  Eigen::VectorXd coupling;  // w = P_H(e1 × r)
};

}  // namespace rc::modes
