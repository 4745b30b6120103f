#include "volume_fluid.hpp"

namespace rc::rom {

void VolumeFluid::finish() {
  share = geostrophic;
  for (const auto& m : modes) share += 2 * (m.c * m.c_left.transpose()).real();
}

Eigen::Vector3d volume_momentum(const VolumeFluid& f, const Eigen::Vector3d& Omega, const std::complex<double>* z) {
  Eigen::Vector3d h = -f.geostrophic * (Omega - f.reference_spin * Eigen::Vector3d::UnitZ());
  for (int l = 0; l < f.size(); ++l) h += 2 * (z[l] * f.modes[l].c).real();
  return h;
}

Eigen::Vector3d volume_moment(const VolumeFluid& f, const Eigen::Vector3d& Omega, const std::complex<double>* z) {
  const std::complex<double> i(0, 1);
  const double spin = Omega.z();
  Eigen::Vector3d m = -Omega.cross(volume_momentum(f, Omega, z));
  for (int l = 0; l < f.size(); ++l) m -= 2 * (i * f.modes[l].lambda(spin) * z[l] * f.modes[l].c).real();
  return m;
}

void volume_rates(const VolumeFluid& f, const Eigen::Vector3d& Omega, const Eigen::Vector3d& Omega_dot,
                  const std::complex<double>* z, std::vector<std::complex<double>>& out) {
  const std::complex<double> i(0, 1);
  const Eigen::Vector3cd acceleration = Omega_dot.cast<std::complex<double>>();
  for (int l = 0; l < f.size(); ++l)
    out.push_back(i * f.modes[l].lambda(Omega.z()) * z[l] - f.modes[l].c_left.cwiseProduct(acceleration).sum());
}

}  // namespace rc::rom
