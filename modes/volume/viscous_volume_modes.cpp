#include "viscous_volume_modes.hpp"

#include "viscous_eigensolver.hpp"

namespace rc::modes {

std::vector<DampedVolumeMode> damped_volume_modes(const ViscousVolumeForms& forms, std::complex<double> target,
                                                  int pairs) {
  ViscousSolveSettings settings;
  settings.pairs = pairs;
  settings.left_vectors = true;
  std::vector<DampedVolumeMode> out;
  for (const ViscousMode& m : viscous_modes_near(forms.forms, target, settings)) {
    DampedVolumeMode d;
    d.lambda = m.lambda;
    d.residual = m.residual;
    d.left_residual = m.left_residual;
    std::complex<double> right[3], left[3];
    for (int k = 0; k < 3; ++k) {
      right[k] = block_bilinear(forms.couplings[k], *m.block);
      left[k] = block_bilinear(forms.couplings[k], *m.left);
    }
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) d.H(j, k) = right[j] * left[k];
    out.push_back(d);
  }
  return out;
}

}  // namespace rc::modes
