// The shape subcommands shared by cavity-modes and spectral-window: sphere, spheroid, cylinder, cone (their
// dimensions as required options) and `section FILE`, and the ShapeSpec of the one that was parsed.
#pragma once

#include "meridian_mesh.hpp"

#include <CLI/CLI.hpp>

#include <deque>
#include <map>
#include <string>

namespace rc::modes {

struct ShapeCommand {
  CLI::App* app = nullptr;
  std::string kind;
  std::map<std::string, double> dims;  // bound to the dimension options
  std::string file;                    // section only
  double inner_radius = 0;             // cylinder only, when --inner-radius is given
};

class ShapeCommands {
 public:
  // Adds the five subcommands to `app`; `purpose` ends each one's description (e.g. ": its mode table").
  ShapeCommands(CLI::App& app, const std::string& purpose);
  ShapeCommands(const ShapeCommands&) = delete;
  ShapeCommands& operator=(const ShapeCommands&) = delete;

  // Each subcommand in turn (the options bind to these, so they never move: a deque).
  std::deque<ShapeCommand>& all() { return commands_; }
  // The parsed shape command, or nullptr if another command (info, compare) was parsed.
  const ShapeCommand* parsed() const;
  // Its ShapeSpec; throws if none was parsed.
  geometry::ShapeSpec parsed_shape() const;
  static bool is_shape(const std::string& name);

 private:
  std::deque<ShapeCommand> commands_;
};

}  // namespace rc::modes
