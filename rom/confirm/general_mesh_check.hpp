// The mesh error of the confirmed roots of a chain without axial symmetry (docs/rom.md, "Mesh error of confirmed
// roots", "Chains without axial symmetry"). A 3-D table's mesh refined by halving every size has eight times the
// unknowns, beyond this machine for the tables users make; so the check goes the other way: each viscous tank's 3-D
// response table is made again on a mesh `coarsen` times as coarse (interior, wall and near-wall sizes), the roots are
// confirmed with those tables as with the user's (confirm_general on a copy of the scene whose tables are the coarse
// ones), and each confirmed root's growth rate is compared with its coarse twin. The difference Δ is the coarse mesh's
// change; where the rate converges at order p in the element size, the table mesh's own error is |Δ| / (coarsen^p − 1).
// The bar is that at first order, |Δ| / (coarsen − 1) = 2|Δ| (mesh_error.hpp, two levels at ratio 1.5): an
// over-estimate once the layers are resolved (P2 and above converge faster), and what covers the under-resolved
// tables users start from (measured: a P2 table's nutation decay 0.02102 ± 0.0031 where finer tables converge to 0.0231;
// docs/rom.md, "Mesh error of confirmed roots"). A rate whose bar exceeds the tolerance is NOT CONVERGED.
//
// An axisymmetric Krylov table's meridian mesh halves at a quarter of the cost of a 3-D one, so its check goes up as
// (26)'s mesh study does: the table made again one level finer (cavity-modes response --mesh-level, every size halved),
// the roots confirmed on it, and the rate reported the finer tables' with the difference as its bar (two levels at
// ratio 2). A scene whose viscous tanks mix the two kinds has no one direction to check in: refused.
#pragma once

#include "general_confirmation.hpp"
#include "mesh_error.hpp"
#include "scene.hpp"
#include "table_refinement.hpp"

#include <complex>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rc::rom {

struct GeneralMeshCheck {
  bool finer = false;   // the check's tables one level finer (axisymmetric Krylov tables), else `coarsen` as coarse
  double coarsen = 1.5;
  std::vector<std::complex<double>> twins;  // each confirmed root's twin on the check's tables
  std::vector<MeshErrorEstimate> errors;    // per confirmed root, from the coarser of the two meshes to the finer
  int rounds = 0;                           // the check's tables' confirmation rounds
  bool all_converged() const;
  bool signs_settled() const;
};

// The check for the roots `confirmed` (confirm_general's with the same `all`, on the scene's own tables, which are left
// as they are): the check's tables made in `scratch` (3-D ones `coarsen` times as coarse, axisymmetric ones a level
// finer), their roots confirmed to `root_tolerance` (relative step), each
// confirmed root paired with the nearest coarse one and its rate
// judged against `tolerance` (relative) with `floor` (1/s, the spectrum's noise) as an absolute allowance. One line
// per table and round to `log`. Throws std::runtime_error when a check's table cannot be made, or the viscous tables
// mix 3-D and axisymmetric ones.
GeneralMeshCheck check_general_mesh(const Scene& scene, const std::vector<std::complex<double>>& confirmed, bool all,
                                    double coarsen, double tolerance, double floor, double root_tolerance,
                                    const std::string& binary, const std::filesystem::path& scratch,
                                    const ProgramRunner& run, std::ostream& log);

}  // namespace rc::rom
