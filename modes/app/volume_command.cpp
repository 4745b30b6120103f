#include "volume_command.hpp"

#include "progress.hpp"

#include "free_surface_run.hpp"
#include "free_surface_table.hpp"

#include "atomic_file.hpp"
#include "mode_table_report.hpp"
#include "petsc_handles.hpp"
#include "ellipsoid_closed_form.hpp"
#include "viscous_volume_run.hpp"
#include "viscous_volume_table.hpp"
#include "boundary_layer_response.hpp"
#include "boundary_layer_table.hpp"
#include "viscous_volume_response.hpp"
#include "viscous_volume_response_table.hpp"
#include "cavity_response.hpp"
#include "volume_fields.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace rc::modes {
namespace {

template <class Common>
void add_common_options(CLI::App* cmd, Common& o) {
  cmd->add_option("--order", o.order, "Lagrange order of the tetrahedra, 1..6 (default 4)");
  cmd->add_option("--mesh-size", o.size, "element size (default 0.4 of the smallest dimension)");
  cmd->add_option("--wall-size", o.wall_size, "element size on the wall, graded to --mesh-size inside (the geometry "
                                              "error lives on the wall; docs/volume.md §4; with --ekman 2 Ek^(1/2) "
                                              "unless given, for the Ekman layers, §7)");
  cmd->add_option("--wall-layer", o.wall_layer, "anisotropic wall layers this thick in all (the ellipsoid or a "
                                                "file), the first --wall-size thick, each next (1 + --wall-growth) "
                                                "times thicker (the viscous fluid's Ekman layers, docs/volume.md §7); "
                                                "0 = none");
  cmd->add_option("--near-wall-size", o.near_wall_size, "with --wall-layer: the elements along the wall and just "
                                                        "inside the layers, growing by 1 per unit distance to "
                                                        "--mesh-size (0 = the interior size; docs/volume.md §7)");
  cmd->add_option("--wall-growth", o.wall_growth, "growth of the element size per unit distance from the wall "
                                                  "(default 1)");
  cmd->add_option("--floor", o.floor, "keep modes whose coupling tensor's trace exceeds this fraction of the sum "
                                      "rule's (default 1e-4)");
  cmd->add_option("--survey-columns", o.columns, "basis vectors of the plain Gauss rule, 12..600 (default 60): more "
                                                 "resolve the band weights of a dense spectrum (docs/volume.md §5)");
  cmd->add_flag("--fields", o.fields, "also store each row's pressure and velocity (complex) at the mesh nodes, with "
                                      "an XDMF companion FILE.xdmf for ParaView (docs/volume.md §5)");
  cmd->add_option("-o,--output", o.output, "mode table to write (HDF5; required without --ekman)");
  cmd->add_option("--ekman", o.ekman, "Ekman number > 0: the viscous fluid's damped modes nearest the targets, with "
                                      "their coupling tensors, printed, and with -o a viscous table (docs/volume.md §7)");
  cmd->add_option("--target", o.targets, "with --ekman: the ideal frequencies of the modes wanted (default: the "
                                         "ellipsoid's spin-over, or the heaviest rows of the ideal table)");
  cmd->add_option("--modes", o.modes, "with --ekman and no --target: how many of the ideal table's heaviest rows to "
                                      "follow (default 1)");
  cmd->add_option("--convergence-tolerance", o.convergence_tolerance,
                  "with --ekman -o: a row is flagged converged if its lambda and E change by less than this against the "
                  "same order on a mesh 1.5 times as coarse (default 1e-3)");
  cmd->add_flag("--no-convergence-check", [&o](std::int64_t) { o.convergence_check = false; },
                "with --ekman -o: skip the comparison with the coarser mesh");
  cmd->add_option("--sigma", o.sigma, "with --ekman: the forced response's frequencies instead of modes, FROM:TO:N or a "
                                      "list of complex numbers (0.5+0.1i,1.2): the 3 x 3 response tensor to -o FILE.csv; "
                                      "with -o FILE.h5 a response table for chain-rom on the real window FROM:TO:N, "
                                      "FROM >= 0 (docs/volume.md §7)");
  cmd->add_option("--max-fit-error", o.max_fit_error, "with --sigma -o FILE.h5: the response table's tolerance, "
                                                      "relative to each entry's largest value on the window (default "
                                                      "1e-4)");
  cmd->add_option("--exact-at", o.exact_at, "with --sigma -o FILE.h5: complex frequencies (0.7-0.003i,1.2) where the "
                                            "response table's R must be the fluid's own, to rounding (a chain's roots: "
                                            "docs/volume.md §7)");
  cmd->add_option("--krylov-vectors", o.krylov_vectors, "with --sigma -o FILE.h5: Krylov vectors per input and "
                                                        "expansion point, 1..16 (default 4)");
  cmd->add_option("--sigma-imag", o.sigma_imag, "with --sigma FROM:TO:N: the imaginary part of every frequency");
  cmd->add_flag("--boundary-layer", o.boundary_layer, "with --ekman --sigma -o FILE.csv: the forced response of the "
                                                      "ideal liquid with Ekman layers on its walls, on the ideal mesh, at "
                                                      "any small Ek (docs/volume.md §9)");
  cmd->add_option("--ideal-table", o.ideal_table, "with --boundary-layer -o T.h5: this tank's ideal table (the same "
                                                  "command without --ekman), whose rows the table takes instead of "
                                                  "surveying the liquid again");
}

// Progress lines on stderr, from the root rank only.
void print_progress(const std::string& line) {
  if (is_root_rank()) std::cerr << line << "\n";
}

// A partially filled 3-D tank's solvers are serial (docs/volume.md §8).
void require_one_rank() {
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  if (ranks > 1) throw std::runtime_error("a partially filled 3-D tank is solved on one rank (run it without mpirun)");
}

std::string text_of(const std::string& file) {
  std::ifstream in(file);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

void print_report(const VolumeTableResult& r) {
  std::cout << table_text(r.table);
  const auto& s = r.survey;
  std::cout << "3-D survey: " << s.columns << " basis vectors; tensor sum rule: the rule's weights sum to I_f - J_zh to "
            << r.sum_rule_mismatch << " (relative)"
            << (s.shifts > 0 ? "; " + std::to_string(s.shifts) + " shift-and-invert run(s)" : std::string()) << "\n";
  if (!s.unsettled.empty()) {
    double weight = 0;
    for (const auto& m : s.unsettled) weight += (m.H(0, 0) + m.H(1, 1)).real();
    std::cout << "NOT CONVERGED: " << s.unsettled.size() << " heavy cluster(s) (transverse weight about " << weight
              << ", a Ritz estimate) did not settle within the basis budget; they are not in the rows, but the band "
                 "weights hold them (reduction = \"bands\", docs/volume.md §5)\n";
  }
  if (r.fields) {
    double worst = 0;
    for (const auto& m : r.fields->modes) {
      const double top = largest_coupling(r.table, m.row);
      worst = std::max(worst, std::abs(m.a * m.a - top) / std::max(top, 1e-300));
    }
    std::cout << "fields: " << r.fields->modes.size() << " rows on " << r.fields->num_points()
              << " nodes; each field's a^2 against its row's largest coupling eigenvalue: " << worst
              << " (relative, worst row)\n";
  }
  std::cout << std::flush;
}

}  // namespace

VolumeCommands::VolumeCommands(CLI::App& app) {
  ellipsoid_ = app.add_subcommand("ellipsoid", "3-D: triaxial ellipsoid, semi-axes a (x), b (y), c (z, the spin axis): "
                                               "its 3-D mode table (docs/volume.md)");
  ellipsoid_->add_option("--a", a_, "semi-axis along x")->required();
  ellipsoid_->add_option("--b", b_, "semi-axis along y")->required();
  ellipsoid_->add_option("--c", c_, "semi-axis along z")->required();
  ellipsoid_->add_option("--tilt", tilt_degrees_, "angle (degrees) of the ellipsoid's c axis against the spin axis, "
                                                  "turned about x");
  ellipsoid_->add_option("--fill", fill_, "partially filled: the liquid's volume fraction in (0, 1] (default 1); its free "
                                         "surface is the cylinder about the craft's spin axis (docs/volume.md §8)");
  ellipsoid_->add_option("--axis-distance", axis_distance_, "with --fill: the distance from the tank's centre to the "
                                                            "craft's spin axis (parallel to z; default 0, on the axis)");
  ellipsoid_->add_option("--axis-direction", axis_direction_degrees_, "with --fill: the direction (degrees from x, in "
                                                                      "the x-y plane) from the spin axis to the tank");
  add_common_options(ellipsoid_, common_);
  volume_ = app.add_subcommand("volume", "3-D: the user's cavity (.geo/.msh with a 3-D physical group \"fluid\", or "
                                         "CAD .step/.stp/.brep): its 3-D mode table (docs/volume.md)");
  volume_->add_option("file", file_, "geometry file")->required();
  volume_->add_option("--tilt", tilt_degrees_, "angle (degrees) by which the file's cavity is turned about x against "
                                               "the spin axis z (the file's own coordinates turned about its origin)");
  add_common_options(volume_, common_);
}

bool VolumeCommands::parsed() const { return ellipsoid_->parsed() || volume_->parsed(); }

geometry::VolumeShapeSpec VolumeCommands::resolve_shape() const {
  if (!ellipsoid_->parsed()) return {"volume", {}, file_, tilt_degrees_ * std::numbers::pi / 180};
  geometry::VolumeShapeSpec shape{"ellipsoid", {{"a", a_}, {"b", b_}, {"c", c_}}, {}, tilt_degrees_ * std::numbers::pi / 180};
  const double phi = axis_direction_degrees_ * std::numbers::pi / 180;
  if (!(axis_distance_ >= 0) || !std::isfinite(axis_distance_) || !std::isfinite(phi))
    throw std::runtime_error("--axis-distance must be >= 0 and finite, --axis-direction finite");
  if (fill_ == 1 && (axis_distance_ != 0 || phi != 0))
    throw std::runtime_error("--axis-distance/--axis-direction place a partially filled tank's free surface (with "
                             "--fill < 1); a full tank's table is placed by the scene's offset");
  shape.fill = fill_;
  shape.spin_axis = {0.0 - axis_distance_ * std::cos(phi), 0.0 - axis_distance_ * std::sin(phi)};  // no −0 printed
  return shape;
}

// A 3-D partial fill's ideal modes are printed and tabled on isotropic meshes, its viscous forced response written as
// CSV (docs/volume.md §8): what else is asked is refused, naming what is built.
void VolumeCommands::check_partial_fill_options() const {
  const Common& o = common_;
  const std::string ext = std::filesystem::path(o.output).extension().string();
  if (o.ekman != 0) {
    if (o.sigma.empty() || (ext != ".csv" && ext != ".h5"))
      throw std::runtime_error("--ekman with --fill in 3-D gives the forced response (--ekman Ek --sigma LIST -o "
                               "FILE.csv) and the response table (--ekman Ek --sigma FROM:TO:N -o T.h5), with "
                               "--boundary-layer at any Ek; its damped modes are not built yet");
    if (!(o.ekman > 0 && o.ekman < 1)) throw std::runtime_error("--ekman must be in (0, 1)");
    if (ext == ".h5") {
      if (!(o.max_fit_error > 0 && o.max_fit_error < 1)) throw std::runtime_error("--max-fit-error must be in (0, 1)");
      if (o.krylov_vectors < 1 || o.krylov_vectors > 16) throw std::runtime_error("--krylov-vectors must be in 1..16");
      if (o.sigma_imag != 0) throw std::runtime_error("a response table's window is real: drop --sigma-imag");
    } else if (!o.exact_at.empty()) {
      throw std::runtime_error("--exact-at belongs to a response table: --ekman Ek --sigma FROM:TO:N -o FILE.h5");
    }
    if (o.order < 2) throw std::runtime_error("--ekman needs --order >= 2 (Taylor-Hood elements)");
    if (!o.targets.empty()) throw std::runtime_error("--sigma computes no modes: drop --target");
  } else if (!o.sigma.empty()) {
    throw std::runtime_error("--sigma needs --ekman (the ideal fluid's response is its table's modal sum)");
  }
  if (o.fields)
    throw std::runtime_error("--fields is not written for a partially filled 3-D tank yet: its modes are printed and, "
                             "with -o T.h5, tabled (docs/volume.md §8)");
  if (o.ekman == 0 && !o.output.empty() && ext != ".h5")
    throw std::runtime_error("-o for a partially filled 3-D tank writes a mode table: a .h5 file");
  if (o.wall_layer > 0) throw std::runtime_error("--wall-layer is not taken with --fill in 3-D (--wall-size is)");
  if (o.ekman == 0 && o.wall_size > 0) throw std::runtime_error("--wall-size belongs to --ekman with --fill in 3-D");
}

VolumeTableRequest VolumeCommands::resolve() const {
  VolumeTableRequest r;
  r.shape = resolve_shape();
  geometry::check_volume_shape(r.shape);
  const Common& o = common_;
  if (!(o.floor > 0 && o.floor < 1)) throw std::runtime_error("--floor must be in (0, 1)");
  if (o.columns < 12 || o.columns > 600) throw std::runtime_error("--survey-columns must be in 12..600");
  r.mesh.order = o.order;
  r.mesh.size = o.size;
  r.mesh.wall_size = o.wall_size;
  r.mesh.wall_growth = o.wall_growth;
  r.mesh.wall_layer = o.wall_layer;
  r.mesh.near_wall_size = o.near_wall_size;
  r.survey.floor = o.floor;
  r.survey.max_columns = o.columns;
  r.fields = o.fields;
  if (o.fields) check_companion_name(o.output);
  if (r.shape.fill < 1) {
    check_partial_fill_options();
    return r;
  }
  if (o.ekman == 0 && o.output.empty()) throw std::runtime_error("-o/--output is required (the table to write)");
  if (o.sigma.empty() && o.sigma_imag != 0) throw std::runtime_error("--sigma-imag needs --sigma");
  if (o.ekman != 0) {
    if (!(o.ekman > 0 && o.ekman < 1)) throw std::runtime_error("--ekman must be in (0, 1)");
    if (o.fields) throw std::runtime_error("--fields is not available with --ekman in 3-D");
    if (o.order < 2) throw std::runtime_error("--ekman needs --order >= 2 (Taylor-Hood elements)");
    for (double t : o.targets)
      if (!(t > 0 && t < 2)) throw std::runtime_error("--target: each frequency must be in (0, 2)");
    if (o.modes < 1 || o.modes > 20) throw std::runtime_error("--modes must be in 1..20");
    if (!(o.convergence_tolerance > 0 && o.convergence_tolerance < 1))
      throw std::runtime_error("--convergence-tolerance must be in (0, 1)");
    if (!o.sigma.empty() && !o.targets.empty()) throw std::runtime_error("--sigma computes no modes: drop --target");
    const std::string ext = std::filesystem::path(o.output).extension().string();
    if (!o.sigma.empty() && ext != ".csv" && ext != ".h5")
      throw std::runtime_error("--sigma writes the response as CSV (-o FILE.csv) or as a response table (-o FILE.h5)");
    if (!o.sigma.empty() && ext == ".h5") {
      if (!(o.max_fit_error > 0 && o.max_fit_error < 1)) throw std::runtime_error("--max-fit-error must be in (0, 1)");
      if (o.krylov_vectors < 1 || o.krylov_vectors > 16) throw std::runtime_error("--krylov-vectors must be in 1..16");
      if (o.sigma_imag != 0) throw std::runtime_error("a response table's window is real: drop --sigma-imag");
    }
    if (!o.exact_at.empty() && (o.sigma.empty() || ext != ".h5"))
      throw std::runtime_error("--exact-at belongs to a response table: --ekman Ek --sigma FROM:TO:N -o FILE.h5");
  } else if (!o.targets.empty()) {
    throw std::runtime_error("--target needs --ekman");
  } else if (!o.sigma.empty()) {
    throw std::runtime_error("--sigma needs --ekman (the ideal fluid's response is its table's modal sum)");
  }

  return r;
}

void VolumeCommands::set_provenance(ModeTable& table, const std::string& command_line) const {
  table.command_line = command_line;
  if (ellipsoid_->parsed()) {
    std::ostringstream os;
    os << "ellipsoid a=" << a_ << " b=" << b_ << " c=" << c_ << " tilt=" << tilt_degrees_ << "deg";
    table.geometry_source = os.str();
  } else {
    table.geometry_source = std::filesystem::path(file_).filename().string();
    if (tilt_degrees_ != 0) table.geometry_source += " tilt=" + std::to_string(tilt_degrees_) + "deg";
    table.geometry_text = text_of(file_);
  }
}

int VolumeCommands::run(const std::string& command_line) const {
  if (common_.boundary_layer) {
    const auto& o = common_;
    const auto ext = std::filesystem::path(o.output).extension();
    if (o.ekman == 0 || o.sigma.empty() || (ext != ".csv" && ext != ".h5"))
      throw std::runtime_error("--boundary-layer gives the forced response (--ekman Ek --sigma LIST -o FILE.csv) or "
                               "its response table (--ekman Ek --sigma FROM:TO:N -o T.h5)");
    if (!o.exact_at.empty() && ext != ".h5")
      throw std::runtime_error("--exact-at belongs to a response table (-o T.h5)");
    if (!o.ideal_table.empty() && ext != ".h5")
      throw std::runtime_error("--ideal-table belongs to a boundary-layer table (-o T.h5)");
    if (o.wall_size > 0 || o.wall_layer > 0 || o.near_wall_size > 0)
      throw std::runtime_error("--boundary-layer meshes the ideal liquid: drop --wall-size, --wall-layer and "
                               "--near-wall-size (the layers are in its wall conditions)");
  } else if (!common_.ideal_table.empty()) {
    throw std::runtime_error("--ideal-table belongs to a boundary-layer table (--boundary-layer ... -o T.h5)");
  }
  const VolumeTableRequest request = resolve();
  if (common_.boundary_layer && std::filesystem::path(common_.output).extension() == ".h5")
    return run_boundary_layer_table(request, command_line);
  if (common_.boundary_layer) return run_boundary_layer_response(request);
  if (request.shape.fill < 1 && common_.ekman > 0 && std::filesystem::path(common_.output).extension() == ".h5")
    return run_response_table(request, command_line);
  if (request.shape.fill < 1 && common_.ekman > 0) return run_fill_response(request);
  if (request.shape.fill < 1) return run_partial_fill(request, command_line);
  if (common_.ekman > 0 && !common_.sigma.empty() && std::filesystem::path(common_.output).extension() == ".h5")
    return run_response_table(request, command_line);
  if (common_.ekman > 0 && !common_.sigma.empty()) return run_response(request);
  if (common_.ekman > 0) return run_viscous(request, command_line);
  VolumeTableResult result = make_volume_table(request, print_progress);
  if (!is_root_rank()) return 0;
  set_provenance(result.table, command_line);
  write_mode_table(result.table, common_.output, result.fields ? &*result.fields : nullptr);
  print_report(result);
  return 0;
}

namespace {

void print_partial_fill(const FreeSurfaceRunResult& r, const geometry::VolumeShapeSpec& shape) {
  const FreeSurfaceSurvey& v = r.survey;
  fmt::print("partially filled tank: fill {:.6g}, spin axis through ({:.6g}, {:.6g}), free surface b = {:.10g} "
             "(area {:.6g})\n", shape.fill, shape.spin_axis[0], shape.spin_axis[1], r.surface_radius, r.surface_area);
  fmt::print("liquid: volume {:.10g}, centroid ({:.6g}, {:.6g}, {:.6g}); {} tetrahedra, {} pressure dofs ({} on the "
             "surface)\n", r.liquid.volume, r.liquid.centroid[0], r.liquid.centroid[1], r.liquid.centroid[2], r.elements,
             r.pressure_dofs, r.surface_dofs);
  fmt::print("sum rule (rotations about the spin axis's point at the centroid's height, I_f - J_D + K): xx {:.10g}, yy {:.10g}, zz {:.10g}; the Gauss "
             "rule's weights sum to it to {:.1e}\n", v.gram(0, 0).real(), v.gram(1, 1).real(), v.gram(2, 2).real(),
             (v.total - v.gram).norm() / v.gram.norm());
  fmt::print("{:>14} {:>12} {:>12} {:>12} {:>12} {:>12} {:>9}\n", "lambda", "E (xx+yy)", "H_zz", "Tx_xx", "Ty_yy",
             "Ux.Tx", "bound");
  for (const auto& m : v.modes)
    fmt::print("{:14.9f} {:12.6g} {:12.6g} {:12.6g} {:12.6g} {:12.6g} {:9.1e}\n", m.lambda, m.transverse(),
               m.H(2, 2).real(), m.H(3, 3).real(), m.H(4, 4).real(), m.H(0, 3).real(), m.residual);
  for (const auto& m : v.unsettled)
    fmt::print("NOT CONVERGED: weight {:.3g} near lambda {:.6g} (bound {:.1e}) did not settle in {} shifts\n",
               m.H.trace().real(), m.lambda, m.residual, v.shifts);
  fmt::print("rows: {} modes (lambda > 0; each is also a mode at -lambda), {} shifts\n", v.modes.size(), v.shifts);
  // The plain rule's measure in bands (both signs of λ folded): where the rows do not hold the weight, a dense
  // cluster does (a generic cavity's inertial spectrum is not discrete, docs/volume.md §8).
  const std::vector<double> edges = {0, 0.05, 0.5, 1, 1.5, 2, 3, 1e300};
  std::vector<double> E(edges.size() - 1, 0), T(edges.size() - 1, 0);
  for (const auto& m : v.rule)
    for (std::size_t i = 0; i + 1 < edges.size(); ++i)
      if (std::abs(m.lambda) >= edges[i] && std::abs(m.lambda) < edges[i + 1]) {
        E[i] += 0.5 * m.transverse();
        T[i] += 0.5 * (m.H(3, 3) + m.H(4, 4)).real();
      }
  fmt::print("bands |lambda| (E = H_xx + H_yy, T = the axial offsets' trace; sums over lambda > 0):");
  for (std::size_t i = 0; i + 1 < edges.size(); ++i)
    fmt::print(" [{:g}, {}): E {:.4g} T {:.4g};", edges[i], i + 2 < edges.size() ? fmt::format("{:g}", edges[i + 1]) : "inf",
               E[i], T[i]);
  fmt::print("\n");
}

}  // namespace

int VolumeCommands::run_partial_fill(const VolumeTableRequest& request, const std::string& command_line) const {
  require_one_rank();
  const FreeSurfaceSurveySettings settings;
  const FreeSurfaceRunResult r = run_free_surface_modes(request.shape, request.mesh, settings,
                                                        print_progress);
  print_partial_fill(r, request.shape);
  if (common_.output.empty()) return 0;
  ModeTable t = free_surface_table(r, request.shape, settings);
  set_provenance(t, command_line);
  write_mode_table(t, common_.output);
  fmt::print("wrote {} ({} rows; chain-rom takes it on the first body of a fixed or a free chain: docs/volume.md §8)\n", common_.output, t.size());
  return 0;
}

namespace {

// The heaviest rows' frequencies of an ideal table.
std::vector<double> heaviest_rows(const ModeTable& t, int modes) {
  std::vector<std::size_t> order(t.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return t.E[i] > t.E[j]; });
  std::vector<double> out;
  for (std::size_t k = 0; k < order.size() && static_cast<int>(k) < modes; ++k) out.push_back(t.lambda[order[k]]);
  if (out.empty()) throw std::runtime_error("the ideal table has no mode to follow: give --target");
  return out;
}

// Rank 0's targets sent to the others (every rank must follow the same targets; two ranks' meshes could differ), or
// its error, so that every rank stops with it.
std::vector<double> shared_from_root(std::vector<double> out, std::string error) {
  int sizes[2] = {static_cast<int>(out.size()), static_cast<int>(error.size())};
  MPI_Bcast(sizes, 2, MPI_INT, 0, PETSC_COMM_WORLD);
  out.resize(sizes[0]);
  error.resize(sizes[1]);
  if (sizes[0] > 0) MPI_Bcast(out.data(), sizes[0], MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  if (sizes[1] > 0) MPI_Bcast(error.data(), sizes[1], MPI_CHAR, 0, PETSC_COMM_WORLD);
  if (!error.empty()) throw std::runtime_error(error);
  return out;
}

// The ideal table of the same cavity on the interior mesh (the same order and --mesh-size; no wall grading and no
// layers: the ideal fluid's), made by every rank together (the ideal 3-D path is distributed); rank 0's is the table.
ModeTable ideal_tensors_table(const VolumeTableRequest& ideal, const std::string& what_for) {
  Progress lines(print_progress);  // "[  1.2 s] ..." lines while it runs
  lines.note("3-D viscous: the ideal table first (" + what_for + ")");
  VolumeTableRequest request = ideal;
  request.fields = false;
  request.mesh.wall_size = 0;
  request.mesh.wall_layer = 0;
  request.mesh.near_wall_size = 0;
  return make_volume_table(request).table;
}

// A partially filled tank's ideal table on the interior mesh (the same order and --mesh-size, no wall grading), for
// its static parts: the frozen liquid, the surface's axis and Gram matrices (docs/volume.md §8). One rank.
ModeTable ideal_fill_table(const VolumeTableRequest& ideal) {
  require_one_rank();
  Progress lines(print_progress);
  lines.note("3-D viscous fill: the ideal table first (the liquid's tensors)");
  geometry::MeshOptions mesh = ideal.mesh;
  mesh.wall_size = 0;
  mesh.wall_layer = 0;
  mesh.near_wall_size = 0;
  const FreeSurfaceSurveySettings settings;
  const FreeSurfaceRunResult r = run_free_surface_modes(ideal.shape, mesh, settings);
  return free_surface_table(r, ideal.shape, settings);
}

// The damped modes' targets: those given; else, printing only, the ellipsoid's spin-over in closed form (any tilt);
// else the heaviest rows of the ideal table on the ideal mesh options, made by every rank together (the ideal 3-D
// path is distributed), which keeps it in `ideal_table` for a viscous table's tensors (made whenever one is written);
// rank 0's rows are the targets every rank follows.
std::vector<double> viscous_targets(const VolumeTableRequest& ideal, const std::vector<double>& given, int modes,
                                    bool table_wanted, std::optional<ModeTable>& ideal_table) {
  if (!table_wanted && !given.empty()) return given;
  if (!table_wanted && ideal.shape.kind == "ellipsoid") {
    const auto& d = ideal.shape.dims;
    return {ellipsoid_modes(d.at("a"), d.at("b"), d.at("c"), ideal.shape.tilt).lambda};
  }
  std::vector<double> out;
  std::string error;
  try {
    ideal_table = ideal_tensors_table(ideal, table_wanted ? "the cavity's tensors" : "the targets");
    out = given.empty() ? heaviest_rows(*ideal_table, modes) : given;
  } catch (const std::exception& e) {
    error = e.what();
  }
  return shared_from_root(std::move(out), std::move(error));
}

void print_viscous_report(const ViscousVolumeRequest& request, const ViscousVolumeResult& r) {
  std::cout << "3-D viscous modes at Ek = " << request.ekman << ": " << r.elements << " tetrahedra of order "
            << request.mesh.order << ", " << r.unknowns << " unknowns (" << r.velocity_unknowns << " velocity), "
            << r.seconds << " s\n";
  std::cout << "# target  lambda  decay  H_xx+H_yy (re, im)  H_zz (re, im)  residual  left_residual\n";
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const auto& m = r.modes[i];
    const std::complex<double> E = m.H(0, 0) + m.H(1, 1);
    std::cout << fmt::format("{:.6f}  {:.10f}  {:.10e}  {:.8e} {:+.3e}  {:.3e} {:+.3e}  {:.1e}  {:.1e}\n",
                             request.targets[i], m.lambda.real(), m.lambda.imag(), E.real(), E.imag(),
                             m.H(2, 2).real(), m.H(2, 2).imag(), m.residual, m.left_residual);
  }
  std::cout << std::flush;
}

}  // namespace

namespace {

// Every viscous run (damped modes, forced response, response table; filled or not) starts from the ideal request's
// shape and mesh with the Ekman number and the wall's default: the Ekman layers (about Ek^{1/2} thick) need elements
// of their order there, 2 Ek^{1/2} unless --wall-size is given (docs/volume.md §7). The ideal table keeps the ideal
// mesh.
template <class Request>
Request viscous_volume_request(const VolumeTableRequest& ideal, double ekman, double given_wall_size) {
  Request request;
  request.shape = ideal.shape;
  request.mesh = ideal.mesh;
  if (given_wall_size == 0) request.mesh.wall_size = 2 * std::sqrt(ekman);
  request.ekman = ekman;
  return request;
}

}  // namespace

int VolumeCommands::run_viscous(const VolumeTableRequest& ideal, const std::string& command_line) const {
  auto request = viscous_volume_request<ViscousVolumeRequest>(ideal, common_.ekman, common_.wall_size);
  const bool table_wanted = !common_.output.empty();
  std::optional<ModeTable> ideal_table;
  request.targets = viscous_targets(ideal, common_.targets, common_.modes, table_wanted, ideal_table);
  const ViscousVolumeResult result = solve_viscous_volume(request, print_progress);
  // The convergence check: the modes just found, again on a mesh 1.5 times as coarse (interior and wall sizes; the
  // layers' first thickness), each from its fine mode's frequency, so that row i meets row i.
  ViscousVolumeCheck check;
  std::optional<ViscousVolumeResult> coarse;
  if (table_wanted && common_.convergence_check) {
    ViscousVolumeRequest c = request;
    c.mesh.size = 1.5 * result.mesh_h;
    c.mesh.wall_size = 1.5 * request.mesh.wall_size;
    c.mesh.near_wall_size = 1.5 * request.mesh.near_wall_size;
    c.targets.clear();
    for (const auto& m : result.modes) c.targets.push_back(m.lambda.real());
    print_progress("3-D viscous: the convergence check on a mesh 1.5 times as coarse");
    coarse = solve_viscous_volume(c, print_progress);
    check = {&*coarse, fmt::format("the same order on a mesh 1.5 times as coarse (h = {:.4g}, wall {:.4g})",
                                   c.mesh.size, c.mesh.wall_size), common_.convergence_tolerance};
  }
  if (!is_root_rank()) return 0;
  print_viscous_report(request, result);
  if (table_wanted) {
    ModeTable table = viscous_volume_table(*ideal_table, request, result, check);
    set_provenance(table, command_line);
    write_mode_table(table, common_.output);
    std::cout << table_text(table) << std::flush;
  }
  return 0;
}

namespace {

// CSV: `#` lines (the method, the definition), then sigma_re, sigma_im and the nine complex entries R_jk (row-major:
// xx, xy, xz, yx, ...), each as _re and _im. Written to a temporary name and renamed (atomic_file.hpp), so no
// half-written file is left.
// A response's CSV: a header, then σ and every entry R_jk (re, im), the directions named by `names`.
template <class Matrix>
void write_response_csv(const std::string& path, const std::string& header, const std::vector<std::string>& names,
                        const std::vector<std::complex<double>>& sigmas, const std::vector<Matrix>& R) {
  write_text_atomically(path, [&](std::ostream& out) {
    out << header;
    out << "sigma_re,sigma_im";
    for (const auto& j : names)
      for (const auto& k : names) out << ",R_" << j << k << "_re,R_" << j << k << "_im";
    out << "\n";
    out.precision(17);
    const auto n = static_cast<Eigen::Index>(names.size());
    for (std::size_t i = 0; i < sigmas.size(); ++i) {
      out << sigmas[i].real() << ',' << sigmas[i].imag();
      for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index k = 0; k < n; ++k) out << ',' << R[i](j, k).real() << ',' << R[i](j, k).imag();
      out << '\n';
    }
  });
}

void write_volume_response(const std::string& path, const std::vector<std::complex<double>>& sigmas,
                           const ViscousVolumeResponse& r, const std::string& method) {
  write_response_csv(path, "# cavity-modes 3-D response: " + method + "\n# R_jk(sigma) = f_j^T (sigma M - A)^-1 f_k = "
                     "sum_l H_jk/(sigma - lambda_l) + const, the moment about e_j per unit rotation about e_k "
                     "(docs/volume.md, section 7)\n", {"x", "y", "z"}, sigmas, r.R);
}

}  // namespace

int VolumeCommands::run_response(const VolumeTableRequest& ideal) const {
  auto request = viscous_volume_request<ViscousVolumeResponseRequest>(ideal, common_.ekman, common_.wall_size);
  request.sigmas = parse_sigma_spec(common_.sigma, common_.sigma_imag);
  const ViscousVolumeResponse r = viscous_volume_response(request, print_progress);
  if (!is_root_rank()) return 0;
  const std::string method = fmt::format("viscous fluid at Ek = {}, forced solves on 3-D Taylor-Hood P{}/P{} ({} "
                                         "tetrahedra, {} unknowns, wall size {})", request.ekman, request.mesh.order,
                                         request.mesh.order - 1, r.elements, r.unknowns, request.mesh.wall_size);
  write_volume_response(common_.output, request.sigmas, r, method);
  std::cout << "3-D response: " << method << ", " << r.seconds << " s\n"
            << "# sigma  R_m1 = (R_xx + i R_xy - i R_yx + R_yy)/2 (re, im)  R_zz (re, im)  -> " << common_.output << "\n";
  const std::complex<double> I(0, 1);
  for (std::size_t i = 0; i < request.sigmas.size(); ++i) {
    const Eigen::Matrix3cd& R = r.R[i];
    const std::complex<double> m1 = 0.5 * (R(0, 0) + I * R(0, 1) - I * R(1, 0) + R(1, 1));
    std::cout << fmt::format("{:.6f}{:+.6f}i  {:.10e} {:+.10e}  {:.6e} {:+.6e}\n", request.sigmas[i].real(),
                             request.sigmas[i].imag(), m1.real(), m1.imag(), R(2, 2).real(), R(2, 2).imag());
  }
  std::cout << std::flush;
  return 0;
}

namespace {

void write_fill_response(const std::string& path, const std::vector<std::complex<double>>& sigmas,
                         const ViscousFillResponse& r, const std::string& method) {
  const std::string header = fmt::format(
      "# cavity-modes 3-D response of a partially filled tank: {}\n# R_jk(sigma) = G_j^T (sigma M - A)^-1 F_k over the "
      "directions Ux, Uy, Uz (rotations about P0 = ({}, {}, {}), the spin axis's point at the liquid's centroid's "
      "height) and Tx, Ty (P0 moved along the axis); about O = P0 - c z it is B R B^T, B = [I | c (e_x, e_y)] "
      "(docs/volume.md, section 8)\n", method, r.axis_point[0], r.axis_point[1], r.axis_point[2]);
  write_response_csv(path, header, {"Ux", "Uy", "Uz", "Tx", "Ty"}, sigmas, r.R);
}

}  // namespace

int VolumeCommands::run_fill_response(const VolumeTableRequest& ideal) const {
  require_one_rank();
  auto request = viscous_volume_request<ViscousVolumeResponseRequest>(ideal, common_.ekman, common_.wall_size);
  request.sigmas = parse_sigma_spec(common_.sigma, common_.sigma_imag);
  const ViscousFillResponse r = viscous_fill_response(request, print_progress);
  const std::string method = fmt::format("viscous liquid at Ek = {}, fill {}, free surface b = {:.10g}; forced solves "
                                         "on 3-D Taylor-Hood P{}/P{} ({} tetrahedra, {} unknowns, {} on the surface; wall size {})",
                                         request.ekman, request.shape.fill, r.surface_radius, request.mesh.order,
                                         request.mesh.order - 1, r.elements, r.unknowns, r.surface_unknowns,
                                         request.mesh.wall_size);
  write_fill_response(common_.output, request.sigmas, r, method);
  std::cout << "3-D fill response: " << method << ", " << r.seconds << " s\n"
            << "# sigma  R_UxUx (re, im)  R_UyUy (re, im)  R_UzUz (re, im)  R_TxTx (re, im)  -> " << common_.output << "\n";
  for (std::size_t i = 0; i < request.sigmas.size(); ++i) {
    const FillResponse& R = r.R[i];
    std::cout << fmt::format("{:.6f}{:+.6f}i", request.sigmas[i].real(), request.sigmas[i].imag());
    for (int k : {0, 1, 2, 3}) std::cout << fmt::format("  {:.8e} {:+.8e}", R(k, k).real(), R(k, k).imag());
    std::cout << "\n";
  }
  std::cout << std::flush;
  return 0;
}

int VolumeCommands::run_boundary_layer_response(const VolumeTableRequest& ideal) const {
  require_one_rank();
  const bool fill = ideal.shape.fill < 1;
  const VolumeSpace space(geometry::mesh_volume(ideal.shape, ideal.mesh), 0, !fill);
  const std::vector<std::complex<double>> sigmas = parse_sigma_spec(common_.sigma, common_.sigma_imag);
  Progress progress(print_progress);
  const BoundaryLayerResponse r = boundary_layer_response(
      space, common_.ekman, sigmas, [&](std::size_t done, std::size_t total) { progress.step("forced solves", done, total); });
  const std::string method = fmt::format(
      "ideal liquid with Ekman layers on its walls at Ek = {}{}; forced solves on 3-D P{} ({} tetrahedra, {} pressure "
      "unknowns, {} wall points)", common_.ekman,
      fill ? fmt::format(", fill {}, free surface b = {:.10g}", ideal.shape.fill, r.surface_radius) : std::string(),
      ideal.mesh.order, space.num_elements(), r.unknowns, r.wall_points);
  const std::vector<std::string> names = fill ? std::vector<std::string>{"Ux", "Uy", "Uz", "Tx", "Ty"}
                                              : std::vector<std::string>{"x", "y", "z"};
  write_response_csv(common_.output, fmt::format("# cavity-modes 3-D response: {}\n# R_jk(sigma), the viscous "
                                                 "response's to first order in Ek^(1/2), {} (docs/volume.md, section 9)\n",
                                                 method, fill ? fmt::format("over Ux, Uy, Uz, Tx, Ty about P0 = ({}, {}, {})",
                                                 r.origin[0], r.origin[1], r.origin[2]) : std::string("about the centroid")),
                     names, sigmas, r.R);
  std::cout << "3-D boundary-layer response: " << method << ", " << r.seconds << " s  -> " << common_.output << "\n";
  const std::complex<double> I(0, 1);
  for (std::size_t i = 0; i < sigmas.size(); ++i) {
    const Eigen::MatrixXcd& R = r.R[i];
    const std::complex<double> m1 = 0.5 * (R(0, 0) + I * R(0, 1) - I * R(1, 0) + R(1, 1));
    std::cout << fmt::format("{:.6f}{:+.6f}i  R_m1 {:.10e} {:+.10e}", sigmas[i].real(), sigmas[i].imag(), m1.real(),
                             m1.imag());
    if (fill) {
      const std::complex<double> gg = 0.5 * (R(3, 3) + I * R(3, 4) - I * R(4, 3) + R(4, 4));
      std::cout << fmt::format("  offset m1 {:.10e} {:+.10e}", gg.real(), gg.imag());
    }
    std::cout << "\n";
  }
  std::cout << std::flush;
  return 0;
}

namespace {

// An ideal table given for a boundary-layer table (--ideal-table): a 3-D one of this tank, its fill and spin axis.
ModeTable given_ideal_table(const std::string& path, const geometry::VolumeShapeSpec& shape) {
  ModeTable t = read_mode_table(path);
  const auto& vf = t.volume_free_surface;
  const bool fill = shape.fill < 1;
  const bool same = t.volume_cavity.present() && !t.viscous() && vf.present() == fill &&
                    (!fill || (std::abs(vf.fill - shape.fill) < 1e-9 && vf.axis.size() == 2 &&
                               std::abs(vf.axis[0] - shape.spin_axis[0]) < 1e-9 &&
                               std::abs(vf.axis[1] - shape.spin_axis[1]) < 1e-9));
  if (!same)
    throw std::runtime_error("--ideal-table " + path + " is not this tank's ideal 3-D table (make it with the same "
                             "command without --ekman, --boundary-layer and --sigma)");
  return t;
}

}  // namespace

int VolumeCommands::run_boundary_layer_table(const VolumeTableRequest& ideal, const std::string& command_line) const {
  require_one_rank();
  BoundaryLayerTableRequest request{ideal.shape, ideal.mesh, common_.ekman, {}, 0, 0};
  if (!common_.exact_at.empty()) request.exact_at = parse_sigma_spec(common_.exact_at, 0.0);
  const std::vector<std::complex<double>> window = parse_sigma_spec(common_.sigma, 0.0);
  request.lo = window.front().real();
  request.hi = window.back().real();
  if (!(request.lo >= 0 && request.hi > request.lo))
    throw std::runtime_error("a boundary-layer table's window --sigma FROM:TO:N is real, 0 <= FROM < TO");
  const ModeTable tensors = !common_.ideal_table.empty() ? given_ideal_table(common_.ideal_table, ideal.shape)
                            : ideal.shape.fill < 1      ? ideal_fill_table(ideal)
                                                        : ideal_tensors_table(ideal, "the ideal rows");
  BoundaryLayerTableResult r = boundary_layer_table(tensors, request);
  set_provenance(r.table, command_line);
  write_mode_table(r.table, common_.output);
  std::cout << table_text(r.table) << "boundary-layer table: " << r.table.solver << "; " << r.seconds << " s\n"
            << std::flush;
  return 0;
}

int VolumeCommands::run_response_table(const VolumeTableRequest& ideal, const std::string& command_line) const {
  auto request = viscous_volume_request<VolumeResponseTableRequest>(ideal, common_.ekman, common_.wall_size);
  for (const std::complex<double> s : parse_sigma_spec(common_.sigma, 0.0)) {
    if (s.imag() != 0 || !(s.real() >= 0)) throw std::runtime_error("a response table's window is real sigma >= 0 (the "
                                                                    "table holds -sigma by symmetry): " + common_.sigma);
    if (!request.window.empty() && !(s.real() > request.window.back()))
      throw std::runtime_error("a response table's window must increase: " + common_.sigma);
    request.window.push_back(s.real());
  }
  if (request.window.size() < 3) throw std::runtime_error("a response table's window needs at least 3 frequencies");
  request.krylov.tolerance = common_.max_fit_error;
  request.krylov.vectors_per_point = common_.krylov_vectors;
  if (!common_.exact_at.empty()) request.krylov.exact_at = parse_sigma_spec(common_.exact_at, 0.0);
  std::optional<ModeTable> ideal_table;
  std::string error;
  try {
    ideal_table = ideal.shape.fill < 1 ? ideal_fill_table(ideal) : ideal_tensors_table(ideal, "the cavity's tensors");
  } catch (const std::exception& e) {
    error = e.what();
  }
  shared_from_root({}, error);
  VolumeResponseTableResult r =
      viscous_volume_response_table(is_root_rank() ? &*ideal_table : nullptr, request, print_progress);
  if (!is_root_rank()) return 0;
  const VolumeKrylovReduction& k = r.reduction;
  if (!k.within_tolerance)
    std::cerr << fmt::format("cavity-modes: warning: after {} expansion points the response table errs by {:.2g}, above "
                             "--max-fit-error {:.2g}; it is written with that error (fit_error)\n", k.points.size(),
                             r.table.fit_error, request.krylov.tolerance);
  set_provenance(r.table, command_line);
  write_mode_table(r.table, common_.output);
  std::cout << fmt::format("3-D response table at Ek = {}: {} unknowns, {} expansion points, {} + {} basis vectors, "
                           "{} poles, {:.1f} s; error estimate {:.2g}, measured at s = {:.6g}: {:.2g}, rows against "
                           "the model {:.2g} (each relative to its entry's largest value on the window)\n",
                           request.ekman, r.unknowns, k.points.size(), k.primal_vectors, k.dual_vectors,
                           r.poles.size(), r.seconds, k.estimate, k.check_point, k.check_error, r.rows_error)
            << table_text(r.table) << std::flush;
  return 0;
}

}  // namespace rc::modes
