#include "discretisation.hpp"

#include "spectral_survey.hpp"

namespace rc::modes {

Discretisation::Discretisation(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh)
    : space(geometry::mesh_meridian(shape, mesh)),
      fluid(integrate_fluid(space)),
      forms(assemble_poincare_forms(space, fluid.centroid_z)),
      stiffness(forms.M),
      zhukovsky(zhukovsky_inertia(forms, stiffness)),
      sum_rule(fluid.A_f - zhukovsky.J_zh),
      velocity(space, fluid.centroid_z),
      coupling(velocity.coupling_vector()) {
  project_solenoidal(velocity, stiffness, coupling);
}

}  // namespace rc::modes
