#include "general_mesh_check.hpp"

#include "mode_table.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace rc::rom {
namespace fs = std::filesystem;
namespace {
using cd = std::complex<double>;

// Whether the scene's viscous tables are all axisymmetric Krylov tables (checked a level finer) or all 3-D (checked
// coarser); throws std::runtime_error when they mix.
bool checked_finer(const Scene& scene) {
  int axisymmetric = 0, three_d = 0;
  const auto count = [&](const fs::path& table) {
    const rc::ModeTable t = rc::read_mode_table(table);
    if (t.viscous()) ++(t.volume_cavity.present() ? three_d : axisymmetric);
  };
  for (const auto& body : scene.bodies) {
    if (body.cavity) count(body.cavity->table);
    for (const auto& c : body.more_cavities) count(c.table);
  }
  if (axisymmetric > 0 && three_d > 0)
    throw std::runtime_error("the viscous tanks mix 3-D response tables (checked on coarser meshes) and axisymmetric "
                             "ones (checked a level finer): check each kind in a scene of its own");
  return axisymmetric > 0;
}

// The scene with each viscous table replaced by the check's one made in `scratch` (each file once, however many tanks
// share it).
Scene with_check_tables(const Scene& scene, bool finer, double coarsen, const std::string& binary,
                        const fs::path& scratch, const ProgramRunner& run, std::ostream& log) {
  Scene copy = scene;
  std::map<fs::path, fs::path> made;
  const auto replace = [&](fs::path& table) {
    if (!rc::read_mode_table(table).viscous()) return;
    auto it = made.find(table);
    if (it == made.end()) {
      const fs::path out = scratch / ("check" + std::to_string(made.size() + 1) + ".h5");
      if (finer) log << "  " << table.string() << ": made again one mesh level finer (every size halved)" << std::endl;
      else log << "  " << table.string() << ": made again on a mesh " << coarsen << " times as coarse" << std::endl;
      remake_on_another_mesh(table, coarsen, out, binary, scratch, run);
      it = made.emplace(table, out).first;
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
  out.finer = checked_finer(scene);
  out.coarsen = coarsen;
  if (out.finer)
    log << "the mesh check: the tables one mesh level finer, their roots confirmed as above" << std::endl;
  else
    log << "the mesh check: the tables on a mesh " << coarsen << " times as coarse, their roots confirmed as above"
        << std::endl;
  const Scene other = with_check_tables(scene, out.finer, coarsen, binary, scratch, run, log);
  const GeneralConfirmation c = confirm_general(other, all, root_tolerance, binary, scratch, run, log);
  out.rounds = c.rounds;
  const std::vector<cd>& candidates = c.confirmed.empty() ? c.spectrum.roots : c.confirmed;
  for (const cd& root : confirmed) {
    const cd twin = candidates.empty() ? cd(NAN, NAN)
                                       : *std::min_element(candidates.begin(), candidates.end(), [&](cd a, cd b) {
                                           return std::abs(a - root) < std::abs(b - root);
                                         });
    out.twins.push_back(twin);
    out.errors.push_back(out.finer ? mesh_error({root, twin}, tolerance, floor, true, 2.0)
                                   : mesh_error({twin, root}, tolerance, floor, true, coarsen));
  }
  return out;
}

}  // namespace rc::rom
