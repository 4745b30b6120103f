// A 3-D cavity's viscous mode table (docs/volume.md §7, "The viscous table"): the damped modes as its rows, each with
// λ + i·decay and its coupling tensor H = (fᵀx)(fᵀy)ᵀ (not Hermitian: x, y the right and left eigenvectors), and the
// cavity's tensors — the frozen fluid's inertia, Zhukovsky's inertia, the tensor sum rule and the λ = 0 weight — from
// the ideal table of the same cavity (they are the Ek → 0 limits the rows' couplings are measured against).
#pragma once

#include "mode_table.hpp"
#include "viscous_volume_run.hpp"

#include <Eigen/Core>

#include <complex>
#include <string>

namespace rc::modes {

// The same modes on a coarser mesh, for the table's convergence columns: each row's relative change of λ + i·decay
// (dlambda) and of E + i·E_imag (dE) against the coarse mode of the same target, converged when both are below
// `tolerance` (docs/volume.md §7, "The viscous table and the chain").
struct ViscousVolumeCheck {
  const ViscousVolumeResult* coarse = nullptr;  // none: no convergence columns
  std::string reference;                        // the coarse mesh, in words
  double tolerance = 0;
};

// A viscous 3-D table's start: the cavity's tensors from the ideal table (`ideal`), the mesh's description; no rows.
ModeTable viscous_volume_table_start(const ModeTable& ideal, const geometry::MeshOptions& mesh, double mesh_h,
                                     int unknowns, double ekman);

// One row: λ + i·decay, its coupling tensor H (9 complex entries in /volume), E + i·E_imag = H_xx + H_yy (the
// axisymmetric viscous table's complex coupling, docs/volume.md §7), a + i·a_imag = √((E + i·E_imag)/2) with N2 = 1,
// κ = 2/λ (0 for a purely damped row, λ = 0).
void add_viscous_volume_row(ModeTable& t, std::complex<double> lambda, const Eigen::Matrix3cd& H, double residual);

// `ideal`: the ideal 3-D table of the same cavity (cavity-modes ellipsoid / volume without --ekman). Throws
// std::runtime_error when two targets found the same damped mode (it would be counted twice) or the table breaks one
// of its identities (ModeTable::validate).
ModeTable viscous_volume_table(const ModeTable& ideal, const ViscousVolumeRequest& request,
                               const ViscousVolumeResult& result, const ViscousVolumeCheck& check = {});

}  // namespace rc::modes
