// The mesh study of `chain-rom confirm` (docs/rom.md, "Mesh error of confirmed roots"): the confirmed roots again on
// finer levels of each viscous tank's mesh family (every size halved per level: cavity-modes response --mesh-level),
// each level's roots iterated from the level before's, and from the levels each root's growth rate with its
// measured mesh error (mesh_error.hpp).
#pragma once

#include "chain_model.hpp"
#include "mesh_error.hpp"
#include "root_confirmation.hpp"
#include "scene.hpp"
#include "served_response.hpp"

#include <complex>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rc::rom {

// A growth rate's relative mesh error above which `confirm` says "not converged" unless --mesh-tolerance says otherwise.
inline constexpr double kDefaultMeshTolerance = 0.02;

struct MeshStudy {
  ServedMesh base;          // level 0: the table's mesh, or the one --mesh-size/--order give
  int refine = 1;           // finer levels after level 0; 0: no study
  bool by_order = false;    // each level raises the Taylor-Hood order by one instead of halving every size
  double tolerance = kDefaultMeshTolerance;  // relative error of a growth rate above which it is "not converged"
  // Per body, the Ekman number whose wall layers every level's mesh is made for (a sweep over spin: its smallest,
  // so that each level is one mesh for the whole sweep); empty or 0: the served Ek's own, as the tables'.
  std::vector<double> mesh_ekman;
};

struct MeshStudyResult {
  // levels[l][j]: root j on level l (level 0 the roots given); NaN where a level's iteration did not converge.
  std::vector<std::vector<std::complex<double>>> levels;
  std::vector<long> unknowns;          // the first tank's real unknowns per level (0 where it names none)
  // Per level: the largest |R_fg| / sqrt(|R_ff R_gg|) at the roots over the mirror-symmetric partially filled tanks,
  // which vanishes for the liquid itself (NaN: no such tank).
  std::vector<double> symmetry_defect;
  std::vector<MeshErrorEstimate> errors;  // per root, from every level that converged
  std::string failure;                 // why the study stopped before its last level (empty: it did not)
  bool by_order = false;               // the levels raised the order (MeshStudy::by_order)
  int solves = 0;
  bool all_converged() const;          // every root's rate within the tolerance
  bool signs_settled() const;          // no root whose growth's sign the mesh error leaves open
};

// The largest |R_fg| / sqrt(|R_ff R_gg|) at `roots` over the tanks whose liquid is mirror-symmetric (R_fg = 0 for the
// liquid itself: what the forced solves give measures the mesh's asymmetry); NaN when no tank is. One forced solve per
// root and tank.
double symmetry_defect(const ChainModel& m, const std::vector<TankResponse>& tanks,
                       const std::vector<std::complex<double>>& roots);

// The served mesh of level `level` of the study (0: its base, the tables' unless --mesh-size/--order): every size halved
// `level` times, or the order raised by `level` (MeshStudy::by_order).
ServedMesh level_mesh(const MeshStudy& study, int level);

// "mesh level 1 (every size of level 0 halved 1 time; a spectral table's truncation raised 1.5 times as often):",
// the heading of a level's lines in the log.
std::string level_title(int level, bool by_order);

// Each root of `before` (NaN: skipped) iterated on (22) with `tanks`' R from its value there, one line per root to
// `log`: the root where its iteration converged, NaN where it did not. One level of a mesh study.
std::vector<std::complex<double>> iterate_roots(const ChainModel& m, const std::vector<TankResponse>& tanks,
                                                const std::vector<std::complex<double>>& before,
                                                const ConfirmSettings& settings, std::ostream& log);

// Root j's mesh error from its values levels[0][j], levels[1][j], ... up to the first level where it did not converge
// (mesh_error.hpp); a root with one level only has an infinite error (nothing measured).
std::vector<MeshErrorEstimate> level_errors(const std::vector<std::vector<std::complex<double>>>& levels,
                                            const MeshStudy& study, double floor);

// Levels 1 .. study.refine: every viscous tank served on the level (the level before shut first, so that one level's
// factorisations are in memory at a time), each root of `level0` iterated from its value on the level before.
// Writes each level's served meshes and roots to `log`. A level that cannot be served (a mesh beyond the machine, a
// failed factorisation) ends the study: `failure` says why, and the errors come from the levels before (a root with
// one level only has an infinite error). `floor` is the spectrum's noise level (1/s).
MeshStudyResult study_mesh(const Scene& scene, const ChainModel& m, const std::vector<std::complex<double>>& level0,
                           const std::vector<long>& level0_unknowns, double level0_symmetry, const MeshStudy& study, const std::string& binary,
                           const std::filesystem::path& scratch, const ConfirmSettings& settings, double floor,
                           std::ostream& log);

}  // namespace rc::rom
