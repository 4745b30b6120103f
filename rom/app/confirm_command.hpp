// `chain-rom confirm SCENE`: the chain's roots checked against the viscous tanks' own response. Each root that a
// verdict rests on (every body root and every growing root; --all: every root) is taken as the start of the
// iteration of root_confirmation.hpp with R(s) from forced solves on each table's own mesh (served_response.hpp),
// and the verdict is given again from the confirmed roots (docs/rom.md, "Confirmed roots").
#pragma once

#include "mesh_study.hpp"
#include "scene.hpp"
#include "table_refinement.hpp"

#include <ostream>
#include <string>

namespace rc::rom {

struct ConfirmRequest {
  std::string cavity_modes;  // the binary; empty: cavity_modes_binary's search
  bool all = false;          // every root, not only the body roots and the growing ones
  double tolerance = 1e-10;  // relative step at which a root counts as converged
  bool json = false;
  // Remake each viscous tank's Krylov response table with R exact at the confirmed roots (table_refinement.hpp),
  // then say how far the new tables' roots are from the confirmed ones. `run` starts cavity-modes.
  bool refine_tables = false;
  ProgramRunner run;
  // The mesh study (docs/rom.md, "Mesh error of confirmed roots"): the roots again on `mesh.refine` finer levels of
  // each tank's mesh (1 by default; 0: the table's mesh only), and each growth rate with its mesh error.
  MeshStudy mesh;
};

// Prints the tanks' forced-solve meshes, one line per root as it is confirmed, the same on each level of the mesh
// study, each selected root's growth rate with its mesh error, and the verdict from the confirmed roots on the finest
// level with whether the mesh has converged them. Returns the number of roots that could not be confirmed. Throws std::runtime_error / SceneError on a bad
// scene or a cavity-modes that cannot start.
int confirm_roots(const Scene& scene, const ConfirmRequest& request, std::ostream& os);

// The same for a chain without axial symmetry, whose viscous tanks are 3-D response tables: with --refine-tables
// only (the tables are remade exact at the roots until the roots stop moving; general_confirmation.hpp). Returns the
// number of roots that did not settle.
int confirm_general_roots(const Scene& scene, const ConfirmRequest& request, std::ostream& os);

}  // namespace rc::rom
