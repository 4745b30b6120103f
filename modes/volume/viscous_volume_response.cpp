#include "viscous_volume_response.hpp"

#include "shifted_solver.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace rc::modes {

std::vector<Eigen::Matrix3cd> forced_volume_response(const ViscousVolumeForms& forms,
                                                     const std::vector<std::complex<double>>& sigmas,
                                                     const std::function<void(std::size_t)>& done) {
  ShiftedSolver solver(forms.forms);
  PVec x;
  petsc_check(VecDuplicate(forms.couplings[0], x.out()), "VecDuplicate");
  std::vector<Eigen::Matrix3cd> out;
  for (std::size_t i = 0; i < sigmas.size(); ++i) {
    solver.factor(sigmas[i]);
    Eigen::Matrix3cd R;
    for (int k = 0; k < 3; ++k) {
      solver.solve(forms.couplings[k], x);
      for (int j = 0; j < 3; ++j) R(j, k) = block_bilinear(forms.couplings[j], x);
    }
    out.push_back(R);
    if (done) done(i + 1);
  }
  return out;
}

std::vector<FillResponse> forced_fill_response(const ViscousVolumeForms& forms,
                                               const std::vector<std::complex<double>>& sigmas,
                                               const std::function<void(std::size_t)>& done) {
  if (forms.fill_inputs.size() != 5) throw std::logic_error("a fill response needs a free surface's five directions");
  ShiftedSolver solver(forms.forms);
  PVec x;
  petsc_check(VecDuplicate(forms.fill_inputs[0], x.out()), "VecDuplicate");
  std::vector<FillResponse> out;
  for (const auto sigma : sigmas) {
    solver.factor(sigma);
    FillResponse R;
    for (int k = 0; k < 5; ++k) {
      solver.solve(forms.fill_inputs[k], x);
      for (int j = 0; j < 5; ++j) R(j, k) = block_bilinear(forms.fill_outputs[j], x);
    }
    out.push_back(R);
    if (done) done(out.size());
  }
  return out;
}

ViscousVolumeResponse viscous_volume_response(const ViscousVolumeResponseRequest& request,
                                              const std::function<void(const std::string&)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  if (request.sigmas.empty()) throw std::runtime_error("no frequency sigma given");
  for (const auto s : request.sigmas)
    if (!std::isfinite(s.real()) || !std::isfinite(s.imag())) throw std::runtime_error("every sigma must be finite");
  const ViscousVolumeSystem system = viscous_volume_system(request.shape, request.mesh, request.ekman, progress);
  ViscousVolumeResponse out;
  out.R = forced_volume_response(system.forms, request.sigmas, [&](std::size_t done) {
    if (progress) progress(fmt::format("3-D viscous response: {} of {} frequencies", done, request.sigmas.size()));
  });
  out.unknowns = system.space->size();
  out.elements = system.space->num_elements();
  out.mesh_h = system.space->geometry().mesh().size;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

ViscousFillResponse viscous_fill_response(const ViscousVolumeResponseRequest& request,
                                          const std::function<void(const std::string&)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  if (request.sigmas.empty()) throw std::runtime_error("no frequency sigma given");
  if (!(request.shape.fill < 1)) throw std::logic_error("a fill response is a partially filled tank's");
  const ViscousVolumeSystem system = viscous_volume_system(request.shape, request.mesh, request.ekman, progress);
  ViscousFillResponse out;
  out.R = forced_fill_response(system.forms, request.sigmas, [&](std::size_t done) {
    if (progress) progress(fmt::format("3-D viscous fill response: {} of {} frequencies", done, request.sigmas.size()));
  });
  out.axis_point = system.forms.axis_point;
  out.surface_radius = system.forms.surface_radius;
  out.unknowns = system.forms.forms.complex_size;
  out.surface_unknowns = system.forms.forms.complex_size - system.space->size();
  out.elements = system.space->num_elements();
  out.mesh_h = system.space->geometry().mesh().size;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace rc::modes
