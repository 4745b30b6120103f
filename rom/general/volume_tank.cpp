#include "volume_tank.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>

namespace rc::rom {
namespace {

[[noreturn]] void fail(const Scene& s, const std::string& key, const std::string& cause) {
  throw SceneError(s.file.string() + ": " + key + ": " + cause);
}

using RowMajor3d = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

Eigen::Matrix3d tensor(const std::vector<double>& v) { return Eigen::Map<const RowMajor3d>(v.data()); }

Eigen::Matrix3cd row_coupling(const rc::ModeTable::Volume& v, std::size_t l) {
  Eigen::Matrix3cd H;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) H(i, j) = {v.coupling_re[9 * l + 3 * i + j], v.coupling_im[9 * l + 3 * i + j]};
  return H;
}

// What the general chain takes of a tank's keys so far: an ideal modal tank on the body's axis.
void require_ideal_modal(const Scene& scene, const std::string& w, const CavitySpec& cav, const rc::ModeTable& t) {
  const std::string later = ": not for a 3-D tank yet (docs/rom.md, \"Bodies and tanks without axial symmetry\")";
  if (cav.viscosity || t.viscous()) fail(scene, w + ".viscosity", "a viscous tank" + later);
  if (cav.static_correction) fail(scene, w + ".static_correction", "the static correction" + later);
  if (cav.galerkin) fail(scene, w + ".reduction", "the Galerkin reduction" + later);
  if (!cav.companion.empty()) fail(scene, w + ".companion", "a companion table" + later);
  const auto& c = t.volume_cavity.centroid;
  const double size = std::cbrt(t.volume);
  if (cav.origin && std::hypot(c[0], c[1]) > 1e-9 * size)
    fail(scene, w + ".origin", "the table's cavity is off the spin axis (centroid x, y = " + std::to_string(c[0]) +
                                   ", " + std::to_string(c[1]) + "): place it with `center` (its modes do not depend "
                                   "on where it sits); several tanks off a body's axis are not in the scene yet");
}

// The rows kept, heaviest first by the trace of H: every coupling one, or the first `modes`, or as many as reach
// `coverage` of the sum rule's trace (the geostrophic weight counted as always kept).
std::vector<int> kept_volume_rows(const Scene& scene, const std::string& w, const CavitySpec& cav,
                                  const rc::ModeTable& t) {
  const rc::ModeTable::Volume& v = t.volume_cavity;
  const double total = tensor(v.sum_rule).trace();
  std::vector<double> weight(t.size());
  std::vector<int> idx;
  for (std::size_t l = 0; l < t.size(); ++l) {
    weight[l] = 2 * row_coupling(v, l).trace().real();  // both signs of λ
    if (weight[l] > 1e-14 * total) idx.push_back(static_cast<int>(l));
  }
  std::stable_sort(idx.begin(), idx.end(), [&](int i, int j) { return weight[i] > weight[j]; });
  std::size_t keep = idx.size();
  if (cav.modes) {
    if (static_cast<std::size_t>(*cav.modes) > idx.size())
      fail(scene, w + ".modes", std::to_string(*cav.modes) + " requested, the table " + cav.table.filename().string() +
                                    " holds " + std::to_string(idx.size()) + " coupling modes");
    keep = *cav.modes;
  } else if (cav.coverage) {
    double acc = tensor(v.geostrophic_re).trace();
    keep = 0;
    while (keep < idx.size() && acc < *cav.coverage * total * (1 - 1e-12)) acc += weight[idx[keep++]];
    if (acc < *cav.coverage * total * (1 - 1e-12)) {
      std::ostringstream os;
      os << "coverage " << *cav.coverage << " not reachable: the table's modes cover " << acc / total;
      fail(scene, w + ".coverage", os.str());
    }
  }
  idx.resize(keep);
  return idx;
}

// A row's H = Σ_j μ_j u_j u_jᴴ as rank-one couplings c_j = √μ_j u_j (one per discrete copy the row's cluster sums).
void add_row_modes(int k, int row, const Eigen::Matrix3cd& H, double lambda, double unit, VolumeTank& tank) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3cd> es(H);
  const double top = es.eigenvalues().maxCoeff();
  for (int j = 0; j < 3; ++j) {
    const double mu = es.eigenvalues()[j];
    if (!(mu > 1e-12 * top)) continue;
    tank.modes.push_back({k, row, lambda, std::sqrt(mu * unit) * es.eigenvectors().col(j)});
  }
}

}  // namespace

VolumeTank volume_tank(const Scene& scene, int k, const rc::ModeTable& t) {
  const BodySpec& b = scene.bodies[k];
  const CavitySpec& cav = *b.cavity;
  const std::string w = "body[" + std::to_string(k + 1) + "].cavity";
  require_ideal_modal(scene, w, cav, t);
  const rc::ModeTable::Volume& v = t.volume_cavity;
  const double L = cav.scale, unit = cav.density * std::pow(L, 5);  // ρL⁵: the table's inertias to kg m²
  VolumeTank tank;
  tank.mass = cav.density * L * L * L * t.volume;
  tank.center = cav.origin ? *cav.origin + L * v.centroid[2] : cav.center;
  // About O_k: the parallel-axis shift along the axis adds m d² to the transverse moments only.
  tank.inertia = unit * tensor(v.inertia);
  tank.inertia(0, 0) += tank.mass * tank.center * tank.center;
  tank.inertia(1, 1) += tank.mass * tank.center * tank.center;
  // The λ = 0 space is real (V and V̄ both in it): its weight is real symmetric up to the table's rounding.
  tank.geostrophic = unit * tensor(v.geostrophic_re);
  tank.geostrophic = 0.5 * (tank.geostrophic + tank.geostrophic.transpose()).eval();
  double kept = tank.geostrophic.trace() / unit;
  for (const int l : kept_volume_rows(scene, w, cav, t)) {
    const Eigen::Matrix3cd H = row_coupling(v, l);
    kept += 2 * H.trace().real();
    add_row_modes(k, l, H, b.spin * t.lambda[l], unit, tank);
  }
  tank.coverage = kept / tensor(v.sum_rule).trace();
  if (!tank.inertia.allFinite() || !(tank.mass > 0))
    fail(scene, w + ".table", "non-physical 3-D table (volume or inertia not positive and finite)");
  return tank;
}

}  // namespace rc::rom
