// Reference tables of published (or closed-form) κ and E, and `cavity-modes compare`.
//
// CSV format (docs/reference-tables.md): '#' comment lines and blank lines are skipped; the first other
// line is the header, naming the columns in any order:
//   shape,dimensions,kappa,E,source[,label]
// then one row per mode, e.g.
//   cylinder,height=2;radius=1,2.0089...,2.0544...,"Stewartson (1959) J. Fluid Mech. 5, 577, ...",n=0 j=1
// Values are for ρ = 1, ω0 = 1, in the table's length unit; E = 2a²/N² (docs/physics.md §2). Fields holding commas
// or quotes are quoted ("..."; "" inside is a quote). A file describes one cavity: every row's shape and
// dimensions must match the mode table it is compared with. Rows of shape `section` may leave dimensions empty.
#pragma once

#include "mode_table.hpp"

#include <filesystem>
#include <istream>
#include <map>
#include <string>
#include <vector>

namespace rc::modes {

struct ReferenceRow {
  int line = 0;  // 1-based line number in the CSV
  std::string shape;
  std::map<std::string, double> dimensions;
  double kappa = 0;  // 2ω0/λ, either sign, |κ| > 1
  double E = 0;      // > 0
  std::string source;
  std::string label;  // optional free text (which mode this is)
};

// Parses a reference CSV; throws std::runtime_error("<name>: line N: <cause>") on a missing or unknown
// column, a wrong number of fields, a non-numeric or non-finite value, an empty file or one without rows.
std::vector<ReferenceRow> parse_reference_csv(std::istream& in, const std::string& name);
std::vector<ReferenceRow> read_reference_csv(const std::filesystem::path& path);

// Writing (used by make-reference-tables): the header line and one row, values to 17 digits.
std::string reference_csv_header();
std::string reference_csv_row(const ReferenceRow& row);

struct ComparedRow {
  std::size_t row = 0;      // index into the reference rows
  std::size_t cluster = 0;  // index into the table's /modes (nearest κ)
  double kappa = 0, E = 0, lambda = 0;  // the table's values
  double rel_kappa = 0, rel_E = 0;      // (table − reference) / |reference|
  double d_lambda = 0;                  // λ_table − λ_reference
  double worst() const;                 // max(|rel_kappa|, |rel_E|)
};

struct Comparison {
  std::vector<ReferenceRow> reference;
  std::vector<ComparedRow> rows;  // one per reference row, in file order
  double tolerance = 0;
  std::size_t worst = 0;   // index into rows of the largest relative difference
  std::size_t failing = 0; // rows with a relative difference above the tolerance
};

// Matches every reference row to the table's cluster of nearest κ. Throws std::runtime_error when a
// row's shape or dimensions differ from the table's (names exactly, values within 1e-12 relative),
// when the table has no modes, or when the tolerance is not a positive finite number.
Comparison compare_with_reference(const ModeTable& table, std::vector<ReferenceRow> reference,
                                  double tolerance, const std::string& reference_name);

// The report printed by `cavity-modes compare`, and the one-line cause of a failed comparison.
std::string comparison_text(const Comparison& c, const ModeTable& table, const std::string& table_name,
                            const std::string& reference_name);
std::string comparison_failure(const Comparison& c, const std::string& reference_name);

}  // namespace rc::modes
