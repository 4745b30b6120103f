#include "general_mesh_check.hpp"

#include "mode_table.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace rc::rom {
namespace fs = std::filesystem;
namespace {
using cd = std::complex<double>;

// The scene with each viscous table replaced by a coarse one made in `scratch` (each file once, however many tanks
// share it).
Scene with_coarse_tables(const Scene& scene, double coarsen, const std::string& binary, const fs::path& scratch,
                         const ProgramRunner& run, std::ostream& log) {
  Scene copy = scene;
  std::map<fs::path, fs::path> coarse;
  const auto replace = [&](fs::path& table) {
    if (!rc::read_mode_table(table).viscous()) return;
    auto it = coarse.find(table);
    if (it == coarse.end()) {
      const fs::path out = scratch / ("coarse" + std::to_string(coarse.size() + 1) + ".h5");
      log << "  " << table.string() << ": made again on a mesh " << coarsen << " times as coarse" << std::endl;
      remake_coarser(table, coarsen, out, binary, scratch, run);
      it = coarse.emplace(table, out).first;
    }
    table = it->second;
  };
  for (auto& body : copy.bodies) {
    if (body.cavity) replace(body.cavity->table);
    for (auto& c : body.more_cavities) replace(c.table);
  }
  return copy;
}

}  // namespace

bool GeneralMeshCheck::all_converged() const {
  return !errors.empty() && std::all_of(errors.begin(), errors.end(), [](const auto& e) { return e.converged; });
}

bool GeneralMeshCheck::signs_settled() const {
  return std::all_of(errors.begin(), errors.end(), [](const auto& e) { return e.sign_settled; });
}

GeneralMeshCheck check_general_mesh(const Scene& scene, const std::vector<cd>& confirmed, bool all, double coarsen,
                                    double tolerance, double floor, double root_tolerance, const std::string& binary,
                                    const fs::path& scratch, const ProgramRunner& run, std::ostream& log) {
  GeneralMeshCheck out;
  out.coarsen = coarsen;
  log << "the mesh check: the tables on a mesh " << coarsen << " times as coarse, their roots confirmed as above"
      << std::endl;
  const Scene coarse = with_coarse_tables(scene, coarsen, binary, scratch, run, log);
  const GeneralConfirmation c = confirm_general(coarse, all, root_tolerance, binary, scratch, run, log);
  out.rounds = c.rounds;
  const std::vector<cd>& candidates = c.confirmed.empty() ? c.spectrum.roots : c.confirmed;
  for (const cd& fine : confirmed) {
    const cd twin = candidates.empty() ? cd(NAN, NAN)
                                       : *std::min_element(candidates.begin(), candidates.end(), [&](cd a, cd b) {
                                           return std::abs(a - fine) < std::abs(b - fine);
                                         });
    out.coarse.push_back(twin);
    out.errors.push_back(mesh_error({twin, fine}, tolerance, floor, true, coarsen));
  }
  return out;
}

}  // namespace rc::rom
