// `cavity-modes compare A.h5 B.h5`: one table against another of the same cavity, typically the same shape on
// two meshes, so that a refinement study is one command (docs/trust.md). It reports what converges for every
// shape — the integrals A_f, C_f, J_zh, A_f − J_zh and the band weights of /bands — and, for information, the
// clusters of A matched to B's of nearest λ (single clusters converge only where the spectrum is discrete:
// spheroids and cylinders, not cones or general sections; docs/cones.md). Two 3-D tables (docs/volume.md §5) are
// compared in their tensors too — inertia, Zhukovsky, the sum rule, the geostrophic weight — and their modes in
// groups: a 3-D mesh splits one mode among discrete copies a little apart, so rows within a relative 1e-2 in λ are
// one group, its λ their E-weighted mean and its coupling the sum of their tensors.
#pragma once

#include "mode_table.hpp"

#include <string>
#include <vector>

namespace rc::modes {

struct QuantityDifference {
  std::string name;
  double a = 0, b = 0;
  double difference = 0;  // |a − b| / scale
  bool judged = true;     // counts towards the verdict
};

struct TableComparison {
  double tolerance = 0;
  std::vector<QuantityDifference> integrals;  // volume, A_f, C_f, J_zh, A_f − J_zh: relative to |b|
  std::vector<QuantityDifference> bands;      // band weights: |ΔE| relative to B's A_f − J_zh
  std::vector<QuantityDifference> tensors;    // 3-D tables: the /volume tensors, largest entry difference (judged)
  std::vector<QuantityDifference> clusters;   // λ and E of A's clusters against B's nearest (not judged)
  std::vector<std::string> notes;             // differences in setup worth knowing (geometry text, order, Ek)
  std::size_t failing = 0;                    // judged quantities above the tolerance
  double worst = 0;                           // the largest judged difference
  std::string worst_name;
};

// Throws std::runtime_error if the tables describe different cavities (shape, dimensions, or both section texts
// stored and different), if one is viscous and the other not, or if the tolerance is not positive and finite.
TableComparison compare_tables(const ModeTable& a, const ModeTable& b, double tolerance);

std::string table_comparison_text(const TableComparison& c, const ModeTable& a, const ModeTable& b,
                                  const std::string& a_name, const std::string& b_name);
// The one-line cause when judged quantities differ by more than the tolerance.
std::string table_comparison_failure(const TableComparison& c);

}  // namespace rc::modes
