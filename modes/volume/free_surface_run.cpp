#include "free_surface_run.hpp"

#include <fmt/format.h>

namespace rc::modes {

FreeSurfaceRunResult run_free_surface_modes(const geometry::VolumeShapeSpec& shape, const geometry::MeshOptions& mesh,
                                            const FreeSurfaceSurveySettings& settings,
                                            const std::function<void(const std::string&)>& log) {
  const auto say = [&](const std::string& s) { if (log) log(s); };
  const VolumeSpace space(geometry::mesh_volume(shape, mesh), 0, false);
  const VolumeForms forms = assemble_volume_forms(space);
  const FreeSurfaceDynamics A(space, forms);
  FreeSurfaceRunResult r;
  r.surface_radius = A.surface().radius();
  r.surface_area = A.surface().area();
  r.pressure_dofs = space.ndof();
  r.surface_dofs = static_cast<int>(A.surface().dofs().size());
  r.elements = space.num_elements();
  r.liquid = A.liquid();
  r.axis_point = A.axis_point();
  r.order = space.order();
  r.mesh_size = space.mesh().size;
  say(fmt::format("free surface: b = {:.10g}, {} tetrahedra of order {}, {} pressure dofs ({} on the surface)",
                  r.surface_radius, r.elements, space.order(), r.pressure_dofs, r.surface_dofs));
  r.survey = survey_free_surface_modes(A, settings);
  return r;
}

}  // namespace rc::modes
