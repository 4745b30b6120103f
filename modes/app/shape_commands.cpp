#include "shape_commands.hpp"

#include <stdexcept>
#include <utility>
#include <vector>

namespace rc::modes {

ShapeCommands::ShapeCommands(CLI::App& app, const std::string& purpose) {
  const auto add = [&](const std::string& kind, const std::string& what,
                       const std::vector<std::pair<std::string, std::string>>& dims) {
    ShapeCommand& c = commands_.emplace_back();
    c.kind = kind;
    c.app = app.add_subcommand(kind, what + purpose);
    for (const auto& [name, help] : dims) c.app->add_option("--" + name, c.dims[name], help)->required();
  };
  add("sphere", "sphere of radius R", {{"radius", "radius R"}});
  add("spheroid", "spheroid with equatorial semi-axis a and polar semi-axis c",
      {{"a", "equatorial semi-axis"}, {"c", "polar semi-axis"}});
  add("cylinder", "circular cylinder", {{"radius", "radius"}, {"height", "full height"}});
  commands_.back().app->add_option("--inner-radius", commands_.back().inner_radius,
                                   "radius of a coaxial rod inside: the liquid fills inner radius < r < radius (an "
                                   "annular cavity, no axis)");
  add("cone", "cone, apex down, flat lid on top", {{"radius", "lid radius"}, {"height", "height"}});
  add("section", "the user's meridian section (.geo or .msh; docs/geometry.md)", {});
  commands_.back().app->add_option("file", commands_.back().file, "section file")->required();
}

const ShapeCommand* ShapeCommands::parsed() const {
  for (const auto& c : commands_)
    if (c.app->parsed()) return &c;
  return nullptr;
}

geometry::ShapeSpec ShapeCommands::parsed_shape() const {
  const ShapeCommand* c = parsed();
  if (!c) throw std::logic_error("no shape command was parsed");
  geometry::ShapeSpec s;
  s.kind = c->kind;
  if (c->kind == "section") s.file = c->file;
  else s.dims = c->dims;
  if (const auto* inner = c->app->get_option_no_throw("--inner-radius"); inner && inner->count() > 0)
    s.dims["inner_radius"] = c->inner_radius;
  return s;
}

bool ShapeCommands::is_shape(const std::string& name) {
  for (const char* k : {"sphere", "spheroid", "cylinder", "cone", "section"})
    if (name == k) return true;
  return false;
}

}  // namespace rc::modes
