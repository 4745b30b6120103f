#include "table_comparison.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numeric>
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

double frobenius(const std::vector<double>& m) {
  return std::sqrt(std::inner_product(m.begin(), m.end(), m.begin(), 0.0));
}

// max |a_ij − b_ij| over entries stored as parallel real and imaginary parts (im empty: real tensors).
double largest_entry_difference(const std::vector<double>& a_re, const std::vector<double>& a_im,
                                const std::vector<double>& b_re, const std::vector<double>& b_im) {
  double d = 0;
  for (std::size_t k = 0; k < a_re.size() && k < b_re.size(); ++k) {
    const double im = a_im.empty() || b_im.empty() ? 0.0 : a_im[k] - b_im[k];
    d = std::max(d, std::hypot(a_re[k] - b_re[k], im));
  }
  return d;
}

// The /volume tensors of two 3-D tables: the largest entry difference, relative to B's inertia and Zhukovsky
// tensors' own norms, and the sum rule's and geostrophic weight's to B's sum-rule tensor (the total coupling).
void add_tensors(TableComparison& c, const ModeTable& a, const ModeTable& b) {
  const auto& va = a.volume_cavity;
  const auto& vb = b.volume_cavity;
  const double rule = std::max(frobenius(vb.sum_rule), 1e-300);
  const auto add = [&](const char* name, const std::vector<double>& ar, const std::vector<double>& ai,
                       const std::vector<double>& br, const std::vector<double>& bi, double scale) {
    const double na = std::hypot(frobenius(ar), frobenius(ai)), nb = std::hypot(frobenius(br), frobenius(bi));
    c.tensors.push_back({name, na, nb, largest_entry_difference(ar, ai, br, bi) / std::max(scale, 1e-300), true});
  };
  add("inertia", va.inertia, {}, vb.inertia, {}, frobenius(vb.inertia));
  add("Zhukovsky", va.zhukovsky, {}, vb.zhukovsky, {}, frobenius(vb.zhukovsky));
  add("sum rule I - J_zh", va.sum_rule, {}, vb.sum_rule, {}, rule);
  add("geostrophic weight", va.geostrophic_re, va.geostrophic_im, vb.geostrophic_re, vb.geostrophic_im, rule);
}

// A 3-D table's rows gathered into groups of λ within a relative 1e-2 of their neighbours (the discrete copies
// of one mode on a mesh without axial symmetry): E-weighted λ, total E, summed coupling tensor.
struct ModeGroup {
  double lambda = 0, E = 0;
  std::vector<double> H_re = std::vector<double>(9), H_im = std::vector<double>(9);
};

std::vector<ModeGroup> mode_groups(const ModeTable& t) {
  std::vector<std::size_t> order(t.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto i, auto j) { return t.lambda[i] < t.lambda[j]; });
  std::vector<ModeGroup> groups;
  double last = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t r = order[k];
    if (k == 0 || t.lambda[r] - last > 1e-2 * std::abs(last)) groups.emplace_back();
    auto& g = groups.back();
    g.lambda += t.E[r] * t.lambda[r];
    g.E += t.E[r];
    for (int e = 0; e < 9; ++e) {
      g.H_re[e] += t.volume_cavity.coupling_re[9 * r + e];
      g.H_im[e] += t.volume_cavity.coupling_im[9 * r + e];
    }
    last = t.lambda[r];
  }
  for (auto& g : groups) g.lambda /= std::max(g.E, 1e-300);
  return groups;
}

// Each of A's mode groups against B's of nearest λ: λ, E and the coupling tensor (for information).
void add_groups(TableComparison& c, const ModeTable& a, const ModeTable& b) {
  const auto ga = mode_groups(a), gb = mode_groups(b);
  for (std::size_t i = 0; i < ga.size() && !gb.empty(); ++i) {
    std::size_t j = 0;
    for (std::size_t k = 1; k < gb.size(); ++k)
      if (std::abs(gb[k].lambda - ga[i].lambda) < std::abs(gb[j].lambda - ga[i].lambda)) j = k;
    const auto label = [&](const char* what) { return fmt::format("group {} -> {}: {}", i + 1, j + 1, what); };
    c.clusters.push_back({label("lambda"), ga[i].lambda, gb[j].lambda,
                          relative(ga[i].lambda, gb[j].lambda, gb[j].lambda), false});
    c.clusters.push_back({label("E"), ga[i].E, gb[j].E, relative(ga[i].E, gb[j].E, gb[j].E), false});
    const double nb = std::hypot(frobenius(gb[j].H_re), frobenius(gb[j].H_im));
    c.clusters.push_back({label("|H|"), std::hypot(frobenius(ga[i].H_re), frobenius(ga[i].H_im)), nb,
                          largest_entry_difference(ga[i].H_re, ga[i].H_im, gb[j].H_re, gb[j].H_im) /
                              std::max(nb, 1e-300), false});
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
  const bool volumes = a.volume_cavity.present() && b.volume_cavity.present();
  if (volumes) {
    add_tensors(c, a, b);
    add_groups(c, a, b);
  } else {
    add_clusters(c, a, b);
  }
  for (const auto* list : {&c.integrals, &c.bands, &c.tensors})
    for (const auto& q : *list) {
      if (!(q.difference <= tolerance)) ++c.failing;  // NaN fails
      if (!(q.difference <= c.worst) || c.worst_name.empty()) { c.worst = q.difference; c.worst_name = q.name; }
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
  if (!c.tensors.empty())
    s += "3-D tensors (norms; largest entry difference / B's norm, sum rule and geostrophic weight / B's sum "
         "rule):\n" + rows(c.tensors, c.tolerance, "diff/norm");
  if (!c.tensors.empty() && !c.clusters.empty())
    s += "mode groups of A (rows within 1e-2 in lambda: a mode's discrete copies) against B's of nearest lambda "
         "(relative difference; |H| largest entry difference / B's norm; for information):\n" +
         rows(c.clusters, c.tolerance, "rel_diff");
  else if (!c.clusters.empty())
    s += "clusters of A against B's of nearest lambda (relative difference; for information: single clusters "
         "converge only where the spectrum is discrete, docs/trust.md):\n" + rows(c.clusters, c.tolerance, "rel_diff");
  const std::size_t judged = c.integrals.size() + c.bands.size() + c.tensors.size();
  s += fmt::format("worst judged difference: {} {:.2e}; {} of {} integrals, band weights and tensors within {:g}\n",
                   c.worst_name, c.worst, judged - c.failing, judged, c.tolerance);
  return s;
}

std::string table_comparison_failure(const TableComparison& c) {
  return fmt::format("{} integrals, band weights or tensors differ by more than {:g}; worst: {} by {:.2e}", c.failing,
                     c.tolerance, c.worst_name, c.worst);
}

}  // namespace rc::modes
