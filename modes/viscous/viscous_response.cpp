#include "viscous_response.hpp"

#include "mesh_broadcast.hpp"
#include "petsc_handles.hpp"
#include "shifted_solver.hpp"
#include "poincare_forms.hpp"
#include "taylor_hood_space.hpp"
#include "viscous_memory.hpp"
#include "viscous_mesh.hpp"

#include <numbers>
#include <stdexcept>
#include <string>

namespace rc::modes {

namespace {

// π fᵀx for the block form x = a + ib: the coupling vector f sits on the real slots only.
std::complex<double> moment_of(Vec f, Vec x) { return std::numbers::pi * block_bilinear(f, x); }

}  // namespace

std::vector<std::shared_ptr<PVec>> forced_solutions(const ViscousForms& forms,
                                                    const std::vector<std::complex<double>>& sigmas,
                                                    const ResponseProgress& progress, bool offset_too) {
  if (offset_too && !forms.offset_coupling) throw std::logic_error("offset solutions need a free surface's coupling");
  std::vector<std::shared_ptr<PVec>> out;
  ShiftedSolver solver(forms);
  const auto solve = [&](Vec input) {
    auto x = std::make_shared<PVec>();
    petsc_check(VecDuplicate(forms.coupling, x->out()), "VecDuplicate");
    solver.solve(input, *x);
    out.push_back(std::move(x));
  };
  for (std::size_t k = 0; k < sigmas.size(); ++k) {
    solver.factor(sigmas[k]);
    solve(forms.coupling);
    if (offset_too) solve(forms.offset_coupling);
    if (progress) progress(k + 1, sigmas.size());
  }
  return out;
}

struct ForcedResponse::State {
  const ViscousForms& forms;
  ShiftedSolver solver;
  PVec x;
  explicit State(const ViscousForms& f) : forms(f), solver(f) {
    petsc_check(VecDuplicate(f.coupling, x.out()), "VecDuplicate");
  }
};

ForcedResponse::ForcedResponse(const ViscousForms& forms) : state_(std::make_unique<State>(forms)) {}
ForcedResponse::~ForcedResponse() = default;

std::complex<double> ForcedResponse::operator()(std::complex<double> sigma) {
  state_->solver.factor(sigma);
  state_->solver.solve(state_->forms.coupling, state_->x);
  return moment_of(state_->forms.coupling, state_->x);
}

OffsetResponse ForcedResponse::with_offset(std::complex<double> sigma) {
  const ViscousForms& forms = state_->forms;
  if (!forms.offset_coupling) throw std::logic_error("an offset response needs a free surface's offset coupling");
  state_->solver.factor(sigma);
  state_->solver.solve(forms.coupling, state_->x);
  OffsetResponse r;
  r.ff = moment_of(forms.coupling, state_->x);
  r.fg = moment_of(forms.offset_coupling, state_->x);  // the pencil is complex symmetric: gᵀ(σ𝓜 − A)⁻¹f = fᵀ(…)⁻¹g
  state_->solver.solve(forms.offset_coupling, state_->x);
  r.gg = moment_of(forms.offset_coupling, state_->x);
  return r;
}

std::vector<std::complex<double>> viscous_response(const ViscousForms& forms,
                                                   const std::vector<std::complex<double>>& sigmas,
                                                   const ResponseProgress& progress) {
  std::vector<std::complex<double>> out;
  ForcedResponse response(forms);
  for (const auto sigma : sigmas) {
    out.push_back(response(sigma));
    if (progress) progress(out.size(), sigmas.size());
  }
  return out;
}

ViscousForms assemble_cavity_forms(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh, double ekman,
                                   MPI_Comm comm, geometry::MeshOptions* used) {
  geometry::MeshOptions made = mesh;
  const TaylorHoodSpace space(mesh_on_root([&] { return viscous_mesh(shape, made); }, PETSC_COMM_WORLD));
  if (used) *used = made;
  // Refused here rather than killed by the system in the factorisation: every rank holds a copy on PETSC_COMM_SELF.
  refuse_viscous_beyond_memory(2L * space.size(), comm == PETSC_COMM_SELF ? world_ranks() : 1, mesh_text(made));
  const double centroid_z = integrate_fluid(space.geometry()).centroid_z;
  return assemble_viscous_forms(space, centroid_z, ekman, comm);
}

std::vector<std::complex<double>> cavity_response(const geometry::ShapeSpec& shape, geometry::MeshOptions mesh,
                                                  double ekman, const std::vector<std::complex<double>>& sigmas,
                                                  long* unknowns, const ResponseProgress& progress) {
  const ViscousForms forms = assemble_cavity_forms(shape, mesh, ekman);
  if (unknowns) *unknowns = 2L * forms.complex_size;
  return viscous_response(forms, sigmas, progress);
}

}  // namespace rc::modes
