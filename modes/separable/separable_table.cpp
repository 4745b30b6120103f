#include "separable_table.hpp"

#include "cluster_selection.hpp"
#include "convergence.hpp"
#include "line_space.hpp"
#include "table_assembly.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

namespace rc::modes {
namespace {

constexpr int kDefaultOrder = 10, kMaxOrder = 12, kCornerLayers = 2;
constexpr long kMaxRadialDofs = 1000, kMaxAxialDofs = 5000;

int elements(double length, double size) {
  return std::max(1, static_cast<int>(std::ceil(length / size - 1e-9)));
}

// Modes that can be rows of a table: not the λ = −2 null vectors p = r w(z) (an exact discrete eigenvalue of
// every radial problem, where (Ar − Cr) r = 0; E = 0) and not below the λ ≈ 0 cut-off.
bool is_mode(const SeparableMode& m, double cutoff) { return m.radial > 0 && std::abs(m.lambda) >= cutoff; }

Cluster as_cluster(const SeparableMode& m) {
  Cluster c;
  c.lambda = m.lambda;
  c.E = m.E;
  c.residual = m.residual;
  c.members = 1;  // every discrete eigenpair is one mode: nothing to merge (separable_cylinder.hpp)
  return c;
}

using Label = std::pair<int, int>;  // (axial n, signed radial ±j)
Label label(const SeparableMode& m) { return {m.axial, m.lambda > 0 ? m.radial : -m.radial}; }

// Each kept mode against the mode of the same label (n, ±j) on the coarser grid.
ConvergenceCheck check_labels(const SeparableSpectrum& coarse, const std::vector<SeparableMode>& kept,
                              std::string reference, double tolerance) {
  std::map<Label, const SeparableMode*> by_label;
  for (const auto& m : coarse.modes)
    if (m.radial > 0) by_label[label(m)] = &m;
  ConvergenceCheck check;
  check.reference = std::move(reference);
  for (const auto& m : kept) {
    const auto it = by_label.find(label(m));
    Cluster ref;
    if (it != by_label.end()) ref = as_cluster(*it->second);
    check.changes.push_back(cluster_change(as_cluster(m), ref, tolerance));
  }
  return check;
}

std::vector<GaussNode> spectral_points(const SeparableSpectrum& s) {
  std::vector<GaussNode> points;
  for (const auto& m : s.modes) points.push_back({m.lambda, m.E});
  return points;
}

}  // namespace

SeparableGrid separable_grid(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh) {
  geometry::check_shape(shape);
  if (shape.kind != "cylinder")
    throw std::runtime_error(shape.kind + ": the separable method is only available for the cylinder (use --method mesh)");
  if (mesh.order != 0 && (mesh.order < 1 || mesh.order > kMaxOrder))
    throw std::runtime_error(fmt::format("separable method: order {} is outside 1..{}", mesh.order, kMaxOrder));
  for (double size : {mesh.size, mesh.radial_size})
    if (!std::isfinite(size) || size < 0)
      throw std::runtime_error(fmt::format("element size {} must be positive and finite (0 = default)", size));
  const double R = shape.dims.at("radius"), H = shape.dims.at("height"), d = std::min(R, H);
  const double b = shape.dims.count("inner_radius") ? shape.dims.at("inner_radius") : 0.0;
  // Radially the heavy modes oscillate like J1(ξ r/a), and ξ of the 20 largest grows only from 28 (2h/a = 2)
  // to 50 (2h/a = 0.25) and 53 (2h/a = 0.1): the radial size follows d down to a/2, not further (an annulus
  // keeps the full cylinder's element size over its narrower span).
  // An annulus keeps at least 4 elements across, however thin (a partially filled tank's thin liquid layer: the
  // graded corner layers at both of its walls need 2, its modes vary across it).
  int radial = elements(R - b, mesh.radial_size > 0 ? mesh.radial_size : std::max(d, R / 2) / 8);
  if (b > 0) radial = std::max(radial, 4);
  const int axial = elements(H, mesh.size > 0 ? mesh.size : 3 * d / 8);
  const SeparableGrid g = SeparableGrid::graded(R, H, mesh.order > 0 ? mesh.order : kDefaultOrder, radial,
                                                axial + axial % 2, kCornerLayers, b);
  // Dense pencils of 2N x 2N cost ~N³: 0.4 s measured at N = 384 on the project machine, so ~7 s at N = 1000
  // (extrapolated), each, for every coupled axial vector; beyond these sizes a run would take many minutes.
  const long radial_dofs = static_cast<long>(g.order) * g.radial_elements();
  const long axial_dofs = static_cast<long>(g.order) * g.axial_elements() + 1;
  if (radial_dofs > kMaxRadialDofs || axial_dofs > kMaxAxialDofs)
    throw std::runtime_error(fmt::format(
        "separable method: {} radial x {} axial dofs exceed what the dense solver handles ({} x {}); give a larger "
        "--radial-size / --mesh-size or a lower --order, or use --method mesh", radial_dofs, axial_dofs,
        kMaxRadialDofs, kMaxAxialDofs));
  return g;
}

SeparableGrid coarser(const SeparableGrid& grid) {
  SeparableGrid c = grid;
  c.radial = merged_pairs(grid.radial);
  c.axial = merged_pairs(grid.axial);
  return c;
}

ModeTable separable_cylinder_table(const SeparableTableSettings& req,
                                   const std::function<void(const std::string&)>& report) {
  const auto start = std::chrono::steady_clock::now();
  const SeparableGrid grid = separable_grid(req.shape, req.grid);
  const double R = req.shape.dims.at("radius"), H = req.shape.dims.at("height");
  const SeparableSpectrum s = solve_separable_cylinder(R, H, grid, [&](int done, int total) {
    if (report) report(fmt::format("radial problem {}/{} ({} dofs each)", done, total, grid.order * grid.radial_elements()));
  });

  std::vector<SeparableMode> candidates;
  for (const auto& m : s.modes)
    if (is_mode(m, req.selection.geostrophic_cutoff)) candidates.push_back(m);
  const std::vector<SeparableMode> kept = select_clusters(std::move(candidates), req.selection, s.sum_rule);
  std::vector<Cluster> clusters;
  for (const auto& m : kept) clusters.push_back(as_cluster(m));

  ModeTable t = start_table(req.shape, s.fluid, s.J_zh);
  t.fe_order = grid.order;
  t.mesh_h = longest_element(grid.axial);
  t.mesh_h_radial = longest_element(grid.radial);
  t.ndof = s.ndof;
  t.solver = fmt::format(
      "separable: tensor-product P{} Lagrange elements ({} radial x {} axial, {} corner layers included; {} x {} dofs) split "
      "exactly into {} radial QEPs, one per coupled axial eigenvector, each solved completely by a dense "
      "symmetric-definite eigensolver (Eigen); sum of E over all eigenpairs - (A_f - J_zh) = {:.1e} (relative)",
      grid.order, grid.radial_elements(), grid.axial_elements(), kCornerLayers, s.radial_dofs, s.axial_dofs,
      s.coupled_axial, (s.sum_E - s.sum_rule) / s.sum_rule);
  t.tolerance = std::numeric_limits<double>::epsilon();  // direct solver: backward errors in /modes/residual
  if (req.check_convergence) {
    const SeparableGrid c = coarser(grid);
    if (report) report("convergence check on a coarser grid");
    add_convergence(t, check_labels(solve_separable_cylinder(R, H, c), kept,
                                    fmt::format("order {} with every two neighbouring elements merged ({} radial x {} "
                                                "axial), modes matched by (axial n, radial j)", c.order,
                                                c.radial_elements(), c.axial_elements()),
                                    req.convergence_tolerance),
                    req.convergence_tolerance);
  }
  // Every eigenpair is known, so the band weights are exact for this discretisation (not a Gauss rule's).
  add_bands(t, band_weights(spectral_points(s)));
  add_modes(t, clusters);
  t.sort_by_energy();
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

}  // namespace rc::modes
