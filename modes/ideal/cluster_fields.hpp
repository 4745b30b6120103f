// The fields of a table's modes at the mesh nodes (cavity-modes --fields; docs/modes.md "Fields").
//
// The cluster step keeps no eigenvectors, so each kept /modes row is re-solved here on its own narrow
// slice: every eigenpair within 2δ of the row's λ (δ = cluster_width · max(|λ|, 0.1), the cluster rule of
// docs/modes.md), the peak = the one of largest E, the members = those within δ of the peak. The cluster's
// field is the part of the coupling flow it carries,
//     W = Σ_l (a_l / N_l²) V_l,   a_l = (e1 × r, V_l),   N_l² = ‖V_l‖²   (docs/physics.md §2),
// independent of each eigenvector's scale and sign, and for a one-member cluster just its mode. W is
// normalised like the table (N² = 1, a ≥ 0). With the members' V orthogonal in the kinetic-energy inner
// product, a(W) = sqrt(Σ a_l²/N_l²) = sqrt(E/2): the stored a checks that.
//
// V from p (docs/physics.md §2, m = 1, ω0 = 1, D = 4 − λ²) in real amplitudes, V = (i v_r, v_φ, i v_z) e^{iφ}:
//     v_r = −(λ p_r + 2 p/r)/D,   v_φ = (2 p_r + λ p/r)/D,   v_z = p_z/λ,
// with p/r → p_r on the axis (p = 0 there). Gradients at a node are the mean over the elements sharing it.
#pragma once

#include "fe_space.hpp"
#include "mode_fields.hpp"
#include "mode_table.hpp"
#include "poincare_forms.hpp"
#include "qep_solver.hpp"

#include <functional>

namespace rc::modes {

struct FieldSettings {
  double cluster_width = 1e-5;  // δ relative to max(|λ|, 0.1): the cluster rule of docs/modes.md
  QepSettings qep;
};

// The mesh part of /fields: points (r, 0, z) of every node, straight sub-triangles through all Lagrange nodes (what
// XDMF shows), the FE triangles. Shared with the viscous fields.
void fill_fields_mesh(const geometry::MeridianMesh& mesh, ModeFields& fields);

// The mesh (points, sub-triangles, FE triangles) and one field per /modes row of `table`, which must have
// been computed on `space`. `progress` (may be empty) is told after each row. Throws std::runtime_error if
// a row's slice holds no eigenpair.
ModeFields cluster_fields(const FESpace& space, const PoincareForms& forms, const ModeTable& table,
                          const FieldSettings& settings,
                          const std::function<void(std::size_t done, std::size_t total)>& progress = {});

// One eigenvector (pressure dofs `p`, eigenvalue λ) times `weight`, with the `a` and `E` to store for it.
struct WeightedPressure {
  double lambda = 0;
  const std::vector<double>* p = nullptr;
  double weight = 1, a = 0, E = 0;
};

// The mesh part and, per entry, p, V (from p as above) and the kinetic-energy density at the mesh nodes: fields
// formed elsewhere (a partially filled tank's single pairs, free_surface_fields.hpp), the nodal gradients built once.
ModeFields weighted_mode_fields(const FESpace& space, const std::vector<WeightedPressure>& rows);

}  // namespace rc::modes
