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
  double coarsen = 1.5;
  std::vector<std::complex<double>> coarse;  // each confirmed root's twin on the coarse tables
  std::vector<MeshErrorEstimate> errors;     // per confirmed root: {coarse, table mesh}
  int rounds = 0;                            // the coarse tables' confirmation rounds
  bool all_converged() const;
  bool signs_settled() const;
};

// The check for the roots `confirmed` (confirm_general's with the same `all`, on the scene's own tables, which are left
// as they are): the coarse tables made in `scratch`, their roots confirmed to `root_tolerance` (relative step), each
// confirmed root paired with the nearest coarse one and its rate
// judged against `tolerance` (relative) with `floor` (1/s, the spectrum's noise) as an absolute allowance. One line
// per table and round to `log`. Throws std::runtime_error when a coarse table cannot be made.
GeneralMeshCheck check_general_mesh(const Scene& scene, const std::vector<std::complex<double>>& confirmed, bool all,
                                    double coarsen, double tolerance, double floor, double root_tolerance,
                                    const std::string& binary, const std::filesystem::path& scratch,
                                    const ProgramRunner& run, std::ostream& log);

}  // namespace rc::rom
