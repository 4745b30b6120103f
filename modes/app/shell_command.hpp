// `cavity-modes shell`: the viscous fluid's damped modes in a full sphere (--inner-radius 0, the default) or a
// spherical shell with no-slip walls, by the spectral method of spherical/shell_pencil.hpp (docs/spherical.md):
// printed, with a check against a coarser truncation, and with -o written as a CSV; with --sigma the fluid's response
// R(σ) to the cavity's tilt instead, printed or written as a CSV, or with -o FILE.h5 a response table for chain-rom
// (spherical/shell_table.hpp); with --serve R at each σ read from standard input (chain-rom confirm's served
// solves, docs/rom.md "Confirmed roots"). The request is resolved here, once; the solvers get the few settings they need.
#pragma once

#include "shell_pencil.hpp"

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
  spherical::ShellSettings settings_at(double factor) const;
  int run_response(const std::string& command_line) const;
  void serve(std::istream& in, std::ostream& out) const;

  CLI::App* app_ = nullptr;
  double inner_radius_ = 0, ekman_ = 0, target_ = 1.0, resolution_ = 1.0, tolerance_ = 1e-6, sigma_imag_ = 0,
         max_fit_error_ = 1e-6, mesh_ekman_ = 0;
  int m_ = 1, modes_ = 1, radial_ = 0, lmax_ = 0, mesh_level_ = 0;
  std::string symmetry_ = "antisymmetric", output_, sigma_;
  bool convergence_check_ = true, serve_ = false;
};

}  // namespace rc::modes
