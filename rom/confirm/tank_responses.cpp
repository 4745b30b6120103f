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

// Confirming with the filled cavity's R would be wrong (docs/viscous.md, "The response of a partially filled tank").
void require_servable(const Scene& scene, const ChainModel& m) {
  for (int k = 0; k < m.n; ++k)
    if (m.bodies[k].ekman > 0 && m.bodies[k].free_surface)
      throw SceneError("body[" + std::to_string(k + 1) + "].cavity.table " + scene.bodies[k].cavity->table.string() +
                       ": the fluid's own response (confirm, and sweeps over spin with viscous tanks) does not take a "
                       "partially filled tank yet (cavity-modes response --fill gives it as CSV)");
}

TankResponses serve_tanks(const Scene& scene, const ChainModel& m, const std::string& binary, const fs::path& scratch,
                          std::ostream& log, const std::vector<double>& mesh_ekman, TableCache* tables) {
  require_servable(scene, m);
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
      args = serve_arguments(table, scratch, ekman, mesh_ek);
    } catch (const std::exception& e) {
      throw SceneError("body[" + std::to_string(k + 1) + "].cavity.table " + cav.table.string() + ": " + e.what());
    }
    log << "  body " << k + 1 << ": " << binary;
    for (const auto& a : args) log << " " << a;
    log << std::endl;
    auto& s = *t.served.emplace_back(std::make_unique<ServedResponse>(binary, args));
    log << "    " << s.ready_line();
    if (same_ek && mesh_ek == 0 && table.ndof > 0 && s.unknowns() > 0 && s.unknowns() != table.ndof)
      log << " -- NOT the table's mesh (" << table.ndof << " unknowns): the table was made by another version or "
          << "with other defaults, so the check is against a different discretisation";
    log << std::endl;
    ServedResponse* p = &s;
    t.responses.push_back({k, cav.density * std::pow(cav.scale, 5), [p](std::complex<double> x) { return (*p)(x); }});
  }
  return t;
}

}  // namespace rc::rom
