// The drivers' scene: parsed and validated (scene.hpp), with the names that only the layers above the parser know checked
// too (run.method against the integrators' registry, linear/integrator.hpp), so that every command refuses a bad scene
// in one line before any work.
#pragma once

#include "scene.hpp"

#include <filesystem>

namespace rc::rom {

Scene load_scene(const std::filesystem::path& file);

}  // namespace rc::rom
