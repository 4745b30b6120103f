#include "tank_responses.hpp"

#include <cmath>
#include <cstdlib>

namespace rc::rom {
namespace fs = std::filesystem;

ScratchFolder::ScratchFolder() {
  char tmpl[] = "/tmp/chain-rom-XXXXXX";
  if (!mkdtemp(tmpl)) throw std::runtime_error("cannot create a temporary folder");
  path = tmpl;
}

ScratchFolder::~ScratchFolder() {
  std::error_code ec;
  fs::remove_all(path, ec);
}

int TankResponses::solves() const {
  int n = 0;
  for (const auto& s : served) n += s->solves();
  return n;
}

namespace {
// A partially filled tank's offset row (root_confirmation.hpp), in its table's lengths.
Eigen::VectorXd offset_row(const Scene& scene, const ChainModel& m, int k) {
  const double L = scene.bodies[k].cavity->scale;
  Eigen::VectorXd g = Eigen::VectorXd::Zero(m.extended ? m.n + 1 : m.n);
  g[k] = m.bodies[k].fluid_center / L;
  for (int j = 0; j < k; ++j) g[j] = scene.bodies[j].next_joint / L;
  if (m.extended) g[m.n] = 1 / L;
  return g;
}
}  // namespace

TankResponses serve_tanks(const Scene& scene, const ChainModel& m, const std::string& binary, const fs::path& scratch,
                          std::ostream& log, const std::vector<double>& mesh_ekman, TableCache* tables,
                          const ServedMesh& mesh) {
  TankResponses t;
  for (int k = 0; k < m.n; ++k) {
    if (m.bodies[k].ekman <= 0) continue;
    const CavitySpec& cav = *scene.bodies[k].cavity;
    const rc::ModeTable own = tables ? rc::ModeTable() : rc::read_mode_table(cav.table);
    const rc::ModeTable& table = tables ? tables->get(cav.table) : own;
    // The scene's own Ekman number: the table's within 1 % for spectrum; any for a sweep over spin.
    const double scene_ekman = *cav.viscosity / (std::abs(scene.bodies[k].spin) * cav.scale * cav.scale);
    const bool same_ek = std::abs(scene_ekman - table.ekman) <= kEkmanTolerance * table.ekman;
    const double ekman = same_ek ? table.ekman : scene_ekman;
    // (at most the served Ek: the table's recorded Ek may round below the sweep's least)
    const double mesh_ek = std::min(ekman, static_cast<std::size_t>(k) < mesh_ekman.size()
                                               ? mesh_ekman[static_cast<std::size_t>(k)] : 0.0);
    std::vector<std::string> args;
    try {
      args = serve_arguments(table, scratch, ekman, mesh_ek, mesh);
    } catch (const std::exception& e) {
      throw SceneError("body[" + std::to_string(k + 1) + "].cavity.table " + cav.table.string() + ": " + e.what());
    }
    log << "  body " << k + 1 << ": " << binary;
    for (const auto& a : args) log << " " << a;
    log << std::endl;
    auto& s = *t.served.emplace_back(std::make_unique<ServedResponse>(binary, args));
    log << "    " << s.ready_line();
    if (same_ek && mesh_ek == 0 && mesh.is_tables() && table.ndof > 0 && s.unknowns() > 0 && s.unknowns() != table.ndof)
      log << " -- NOT the table's mesh (" << table.ndof << " unknowns): its recorded command line does not give "
          << "back its mesh (a table made by an older cavity-modes, whose defaults differed), so the check is against "
          << "a different discretisation";
    log << std::endl;
    ServedResponse* p = &s;
    t.responses.push_back({k, cav.density * std::pow(cav.scale, 5), [p](std::complex<double> x) { return (*p)(x); },
                           {}, {}, false});
    if (m.bodies[k].free_surface) {  // served with --fill (its table's command line): R, R_fg, R_gg
      t.responses.back().R_offset = [p](std::complex<double> x) { return p->offset(x); };
      t.responses.back().offset_row = offset_row(scene, m, k);
      t.responses.back().mirror_symmetric =
          table.shape == "sphere" || table.shape == "spheroid" || table.shape == "cylinder";
    }
  }
  return t;
}

}  // namespace rc::rom
