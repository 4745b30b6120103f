// The fluid's moment response at complex frequencies by direct forced solves, no modes (docs/viscous.md,
// "Response function"):
//   R(σ) = π fᵀ (σ𝓜 − A)⁻¹ f = Σ_l E_l / (σ − λ_l) + (a constant from the pencil's infinite eigenvalues),
// with A, 𝓜, f of viscous_forms.hpp; its poles are the damped modes and their residues the table's E + i E_imag.
// σ − A is solved in the real block form (one MUMPS LU per σ).
#pragma once

#include "meridian_mesh.hpp"
#include "viscous_forms.hpp"

#include <complex>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace rc::modes {

// Called after each σ with (done, total).
using ResponseProgress = std::function<void(std::size_t, std::size_t)>;

// Throws std::runtime_error if a factorisation fails (σ on an eigenvalue, or a singular matrix).
std::vector<std::complex<double>> viscous_response(const ViscousForms& forms,
                                                   const std::vector<std::complex<double>>& sigmas,
                                                   const ResponseProgress& progress = {});

// A partially filled tank's response about a point at height −c below the liquid's centroid (docs/physics.md §2,
// "Partially filled tanks"): R(c) = R_ff + 2c R_fg + c² R_gg with R_xy = π xᵀ(σ𝓜 − A)⁻¹ y over the coupling f and the
// offset coupling g of viscous_forms.hpp; near a damped mode λ_c their residues are 2a_c², 2a_c t_c and 2t_c².
struct OffsetResponse {
  std::complex<double> ff, fg, gg;
};

// R(σ) one σ at a time, from one solver object that keeps the pattern and MUMPS's analysis across calls: for
// callers that choose the next σ from the last answer (a root iteration on Kononov's (22) with the fluid's own
// response: `cavity-modes response ... --serve`, which chain-rom confirm drives; docs/rom.md, "Confirmed roots").
// `forms` must outlive it. Throws std::runtime_error when a factorisation fails.
class ForcedResponse {
 public:
  explicit ForcedResponse(const ViscousForms& forms);
  ~ForcedResponse();
  ForcedResponse(const ForcedResponse&) = delete;
  ForcedResponse& operator=(const ForcedResponse&) = delete;
  std::complex<double> operator()(std::complex<double> sigma);
  // The three parts at σ (two solves on one factorisation); forms with a free surface only (std::logic_error else).
  OffsetResponse with_offset(std::complex<double> sigma);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The forced solutions x(σ) = (σ𝓜 − A)⁻¹ f themselves, in the block form of viscous_forms.hpp (distributed like the
// forms), one per σ: the responses' fields, a Galerkin basis (galerkin_response.hpp). R(σ) = π fᵀx(σ). With
// `offset_too` (forms with a free surface) each σ gives two, x(σ) then (σ𝓜 − A)⁻¹ g for the offset coupling g.
std::vector<std::shared_ptr<PVec>> forced_solutions(const ViscousForms& forms,
                                                    const std::vector<std::complex<double>>& sigmas,
                                                    const ResponseProgress& progress = {}, bool offset_too = false);

// A cavity's forms: meshes it (viscous_mesh_defaults must have resolved `mesh`) and assembles at `ekman` with z
// measured from the fluid centroid. Assemble once, then call viscous_response as often as needed (the response
// fit asks for more σ where its fit errs).
// `comm`: the matrices' communicator; PETSC_COMM_SELF gives every rank the whole problem (the mesh still comes from
// rank 0), for frequencies split between ranks (docs/viscous.md, "Response fit"). The mesh falls back as a table's does
// where gmsh cannot make the wall layers (viscous_mesh.hpp); `used` (rank 0's) receives the options it was made with.
ViscousForms assemble_cavity_forms(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh, double ekman,
                                   MPI_Comm comm = PETSC_COMM_WORLD, geometry::MeshOptions* used = nullptr);

// assemble_cavity_forms, then viscous_response at every σ. `unknowns` receives the real unknowns' count.
std::vector<std::complex<double>> cavity_response(const geometry::ShapeSpec& shape, geometry::MeshOptions mesh,
                                                  double ekman, const std::vector<std::complex<double>>& sigmas,
                                                  long* unknowns = nullptr, const ResponseProgress& progress = {});

}  // namespace rc::modes
