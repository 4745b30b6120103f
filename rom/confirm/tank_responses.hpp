// Every viscous tank of a chain with its own response R(s) served by cavity-modes (served_response.hpp), as the
// TankResponse list that root_confirmation.hpp iterates with: what `chain-rom confirm` and the confirmed spin sweep
// (confirmed_sweep.hpp) share.
#pragma once

#include "chain_model.hpp"
#include "root_confirmation.hpp"
#include "scene.hpp"
#include "served_response.hpp"

#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace rc::rom {

// A folder for section files written from tables, removed with it.
struct ScratchFolder {
  std::filesystem::path path;
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
};

struct TankResponses {
  std::vector<std::unique_ptr<ServedResponse>> served;
  std::vector<TankResponse> responses;
  int solves() const;
};

// Starts one served response per body of `m` with a viscous table, on the table's mesh at the Ekman number of the
// scene's viscosity and spin, nu/(|spin| scale^2) (the table's own when they agree within kEkmanTolerance, so that
// the mesh is the table's); `mesh_ekman` (per body, 0: none) makes the mesh as for that Ek instead; `tables` (when
// given) holds the tables already read, which a sweep does not read again at every point. Writes one line per tank to
// `log` (the command and the served mesh, and a warning when it is not the table's mesh); `mesh` (when not the
// table's) serves a mesh study's level instead. Throws SceneError naming the table when its provenance cannot be
// read back, std::runtime_error when cavity-modes does not start.
TankResponses serve_tanks(const Scene& scene, const ChainModel& m, const std::string& binary,
                          const std::filesystem::path& scratch, std::ostream& log,
                          const std::vector<double>& mesh_ekman = {}, TableCache* tables = nullptr,
                          const ServedMesh& mesh = {});

}  // namespace rc::rom
