// A 3-D cavity's ideal mode table, end to end (docs/volume.md): mesh → forms → the block Lanczos survey of the
// coupling's matrix measure → Zhukovsky's tensor → the table (common/mode_table.hpp, /volume). The request is resolved
// once by the command (modes/app/volume_command.*); this layer takes only what it needs.
#pragma once

#include "mode_fields.hpp"
#include "mode_table.hpp"
#include "volume_mesh.hpp"
#include "volume_survey.hpp"

#include <functional>
#include <optional>
#include <string>

namespace rc::modes {

struct VolumeTableRequest {
  geometry::VolumeShapeSpec shape;
  geometry::MeshOptions mesh;  // order, size (0: default), wall_size/wall_growth
  VolumeSurveySettings survey;
  bool fields = false;  // also each row's P and V at the mesh nodes (volume_fields.hpp)
};

struct VolumeTableResult {
  ModeTable table;
  VolumeSurvey survey;
  double sum_rule_mismatch = 0;  // max |Σ H over the rule − (I_f − J_zh)| / trace(I_f − J_zh)
  std::optional<ModeFields> fields;  // with request.fields
};

// The order taken by the commands (docs/volume.md); the default size is the mesher's (geometry/volume_mesh.hpp).
inline constexpr int kVolumeDefaultOrder = 4;

// `progress` receives a line per phase and at least every 5 s while working (fe/progress.hpp); none by default.
// One ideal 3-D row of /modes: λ, κ = 2/λ, E = H_xx + H_yy, a = √(E/2), N2 = 1, with its bound, spread and members (its
// coupling tensors are the caller's).
void push_ideal_volume_row(ModeTable& t, double lambda, double E, double residual, double spread, int members);

VolumeTableResult make_volume_table(const VolumeTableRequest& request,
                                    const std::function<void(const std::string&)>& progress = {});

}  // namespace rc::modes
