#include "mesh_study.hpp"

#include "root_confirmation.hpp"
#include "tank_responses.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rc::rom {
namespace {
using cd = std::complex<double>;
const cd kMissing{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};

bool known(cd z) { return std::isfinite(z.real()) && std::isfinite(z.imag()); }

// Root j's values on the levels where it converged, from level 0 up to the first level where it did not.
std::vector<cd> converged_levels(const std::vector<std::vector<cd>>& levels, std::size_t j) {
  std::vector<cd> out;
  for (const auto& level : levels) {
    if (!known(level[j])) break;
    out.push_back(level[j]);
  }
  return out;
}

// One level: the tanks served on it and every root iterated from the level before's value.
std::vector<cd> confirm_level(const Scene& scene, const ChainModel& m, const std::vector<cd>& before, int level,
                              const MeshStudy& study, const std::string& binary,
                              const std::filesystem::path& scratch, const ConfirmSettings& settings,
                              std::ostream& log, MeshStudyResult& r) {
  log << level_title(level, study.by_order) << std::endl;
  TankResponses tanks = serve_tanks(scene, m, binary, scratch, log, study.mesh_ekman, nullptr, level_mesh(study, level));
  r.unknowns.push_back(tanks.served.empty() ? 0 : tanks.served.front()->unknowns());
  std::vector<cd> out = iterate_roots(m, tanks.responses, before, settings, log);
  r.symmetry_defect.push_back(symmetry_defect(m, tanks.responses, out));
  r.solves += tanks.solves();
  return out;
}

}  // namespace

ServedMesh level_mesh(const MeshStudy& study, int level) {
  ServedMesh mesh = study.base;
  if (level == 0) return mesh;
  if (study.by_order) mesh.order_raise = level;
  else mesh.level = level;
  return mesh;
}

std::string level_title(int level, bool by_order) {
  std::ostringstream os;
  if (by_order) os << "mesh level " << level << " (the order of level 0 raised by " << level << "):";
  else os << "mesh level " << level << " (every size of level 0 halved " << level << (level == 1 ? " time" : " times")
          << "; a spectral table's truncation raised 1.5 times as often):";
  return os.str();
}

std::vector<cd> iterate_roots(const ChainModel& m, const std::vector<TankResponse>& tanks, const std::vector<cd>& before,
                              const ConfirmSettings& settings, std::ostream& log) {
  std::vector<cd> out(before.size(), kMissing);
  for (std::size_t j = 0; j < before.size(); ++j) {
    if (!known(before[j])) continue;
    const ConfirmedRoot root = confirm_root(m, tanks, before[j], settings);
    log << "  " << std::setw(34) << root_text(before[j]) << "  ->  " << std::setw(34) << root_text(root.sigma)
        << std::setprecision(2) << "  moved " << root.moved() << ", " << root.evaluations << " evaluations"
        << (root.converged ? "" : "  NOT CONFIRMED: " + root.failure) << std::endl;
    if (root.converged) out[j] = root.sigma;
  }
  return out;
}

std::vector<MeshErrorEstimate> level_errors(const std::vector<std::vector<cd>>& levels, const MeshStudy& study,
                                            double floor) {
  std::vector<MeshErrorEstimate> errors;
  for (std::size_t j = 0; j < (levels.empty() ? 0 : levels.front().size()); ++j) {
    const std::vector<cd> values = converged_levels(levels, j);
    if (values.size() >= 2) {
      errors.push_back(mesh_error(values, study.tolerance, floor, !study.by_order));
      continue;
    }
    MeshErrorEstimate none;  // one level only: nothing measured
    none.sigma = values.empty() ? kMissing : values.front();
    none.growth = -none.sigma.imag();
    none.extrapolated = none.growth;
    none.error = std::numeric_limits<double>::infinity();
    errors.push_back(none);
  }
  return errors;
}

bool MeshStudyResult::all_converged() const {
  return !errors.empty() && std::all_of(errors.begin(), errors.end(), [](const auto& e) { return e.converged; });
}

bool MeshStudyResult::signs_settled() const {
  return std::all_of(errors.begin(), errors.end(), [](const auto& e) { return e.sign_settled; });
}

double symmetry_defect(const ChainModel& m, const std::vector<TankResponse>& tanks, const std::vector<cd>& roots) {
  double worst = std::numeric_limits<double>::quiet_NaN();
  for (const TankResponse& t : tanks) {
    if (!t.mirror_symmetric || !t.R_offset) continue;
    const double w = m.bodies[t.body].omega;
    for (const cd& sigma : roots) {
      if (!known(sigma)) continue;
      cd s = (sigma + w) / w;
      if (w < 0) s = std::conj(s);  // a negative spin mirrors the flow (root_confirmation.hpp)
      const auto R = t.R_offset(s);
      const double d = std::abs(R[1]) / std::sqrt(std::abs(R[0]) * std::abs(R[2]));
      worst = std::isnan(worst) ? d : std::max(worst, d);
    }
  }
  return worst;
}

MeshStudyResult study_mesh(const Scene& scene, const ChainModel& m, const std::vector<cd>& level0,
                           const std::vector<long>& level0_unknowns, double level0_symmetry, const MeshStudy& study, const std::string& binary,
                           const std::filesystem::path& scratch, const ConfirmSettings& settings, double floor,
                           std::ostream& log) {
  MeshStudyResult r;
  r.by_order = study.by_order;
  r.levels.push_back(level0);
  r.unknowns.push_back(level0_unknowns.empty() ? 0 : level0_unknowns.front());
  r.symmetry_defect.push_back(level0_symmetry);
  for (int level = 1; level <= study.refine; ++level) {
    try {
      r.levels.push_back(confirm_level(scene, m, r.levels.back(), level, study, binary, scratch, settings, log, r));
    } catch (const std::exception& e) {
      r.failure = "mesh level " + std::to_string(level) + " could not be served: " + e.what();
      log << "  " << r.failure << std::endl;
      break;
    }
  }
  r.errors = level_errors(r.levels, study, floor);
  return r;
}

}  // namespace rc::rom
