// A table's "mode" (docs/physics.md §2): a spectral cluster, and the settings of the two ways of refining the survey's
// nodes into clusters — shift-and-invert Lanczos Gauss rules (lanczos_refinement.hpp, the default) and
// SLEPc spectrum slices (slice_refinement.hpp). See docs/modes.md, "Clusters".
#pragma once

#include "qep_solver.hpp"
#include "shift_invert_survey.hpp"

namespace rc::modes {

struct Cluster {
  double lambda = 0;     // E-weighted mean of the members' λ
  double E = 0;          // sum of the members' E
  double spread = 0;     // E-weighted standard deviation of the members' λ
  double residual = 0;   // worst residual of the members (see docs/modes.md for its meaning per method)
  int members = 0;       // eigenpairs (slices) or Gauss nodes (search) merged
};

enum class ClusterMethod { lanczos, slices };

struct ClusterSettings {
  ClusterMethod method = ClusterMethod::lanczos;
  double cluster_width = 1e-5;  // members within this · max(|λ|, 0.1) of each other are one cluster
  double slice_width = 2e-3;    // first window (slice) half-width around a node, relative to max(|θ|, 0.1)
  int widenings = 2;            // at most this many ×4 widenings of it
  // lanczos (lanczos_refinement.hpp)
  double floor = 1e-7;          // Gauss nodes lighter than this · (A_f − J_zh) need not settle
  bool fill_gaps = false;       // search the gaps between kept clusters below gap_lambda (cavity_table.cpp)
  double gap_lambda = 0.5;
  ShiftInvertSettings sil;
  // slices (slice_refinement.hpp)
  QepSettings qep;
};

}  // namespace rc::modes
