#include "table_comparison.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace rc::modes {
namespace {

void check_same_cavity(const ModeTable& a, const ModeTable& b) {
  const std::string why = cavity_difference(a, b);
  if (!why.empty()) throw std::runtime_error("the tables describe different cavities: " + why);
  if (a.viscous() != b.viscous()) throw std::runtime_error("one table is viscous, the other ideal");
}

double relative(double a, double b, double scale) { return std::abs(a - b) / std::max(std::abs(scale), 1e-300); }

std::vector<std::string> setup_notes(const ModeTable& a, const ModeTable& b) {
  std::vector<std::string> notes;
  if (a.shape == "section" && (a.geometry_text.empty() || b.geometry_text.empty()))
    notes.push_back("a table predates stored section texts: that both come from the same file is not checked");
  if (a.ekman != b.ekman) notes.push_back(fmt::format("Ekman numbers differ: {:g} and {:g}", a.ekman, b.ekman));
  if (a.bands.size() == 0 || b.bands.size() == 0) notes.push_back("a table has no /bands: band weights not compared");
  return notes;
}

// B's cluster of nearest λ for each of A's, with λ and E differences (relative to B's).
void add_clusters(TableComparison& c, const ModeTable& a, const ModeTable& b) {
  for (std::size_t i = 0; i < a.size() && b.size() > 0; ++i) {
    std::size_t j = 0;
    for (std::size_t k = 1; k < b.size(); ++k)
      if (std::abs(b.lambda[k] - a.lambda[i]) < std::abs(b.lambda[j] - a.lambda[i])) j = k;
    c.clusters.push_back({fmt::format("cluster {} -> {}: lambda", i + 1, j + 1), a.lambda[i], b.lambda[j],
                          relative(a.lambda[i], b.lambda[j], b.lambda[j]), false});
    c.clusters.push_back({fmt::format("cluster {} -> {}: E", i + 1, j + 1), a.E[i], b.E[j],
                          relative(a.E[i], b.E[j], b.E[j]), false});
  }
}

}  // namespace

TableComparison compare_tables(const ModeTable& a, const ModeTable& b, double tolerance) {
  if (!(tolerance > 0) || !std::isfinite(tolerance))
    throw std::runtime_error(fmt::format("--tolerance {:g} is not a positive number", tolerance));
  check_same_cavity(a, b);
  TableComparison c;
  c.tolerance = tolerance;
  c.notes = setup_notes(a, b);
  const std::pair<const char*, double ModeTable::*> integrals[] = {
      {"volume", &ModeTable::volume}, {"A_f", &ModeTable::A_f}, {"C_f", &ModeTable::C_f},
      {"J_zh", &ModeTable::J_zh}, {"A_f - J_zh", &ModeTable::sum_rule}};
  for (const auto& [name, field] : integrals)
    c.integrals.push_back({name, a.*field, b.*field, relative(a.*field, b.*field, b.*field), true});
  const bool same_bands = a.bands.lo == b.bands.lo && a.bands.hi == b.bands.hi;
  if (a.bands.size() > 0 && b.bands.size() > 0 && !same_bands)
    c.notes.push_back("the tables' band edges differ: band weights not compared");
  if (same_bands)
    for (std::size_t k = 0; k < a.bands.size(); ++k)
      c.bands.push_back({fmt::format("band [{:+.2f}, {:+.2f})", a.bands.lo[k], a.bands.hi[k]), a.bands.E[k],
                         b.bands.E[k], relative(a.bands.E[k], b.bands.E[k], b.sum_rule), true});
  add_clusters(c, a, b);
  for (const auto* list : {&c.integrals, &c.bands})
    for (const auto& q : *list) {
      if (!(q.difference <= tolerance)) ++c.failing;  // NaN fails
      if (!(q.difference <= c.worst)) { c.worst = q.difference; c.worst_name = q.name; }
    }
  return c;
}

namespace {

// Decimal digits that agree: −log10 of the difference (16 at zero).
std::string digits(double d) { return d > 0 ? fmt::format("{:.1f}", std::min(16.0, -std::log10(d))) : "16"; }

std::string rows(const std::vector<QuantityDifference>& list, double tolerance, const char* scale) {
  std::string s = fmt::format("{:>24} {:>20} {:>20} {:>10} {:>6}\n", "", "A", "B", scale, "digits");
  for (const auto& q : list)
    s += fmt::format("{:>24} {:>20.13g} {:>20.13g} {:>10.2e} {:>6}{}\n", q.name, q.a, q.b, q.difference,
                     digits(q.difference), q.judged && !(q.difference <= tolerance) ? "  <- over" : "");
  return s;
}

}  // namespace

std::string table_comparison_text(const TableComparison& c, const ModeTable& a, const ModeTable& b,
                                  const std::string& a_name, const std::string& b_name) {
  const auto describe = [](const ModeTable& t) {
    return fmt::format("{}, order {}, h = {:g}{}, {} dofs, {} clusters", t.shape, t.fe_order, t.mesh_h,
                       t.viscous() ? fmt::format(", Ek = {:g}", t.ekman) : std::string(), t.ndof, t.size());
  };
  std::string s = fmt::format("A {}: {}\nB {}: {}\n", a_name, describe(a), b_name, describe(b));
  for (const auto& n : c.notes) s += "note: " + n + "\n";
  s += "integrals (relative difference):\n" + rows(c.integrals, c.tolerance, "rel_diff");
  std::vector<QuantityDifference> weighty;  // bands holding weight in either table
  for (const auto& q : c.bands)
    if (q.a > 0 || q.b > 0) weighty.push_back(q);
  if (!c.bands.empty())
    s += fmt::format("band weights (|difference| / B's A_f - J_zh; {} of {} bands hold weight):\n", weighty.size(),
                     c.bands.size()) + rows(weighty, c.tolerance, "diff/rule");
  if (!c.clusters.empty())
    s += "clusters of A against B's of nearest lambda (relative difference; for information: single clusters "
         "converge only where the spectrum is discrete, docs/trust.md):\n" + rows(c.clusters, c.tolerance, "rel_diff");
  s += fmt::format("worst judged difference: {} {:.2e}; {} of {} integrals and band weights within {:g}\n",
                   c.worst_name, c.worst, c.integrals.size() + c.bands.size() - c.failing,
                   c.integrals.size() + c.bands.size(), c.tolerance);
  return s;
}

std::string table_comparison_failure(const TableComparison& c) {
  return fmt::format("{} integrals or band weights differ by more than {:g}; worst: {} by {:.2e}", c.failing,
                     c.tolerance, c.worst_name, c.worst);
}

}  // namespace rc::modes
