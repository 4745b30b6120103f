#include "load_scene.hpp"

#include "integrator.hpp"

namespace rc::rom {

Scene load_scene(const std::filesystem::path& file) {
  Scene scene = parse_scene(file);
  if (scene.run.present && !scene.run.nonlinear()) linear_integrator(scene);  // throws SceneError for an unknown name
  return scene;
}

}  // namespace rc::rom
