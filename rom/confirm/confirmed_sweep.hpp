// A sweep whose key moves a viscous tank's Ekman number Ek = nu/(|spin| scale^2) (body[k].spin,
// system.spin_factor, body[k].cavity.scale): no one table holds along it, so each point's roots are those of
// Kononov's (22) with every viscous tank's own R(s) by forced solves at that point's Ek (a served cavity-modes per
// tank and point, on the table's mesh recipe: tank_responses.hpp), by the iteration of root_confirmation.hpp. Each
// point starts from the table's body and growing roots there (its modes scaled to that spin: only the Ekman number
// differs), and from the roots followed from the point before wherever no root confirmed from those is near, so
// that a root keeps being followed when the table stops showing it (docs/rom.md, "Spin sweeps with viscous tanks").
#pragma once

#include "mesh_error.hpp"
#include "mesh_study.hpp"
#include "scene.hpp"
#include "sweep.hpp"

#include <complex>
#include <filesystem>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace rc::rom {

// True when `key` changes the Ekman number of some viscous tank of `scene`.
bool moves_viscous_ekman(const Scene& scene, const ParamKey& key);

struct FollowedRoot {
  std::string owner;  // as the table's spectrum names it where the root was first found
  std::complex<double> sigma;
  bool converged = false;
};

struct ConfirmedSweepPoint {
  double value = 0;
  bool ok = false;
  std::string error;
  std::vector<double> ekman;  // per viscous tank, body order
  std::vector<FollowedRoot> roots;     // after a mesh study: on its finest level
  // The mesh study (empty: none): per root of `roots`, its growth rate's mesh error from the levels (mesh_error.hpp).
  std::vector<MeshErrorEstimate> errors;
  std::string mesh_failure;           // why the study stopped before its last level (empty: it did not)
  bool stable = false;
  double growth = 0;                  // largest -Im sigma over the confirmed roots (1/s)
  double growth_error = std::numeric_limits<double>::quiet_NaN();  // that root's mesh error (NaN: not measured)
  double noise = 0;                   // the spectrum's noise level: a growth below it is none (1/s)
  int growing = 0, unconfirmed = 0, solves = 0;
  double seconds = 0;
  bool mesh_measured() const { return !errors.empty(); }
  bool mesh_converged() const;        // every root's growth rate within the study's tolerance
  bool sign_settled() const;          // no root whose growth's sign the mesh error leaves open
};

// Runs the sweep point by point (serially: the forced solves are the work). A key that moves the Ekman numbers serves
// every point at its own (a served process per tank and point); any other key (sweep --confirm) serves each tank once
// for the whole sweep and confirms every point's body and growing roots with it. Then the mesh study (`study.refine`
// finer levels of each tank's mesh, as confirm's: docs/rom.md, "Mesh error of confirmed roots"): each point's roots
// iterated again on every level, per point where each point is served at its own Ek, else level by level for the
// whole sweep; each root then carries its growth rate's measured error.
// `log` gets the served meshes and one line per point. Throws SweepError for a value where a viscous tank does
// not spin (Ek undefined).
std::vector<ConfirmedSweepPoint> run_confirmed_sweep(const Scene& base, const SweepAxis& axis,
                                                     const std::string& cavity_modes, double tolerance,
                                                     const MeshStudy& study, std::ostream& log);

// One line of a sweep's progress: the point's value, its roots and verdict, `work` (what was run for it) and its time.
void log_sweep_point(std::ostream& log, const SweepAxis& axis, const ConfirmedSweepPoint& p, int index,
                     const std::string& work);

// The sweep CSV of write_sweep_csv (<key>,stable,margin,nonreal; margin = the largest growth rate, nonreal = the
// roots followed) with margin_error,mesh_converged after them (the mesh study's error of that rate and whether every
// root's is within the tolerance; nan where no study ran), and beside it OUT.roots.csv:
// <key>,owner,sigma_re,sigma_im,confirmed,growth_error,mesh_converged, one row per root and point.
void write_confirmed_sweep(const std::vector<ConfirmedSweepPoint>& points, const SweepAxis& axis,
                           const std::filesystem::path& out);

}  // namespace rc::rom
