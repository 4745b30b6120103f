#include "partial_fill_table.hpp"

#include "convergence.hpp"
#include "fe_space.hpp"
#include "free_surface.hpp"
#include "free_surface_fields.hpp"
#include "free_surface_mesh.hpp"
#include "free_surface_sparse.hpp"
#include "line_space.hpp"
#include "partial_fill_closed_form.hpp"
#include "partial_fill_cylinder.hpp"
#include "separable_table.hpp"
#include "table_assembly.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <list>

namespace rc::modes {

ModeTable::FreeSurface free_surface_attributes(const PartialFillSpectrum& s, double fill) {
  ModeTable::FreeSurface f;
  f.fill = fill;
  f.radius = s.surface_radius;
  f.K0 = s.K0;
  f.K1 = s.K1;
  f.K2 = s.K2;
  f.J1 = s.J_D1;
  f.J2 = s.J_D2;
  return f;
}

namespace {

constexpr double kRoundingWeight = 1e-12;  // relative to the sum rule
// The sparse solver's pairs per target: a target's heavy pair may sit among many light ones (the partially filled
// sphere: 12 found the rigid turn at λ = 1 that 2 missed, measured 2026-11-27).
constexpr int kPairsPerTarget = 16;

// A pair as a selection item: its weight is its largest E about a point within one height H of the centroid (for a
// sphere or spheroid H is its polar diameter, for a section the liquid's axial extent).
struct Candidate {
  const PartialFillPair* pair = nullptr;
  double E = 0;  // the selection's weight (cluster_selection.hpp sorts and sums by E)
};

double weight(const PartialFillPair& p, double height) {
  return 2 * std::pow(std::abs(p.coupling.a) + height * std::abs(p.coupling.t), 2);
}

// A row of the table (E about the centroid) or, with `height`, the pair as the convergence check compares it: by λ
// and by its weight, which unlike E about the centroid is positive for every kept pair.
Cluster as_cluster(const PartialFillPair& p, double height = 0) {
  Cluster c;
  c.lambda = p.lambda;
  c.E = height > 0 ? weight(p, height) : p.coupling.E;
  c.residual = p.residual;
  c.members = 1;
  return c;
}

// Each kept pair against the coarse grid's pair of the same axial vector nearest in λ among those of like weight
// (within a factor 10: a pair of another family near the same λ is not its match).
ConvergenceCheck check_against(const PartialFillSpectrum& coarse, const std::vector<Candidate>& kept, double height,
                               std::string reference, double tolerance) {
  ConvergenceCheck check;
  check.reference = std::move(reference);
  for (const Candidate& k : kept) {
    const PartialFillPair* best = nullptr;
    for (const auto& p : coarse.pairs) {
      const double w = weight(p, height);
      if (p.axial != k.pair->axial || w < 0.1 * k.E || w > 10 * k.E) continue;
      if (!best || std::abs(p.lambda - k.pair->lambda) < std::abs(best->lambda - k.pair->lambda)) best = &p;
    }
    check.changes.push_back(
        cluster_change(as_cluster(*k.pair, height), best ? as_cluster(*best, height) : Cluster{}, tolerance));
  }
  return check;
}

SeparableGrid annulus_grid(const PartialFillTableSettings& req, double b) {
  geometry::ShapeSpec annulus = req.shape;
  annulus.dims["inner_radius"] = b;
  return separable_grid(annulus, req.grid);
}


// The height within which a row's weight is its largest E (the Candidate's comment above).
double selection_height(const PartialFillTableSettings& req, const PartialFillSpectrum& s) {
  return req.shape.kind == "sphere"     ? 2 * req.shape.dims.at("radius")
         : req.shape.kind == "spheroid" ? 2 * req.shape.dims.at("c")
         : req.shape.kind == "section"  ? s.height
                                        : req.shape.dims.at("height");
}

// The pairs a table keeps as rows, by weight against the sum rule (cluster_selection.hpp).
std::vector<Candidate> kept_rows(const PartialFillTableSettings& req, const PartialFillSpectrum& s, double H) {
  const double sum_rule_wide = std::max({s.sum_rule_about(0), s.sum_rule_about(H), s.sum_rule_about(-H)});
  std::vector<Candidate> candidates;
  for (const auto& p : s.pairs) {
    const double w = weight(p, H);
    // Weights at rounding level (a sphere's modes but one: measured 1e-22 of the sum rule) are no modes to keep.
    if (std::abs(p.lambda) >= req.selection.geostrophic_cutoff && w > kRoundingWeight * sum_rule_wide)
      candidates.push_back({&p, w});
  }
  return select_clusters(std::move(candidates), req.selection, sum_rule_wide);
}

// The table of one spectrum: rows by weight, the convergence check against `coarse` (solved only when checked), the
// /free_surface attributes; the caller adds its discretisation's fields and solver line.
ModeTable spectrum_table(const PartialFillTableSettings& req, const PartialFillSpectrum& s,
                         const std::function<PartialFillSpectrum()>& coarse, const std::string& coarse_description,
                         const std::function<void(const std::string&)>& report) {
  const double H = selection_height(req, s);
  const std::vector<Candidate> kept = kept_rows(req, s, H);

  ModeTable t = start_table(req.shape, s.fluid, s.J_D);
  t.sum_rule = s.sum_rule;
  t.normalisation = "rho = 1, omega0 = 1; each mode's state (V, eta) is normalised to N2 = |V|^2 + b |eta|^2 = 1, "
                    "a = <U_c, W> about the liquid's centroid with the free surface's share, so E = 2 a^2 / N2; about "
                    "a point at height -c below the centroid a + c t (docs/physics.md §2, \"Partially filled tanks\")";
  t.tolerance = std::numeric_limits<double>::epsilon();
  t.free_surface = free_surface_attributes(s, req.fill);
  if (req.check_convergence) {
    if (report) report("convergence check on a coarser discretisation");
    add_convergence(t, check_against(coarse(), kept, H, coarse_description, req.convergence_tolerance),
                    req.convergence_tolerance);
  }
  std::vector<Cluster> clusters;
  for (const Candidate& k : kept) clusters.push_back(as_cluster(*k.pair));
  add_modes(t, clusters);
  // add_modes writes a = sqrt(E/2) ≥ 0: the offset coupling t takes the same sign change.
  for (const Candidate& k : kept) t.free_surface.t.push_back(k.pair->coupling.a < 0 ? -k.pair->coupling.t : k.pair->coupling.t);
  t.sort_by_energy();
  return t;
}

// The mesh method's spectra of one liquid, each mesh solved once: every pair by the dense solver when the mesh's
// unknowns fit req.max_unknowns; beyond, two levels — the rows the mesh with its sizes doubled keeps (solved the same
// way, and kept for the convergence check) give the targets of the sparse solver (free_surface_sparse.hpp).
class MeshSpectra {
 public:
  MeshSpectra(const PartialFillTableSettings& req, const geometry::ShapeSpec& liquid,
              const std::function<void(const std::string&)>& report)
      : req_(req), liquid_(liquid), report_(report) {}

  const PartialFillSpectrum& on(const geometry::MeshOptions& o) {
    for (const auto& [size, s] : solved_)
      if (size == o.size) return s;
    solved_.emplace_back(o.size, solve(FESpace(geometry::mesh_meridian(liquid_, o)), o, false));
    return solved_.back().second;
  }

  PartialFillSpectrum solve(const FESpace& space, const geometry::MeshOptions& o, bool keep_pressure) {
    const long unknowns = free_surface_unknowns(space);
    if (unknowns <= req_.max_unknowns) {
      PartialFillSpectrum s = solve_partially_filled_mesh(space, req_.max_unknowns, keep_pressure);
      say(fmt::format("{} pairs of {} pressure dofs (mesh size {:g}), sum of E - sum rule = {:.1e} (relative)",
                      s.pairs.size(), s.radial_dofs, o.size, (s.sum_E - s.sum_rule) / s.sum_rule));
      return s;
    }
    std::string unused;
    say(fmt::format("{} unknowns (mesh size {:g}) > {}: the targets from the mesh with its sizes doubled", unknowns,
                    o.size, req_.max_unknowns));
    const PartialFillSpectrum& coarse = on(coarser(o, unused));
    std::vector<double> targets;
    for (const Candidate& k : kept_rows(req_, coarse, selection_height(req_, coarse))) targets.push_back(k.pair->lambda);
    PartialFillSpectrum s = solve_partially_filled_near(space, targets, kPairsPerTarget, keep_pressure);
    say(fmt::format("{} pairs near {} targets (mesh size {:g}, sparse), their sum of E {:.4f} of the sum rule{}{}",
                    s.pairs.size(), targets.size(), o.size, s.sum_E / s.sum_rule,
                    s.skipped ? fmt::format("; {} near-double eigenvalues returned complex, not kept", s.skipped) : "",
                    s.short_targets ? fmt::format("; at {} targets fewer than {} pairs converged (the nearest kept)",
                                                  s.short_targets, kPairsPerTarget) : ""));
    return s;
  }

 private:
  void say(const std::string& line) const {
    if (report_) report_(line);
  }

  const PartialFillTableSettings& req_;
  geometry::ShapeSpec liquid_;
  std::function<void(const std::string&)> report_;
  std::list<std::pair<double, PartialFillSpectrum>> solved_;  // a list: references to its spectra stay valid
};

}  // namespace

ModeTable partially_filled_cylinder_table(const PartialFillTableSettings& req,
                                          const std::function<void(const std::string&)>& report) {
  const auto start = std::chrono::steady_clock::now();
  if (req.shape.kind != "cylinder" || req.shape.dims.count("inner_radius"))
    throw std::runtime_error("--fill by the separable method: a plain cylinder only (--method mesh takes the others)");
  if (!(req.fill > 0 && req.fill < 1)) throw std::runtime_error("--fill must be in (0, 1) for a partially filled tank");
  const double R = req.shape.dims.at("radius"), H = req.shape.dims.at("height");
  const double b = exact::partial_fill_surface_radius(R, req.fill);
  const SeparableGrid grid = annulus_grid(req, b);
  if (report) report(fmt::format("partially filled cylinder: free surface r = {:.10g}, {} x {} elements of order {}", b,
                                 grid.radial_elements(), grid.axial_elements(), grid.order));
  const PartialFillSpectrum s = solve_partially_filled_cylinder(R, H, req.fill, grid);
  const SeparableGrid c = coarser(grid);
  ModeTable t = spectrum_table(
      req, s, [&] { return solve_partially_filled_cylinder(R, H, req.fill, c); },
      fmt::format("order {} with every two neighbouring elements merged ({} radial x {} axial), pairs matched by axial "
                  "vector and nearest lambda", c.order, c.radial_elements(), c.axial_elements()),
      report);
  t.fe_order = grid.order;
  t.mesh_h = longest_element(grid.axial);
  t.mesh_h_radial = longest_element(grid.radial);
  t.ndof = static_cast<long>(s.radial_dofs) * s.axial_dofs;
  t.solver = fmt::format(
      "separable, free surface r = b: tensor-product P{} Lagrange elements ({} radial x {} axial) over b < r < a, one "
      "radial quartic per axial eigenvector made a symmetric quadratic by the surface unknown, each solved completely "
      "by a dense eigensolver (Eigen) of its companion form; sum of E over all pairs - (A_f + K2 - J_zh) = {:.1e} "
      "(relative)", grid.order, grid.radial_elements(), grid.axial_elements(), (s.sum_E - s.sum_rule) / s.sum_rule);
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

ModeTable partially_filled_mesh_table(const PartialFillTableSettings& req,
                                      const std::function<void(const std::string&)>& report, ModeFields* fields) {
  const auto start = std::chrono::steady_clock::now();
  const geometry::ShapeSpec liquid = geometry::partially_filled(req.shape, req.fill);
  geometry::MeshOptions mesh = req.grid;
  if (mesh.size == 0) mesh.size = geometry::default_mesh_size(liquid) * kFreeSurfaceSizeFactor;
  if (report) report(fmt::format("partially filled {}: free surface r = {:.10g}, order {}, mesh size {:g}",
                                 req.shape.kind, liquid.dims.at("free_radius"), mesh.order, mesh.size));
  MeshSpectra spectra(req, liquid, report);
  const FESpace space(geometry::mesh_meridian(liquid, mesh));
  const PartialFillSpectrum s = spectra.solve(space, mesh, fields != nullptr);
  std::string coarse_description;
  const geometry::MeshOptions c = coarser(mesh, coarse_description);
  ModeTable t = spectrum_table(req, s, [&] { return spectra.on(c); },
                               coarse_description + ", pairs matched by nearest lambda", report);
  t.fe_order = s.order;
  t.mesh_h = mesh.size;
  t.mesh_h_radial = mesh.radial_size;
  t.ndof = s.radial_dofs;
  t.solver = s.complete ? fmt::format(
      "mesh, free surface r = b: P{} Lagrange triangles ({} pressure dofs), the quartic made a symmetric quadratic by "
      "one unknown per surface dof, every eigenpair by a dense eigensolver (LAPACK) of its companion form; sum of E "
      "over all pairs - (A_f + K2 - J_zh) = {:.1e} (relative)", s.order, s.radial_dofs,
      (s.sum_E - s.sum_rule) / s.sum_rule)
      : fmt::format(
      "mesh, free surface r = b: P{} Lagrange triangles ({} pressure dofs), the quartic made a symmetric quadratic by "
      "one unknown per surface dof; beyond the dense solver's {} unknowns, the {} pairs nearest the rows of the mesh "
      "with its sizes doubled by SLEPc (TOAR, shift-and-invert, MUMPS LU): not every pair, so the coverage is what "
      "the rows hold of A_f + K2 - J_zh", s.order, s.radial_dofs, req.max_unknowns, kPairsPerTarget);
  if (fields) *fields = free_surface_fields(space, s, t);
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

}  // namespace rc::modes
