// The 3-D shape commands of cavity-modes (docs/volume.md): `ellipsoid --a --b --c [--tilt DEG]` and
// `volume FILE` (.geo/.msh with a 3-D group "fluid", or CAD .step/.stp/.brep), each writing an ideal 3-D mode table,
// or with --ekman the viscous fluid's damped modes and their coupling tensors, printed and, with -o, as a viscous table,
// or with --ekman and --sigma its forced response: a CSV, or with -o FILE.h5 a response table for chain-rom; an
// ellipsoid with --fill F (< 1) and the spin axis's distance is a partially filled tank whose ideal modes are printed
// and tabled, or with --ekman and --sigma its viscous forced response written as CSV.
// The request is resolved here, once; make_volume_table gets only what it needs.
#pragma once

#include "volume_table.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace rc::modes {

class VolumeCommands {
 public:
  explicit VolumeCommands(CLI::App& app);
  VolumeCommands(const VolumeCommands&) = delete;
  VolumeCommands& operator=(const VolumeCommands&) = delete;

  bool parsed() const;
  static bool is_volume_command(const std::string& name) { return name == "ellipsoid" || name == "volume"; }
  // Checks the parsed options (one-line errors), computes and writes the table, prints its report. Inside a PETSc
  // session.
  int run(const std::string& command_line) const;

 private:
  VolumeTableRequest resolve() const;
  geometry::VolumeShapeSpec resolve_shape() const;
  void check_partial_fill_options() const;
  int run_viscous(const VolumeTableRequest& ideal, const std::string& command_line) const;
  int run_response(const VolumeTableRequest& ideal) const;
  int run_response_table(const VolumeTableRequest& ideal, const std::string& command_line) const;
  int run_partial_fill(const VolumeTableRequest& request, const std::string& command_line) const;
  int run_fill_response(const VolumeTableRequest& ideal) const;
  int run_boundary_layer_response(const VolumeTableRequest& ideal) const;
  int run_boundary_layer_table(const VolumeTableRequest& ideal, const std::string& command_line) const;
  void set_provenance(ModeTable& table, const std::string& command_line) const;
  CLI::App *ellipsoid_ = nullptr, *volume_ = nullptr;
  double a_ = 0, b_ = 0, c_ = 0, tilt_degrees_ = 0;
  double fill_ = 1, axis_distance_ = 0, axis_direction_degrees_ = 0;  // a partially filled tank (docs/volume.md §8)
  std::string file_;
  // The options both commands take (add_common_options).
  struct Common {
    std::string output;
    int order = kVolumeDefaultOrder, columns = 60;
    double size = 0, wall_size = 0, wall_growth = 1.0, wall_layer = 0, near_wall_size = 0, floor = 1e-4;
    bool fields = false;
    double ekman = 0;             // > 0: the viscous fluid's damped modes (docs/volume.md §7)
    std::vector<double> targets;  // their ideal frequencies (default: the closed form's, or the ideal table's)
    int modes = 1;
    bool convergence_check = true;      // with --ekman -o: the modes again on a mesh 1.5 times as coarse
    double convergence_tolerance = 1e-3;
    std::string sigma;            // with --ekman: the forced response's frequencies (docs/volume.md §7), no modes
    double sigma_imag = 0;
    double max_fit_error = 1e-4;  // with --sigma -o FILE.h5: the response table's tolerance
    int krylov_vectors = 4;       // and its Krylov vectors per input and expansion point
    std::string exact_at;         // and the complex frequencies where its R must be exact
    bool boundary_layer = false;  // with --ekman --sigma: the ideal liquid with Ekman layers on its walls (docs/volume.md §9)
    std::string ideal_table;      // and with -o T.h5: the ideal table to take its rows from (no survey)
  } common_;
};

}  // namespace rc::modes
