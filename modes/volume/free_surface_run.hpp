// A partially filled 3-D tank's ideal modes from its shape (docs/volume.md §8): meshed to its fill beyond the cylinder
// about the craft's spin axis, the free-surface operator built and surveyed. The command's driver
// (app/volume_command.cpp) prints the result.
#pragma once

#include "free_surface_survey.hpp"
#include "volume_mesh.hpp"

#include <functional>
#include <string>

namespace rc::modes {

struct FreeSurfaceRunResult {
  double surface_radius = 0;    // b
  double surface_area = 0;
  int pressure_dofs = 0, surface_dofs = 0, order = 0;
  double mesh_size = 0;
  std::size_t elements = 0;
  VolumeIntegrals liquid;       // volume, centroid, inertia about the centroid
  std::array<double, 3> axis_point{};  // P0: the spin axis's point at the centroid's height (the couplings' origin)
  FreeSurfaceSurvey survey;
};

// Serial. `log` sees one line per stage.
FreeSurfaceRunResult run_free_surface_modes(const geometry::VolumeShapeSpec& shape, const geometry::MeshOptions& mesh,
                                            const FreeSurfaceSurveySettings& settings,
                                            const std::function<void(const std::string&)>& log = {});

}  // namespace rc::modes
