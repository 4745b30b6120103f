// `cavity-modes shell`: the viscous fluid's damped modes in a full sphere (--inner-radius 0, the default) or a
// spherical shell with no-slip walls, by the spectral method of spherical/shell_pencil.hpp (docs/spherical.md):
// printed, with a check against a coarser truncation, and with -o written as a CSV. The request is resolved here,
// once; the solver gets the few settings it needs.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace rc::modes {

class ShellCommand {
 public:
  explicit ShellCommand(CLI::App& app);
  ShellCommand(const ShellCommand&) = delete;
  ShellCommand& operator=(const ShellCommand&) = delete;

  bool parsed() const { return app_->parsed(); }
  // Checks the options (one-line errors), solves, prints and writes. Inside a PETSc session.
  int run(const std::string& command_line) const;

 private:
  CLI::App* app_ = nullptr;
  double inner_radius_ = 0, ekman_ = 0, target_ = 1.0, resolution_ = 1.0, tolerance_ = 1e-6;
  int m_ = 1, modes_ = 1, radial_ = 0, lmax_ = 0;
  std::string symmetry_ = "antisymmetric", output_;
  bool convergence_check_ = true;
};

}  // namespace rc::modes
