#include "reference_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <stdexcept>

namespace rc::modes {
namespace {

constexpr double kDimensionTolerance = 1e-12;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

[[noreturn]] void fail(const std::string& name, int line, const std::string& cause) {
  throw std::runtime_error(fmt::format("{}: line {}: {}", name, line, cause));
}

// Splits one CSV line; fields may be quoted ("a, b"), with "" for a quote inside quotes.
std::vector<std::string> split_csv(const std::string& line, const std::string& name, int lineno) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false, was_quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch == '"') {
        if (i + 1 < line.size() && line[i + 1] == '"') { field += '"'; ++i; }
        else quoted = false;
      } else {
        field += ch;
      }
    } else if (ch == '"') {
      if (!trim(field).empty()) fail(name, lineno, "a quote inside an unquoted field");
      field.clear();
      quoted = was_quoted = true;
    } else if (ch == ',') {
      fields.push_back(was_quoted ? field : trim(field));
      field.clear();
      was_quoted = false;
    } else if (was_quoted) {
      if (ch != ' ' && ch != '\t' && ch != '\r') fail(name, lineno, "text after a closing quote");
    } else {
      field += ch;
    }
  }
  if (quoted) fail(name, lineno, "unterminated quote");
  fields.push_back(was_quoted ? field : trim(field));
  return fields;
}

double parse_number(const std::string& text, const std::string& what, const std::string& name, int lineno) {
  const std::string t = trim(text);
  if (t.empty()) fail(name, lineno, fmt::format("{} is empty", what));
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size()) fail(name, lineno, fmt::format("{} = '{}' is not a number", what, t));
  if (!std::isfinite(v) || errno == ERANGE) fail(name, lineno, fmt::format("{} = '{}' is not finite", what, t));
  return v;
}

std::map<std::string, double> parse_dimensions(const std::string& text, const std::string& name, int lineno) {
  std::map<std::string, double> dims;
  std::size_t start = 0;
  const std::string t = trim(text);
  if (t.empty()) fail(name, lineno, "dimensions is empty (expected e.g. radius=1;height=2)");
  while (start <= t.size()) {
    const auto stop = std::min(t.find(';', start), t.size());
    const std::string item = trim(t.substr(start, stop - start));
    const auto eq = item.find('=');
    if (eq == std::string::npos || trim(item.substr(0, eq)).empty())
      fail(name, lineno, fmt::format("dimension '{}' is not name=value", item));
    const std::string key = trim(item.substr(0, eq));
    if (dims.count(key)) fail(name, lineno, fmt::format("dimension '{}' given twice", key));
    dims[key] = parse_number(item.substr(eq + 1), "dimension " + key, name, lineno);
    start = stop + 1;
  }
  return dims;
}

std::string format_dimensions(const std::map<std::string, double>& dims, const char* fmt_str) {
  std::string s;
  for (const auto& [k, v] : dims) s += (s.empty() ? "" : ";") + k + "=" + fmt::format(fmt::runtime(fmt_str), v);
  return s;
}

std::string quote(const std::string& s) {
  if (s.find_first_of(",\"#") == std::string::npos && trim(s) == s) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

}  // namespace

std::vector<ReferenceRow> parse_reference_csv(std::istream& in, const std::string& name) {
  static const std::vector<std::string> required = {"shape", "dimensions", "kappa", "E", "source"};
  static const std::vector<std::string> optional = {"label"};
  std::map<std::string, std::size_t> column;
  std::vector<ReferenceRow> rows;
  std::string line;
  int lineno = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto fields = split_csv(line, name, lineno);
    if (!header) {
      for (std::size_t i = 0; i < fields.size(); ++i) {
        const auto& c = fields[i];
        if (std::find(required.begin(), required.end(), c) == required.end() &&
            std::find(optional.begin(), optional.end(), c) == optional.end())
          fail(name, lineno, fmt::format("unknown column '{}' in the header (expected shape,dimensions,kappa,E,"
                                         "source and optionally label)", c));
        if (column.count(c)) fail(name, lineno, fmt::format("column '{}' given twice", c));
        column[c] = i;
      }
      for (const auto& c : required)
        if (!column.count(c))
          fail(name, lineno, fmt::format("the header lacks column '{}' (expected shape,dimensions,kappa,E,source)",
                                         c));
      header = true;
      continue;
    }
    if (fields.size() != column.size())
      fail(name, lineno, fmt::format("{} fields, the header has {} columns", fields.size(), column.size()));
    ReferenceRow r;
    r.line = lineno;
    r.shape = fields[column["shape"]];
    if (r.shape.empty()) fail(name, lineno, "shape is empty");
    // A user's section has no dimensions to name (the table keeps its file's text instead): empty is allowed.
    if (!(r.shape == "section" && trim(fields[column["dimensions"]]).empty()))
      r.dimensions = parse_dimensions(fields[column["dimensions"]], name, lineno);
    r.kappa = parse_number(fields[column["kappa"]], "kappa", name, lineno);
    if (!(std::abs(r.kappa) > 1))
      fail(name, lineno, fmt::format("kappa = {:g} is not an inertial mode (|kappa| > 1, |lambda| < 2)", r.kappa));
    r.E = parse_number(fields[column["E"]], "E", name, lineno);
    if (!(r.E > 0)) fail(name, lineno, fmt::format("E = {:g} is not positive", r.E));
    r.source = fields[column["source"]];
    if (r.source.empty()) fail(name, lineno, "source is empty (cite where the row comes from)");
    if (column.count("label")) r.label = fields[column["label"]];
    rows.push_back(std::move(r));
  }
  if (!header) throw std::runtime_error(name + ": empty (no header line, no rows)");
  if (rows.empty()) throw std::runtime_error(name + ": no reference rows after the header");
  return rows;
}

std::vector<ReferenceRow> read_reference_csv(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw std::runtime_error(path.string() + ": cannot read (a directory)");
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot read");
  return parse_reference_csv(in, path.string());
}

std::string reference_csv_header() { return "shape,dimensions,kappa,E,source,label\n"; }

std::string reference_csv_row(const ReferenceRow& r) {
  return fmt::format("{},{},{:.17g},{:.17g},{},{}\n", quote(r.shape), format_dimensions(r.dimensions, "{:.17g}"),
                     r.kappa, r.E, quote(r.source), quote(r.label));
}

double ComparedRow::worst() const { return std::max(std::abs(rel_kappa), std::abs(rel_E)); }

Comparison compare_with_reference(const ModeTable& table, std::vector<ReferenceRow> reference, double tolerance,
                                  const std::string& name) {
  if (!(tolerance > 0) || !std::isfinite(tolerance))
    throw std::runtime_error(fmt::format("--tolerance {:g} is not a positive number", tolerance));
  if (table.size() == 0) throw std::runtime_error("the mode table holds no modes");
  const std::string table_dims = format_dimensions(table.dimensions, "{:.17g}");
  for (const auto& r : reference) {
    if (r.shape != table.shape)
      fail(name, r.line, fmt::format("shape '{}' does not match the table's '{}'", r.shape, table.shape));
    for (const auto& [k, v] : r.dimensions) {
      const auto it = table.dimensions.find(k);
      if (it == table.dimensions.end())
        fail(name, r.line, fmt::format("dimension '{}' is not one of the table's ({})", k, table_dims));
      if (!(std::abs(it->second - v) <= kDimensionTolerance * std::abs(it->second)))
        fail(name, r.line, fmt::format("dimension {} = {:.17g} does not match the table's {} = {:.17g}", k, v, k,
                                       it->second));
    }
    for (const auto& [k, v] : table.dimensions)
      if (!r.dimensions.count(k))
        fail(name, r.line, fmt::format("dimension '{}' missing (the table has {})", k, table_dims));
  }
  Comparison c;
  c.tolerance = tolerance;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const auto& r = reference[i];
    ComparedRow row;
    row.row = i;
    for (std::size_t j = 1; j < table.size(); ++j)
      if (std::abs(table.kappa[j] - r.kappa) < std::abs(table.kappa[row.cluster] - r.kappa)) row.cluster = j;
    row.kappa = table.kappa[row.cluster];
    row.E = table.E[row.cluster];
    row.lambda = table.lambda[row.cluster];
    row.rel_kappa = (row.kappa - r.kappa) / std::abs(r.kappa);
    row.rel_E = (row.E - r.E) / r.E;
    row.d_lambda = row.lambda - 2 / r.kappa;
    if (!(row.worst() <= tolerance)) ++c.failing;  // NaN counts as a failure
    if (c.rows.empty() || !(row.worst() <= c.rows[c.worst].worst())) c.worst = c.rows.size();
    c.rows.push_back(row);
  }
  c.reference = std::move(reference);
  return c;
}

std::string comparison_text(const Comparison& c, const ModeTable& t, const std::string& table_name,
                            const std::string& reference_name) {
  std::string dims;
  for (const auto& [k, v] : t.dimensions) dims += fmt::format(" {}={:g}", k, v);
  std::string s = fmt::format("table {}: {}{}, order {}, h = {:g}, {} clusters\n", table_name, t.shape, dims,
                              t.fe_order, t.mesh_h, t.size());
  if (t.shape == "section")
    s += fmt::format("note: a CSV names no section file; this table was made from {}: make sure the reference "
                     "describes that section\n", t.geometry_source.empty() ? "(not recorded)" : t.geometry_source);
  s += fmt::format("reference {}: {} rows; each matched to the cluster of nearest kappa; tolerance {:g} "
                   "(relative, kappa and E)\n",
                   reference_name, c.reference.size(), c.tolerance);
  s += fmt::format("{:>4} {:>5} {:>4} {:>19} {:>19} {:>9} {:>19} {:>19} {:>9} {:>9}  {}\n", "row", "line", "cl",
                   "kappa_ref", "kappa_table", "rel_diff", "E_ref", "E_table", "rel_diff", "d_lambda", "label [source]");
  std::vector<std::string> sources;
  for (const auto& row : c.rows) {
    const auto& r = c.reference[row.row];
    auto it = std::find(sources.begin(), sources.end(), r.source);
    if (it == sources.end()) it = sources.insert(sources.end(), r.source);
    const auto src = static_cast<std::size_t>(it - sources.begin()) + 1;
    s += fmt::format("{:>4} {:>5} {:>4} {:>19.14f} {:>19.14f} {:>+9.1e} {:>19.14f} {:>19.14f} {:>+9.1e} {:>+9.1e}  "
                     "{}[{}]{}\n",
                     row.row + 1, r.line, row.cluster + 1, r.kappa, row.kappa, row.rel_kappa, r.E, row.E, row.rel_E,
                     row.d_lambda, r.label.empty() ? "" : r.label + " ", src, row.worst() <= c.tolerance ? "" : "  <- over");
  }
  for (std::size_t i = 0; i < sources.size(); ++i) s += fmt::format("[{}] {}\n", i + 1, sources[i]);
  for (std::size_t i = 0; i < c.rows.size(); ++i)
    for (std::size_t j = i + 1; j < c.rows.size(); ++j)
      if (c.rows[i].cluster == c.rows[j].cluster)
        s += fmt::format("note: rows {} and {} both matched cluster {} (a reference mode may be missing from the "
                         "table)\n",
                         i + 1, j + 1, c.rows[i].cluster + 1);
  const auto& w = c.rows[c.worst];
  s += fmt::format("worst: row {} (line {}), |rel diff| {:.2e} ({}); {} of {} rows within {:g}\n", w.row + 1,
                   c.reference[w.row].line, w.worst(), std::abs(w.rel_E) >= std::abs(w.rel_kappa) ? "E" : "kappa",
                   c.rows.size() - c.failing, c.rows.size(), c.tolerance);
  return s;
}

std::string comparison_failure(const Comparison& c, const std::string& reference_name) {
  const auto& w = c.rows[c.worst];
  const auto& r = c.reference[w.row];
  const bool e_worse = !(std::abs(w.rel_kappa) > std::abs(w.rel_E));
  return fmt::format("{} of {} reference rows differ by more than {:g}; worst: row {} ({} line {}, kappa {:.10g}{}): "
                     "{} differs from cluster {} by {:.2e} relative",
                     c.failing, c.rows.size(), c.tolerance, w.row + 1, reference_name, r.line, r.kappa,
                     r.label.empty() ? "" : ", " + r.label, e_worse ? "E" : "kappa", w.cluster + 1,
                     e_worse ? w.rel_E : w.rel_kappa);
}

}  // namespace rc::modes
