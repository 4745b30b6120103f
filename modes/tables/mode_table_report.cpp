#include "mode_table_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace rc::modes {

namespace {

std::string tensor_line(const char* name, const std::vector<double>& T) {
  return fmt::format("  {:<12} [{:.9g} {:.9g} {:.9g}; {:.9g} {:.9g} {:.9g}; {:.9g} {:.9g} {:.9g}]\n", name, T[0], T[1],
                     T[2], T[3], T[4], T[5], T[6], T[7], T[8]);
}

// A 3-D table's tensors and each mode's coupling to the three axes (|c_k|² = H_kk).
std::string volume_text(const ModeTable& t) {
  const auto& v = t.volume_cavity;
  std::string s = fmt::format("3-D cavity (docs/volume.md): centroid ({:.9g}, {:.9g}, {:.9g}), tilt {:g} rad; ",
                              v.centroid[0], v.centroid[1], v.centroid[2], v.tilt);
  const auto& f = t.volume_free_surface;
  s += f.present() ? fmt::format("partially filled to {:g}, its free surface the cylinder b = {:.10g} about the spin axis "
                                 "through ({:.9g}, {:.9g}) (docs/volume.md §8); the inertia about the centroid, the "
                                 "other tensors and the couplings about the axis's point at the centroid's height:\n",
                                 f.fill, f.radius, f.axis[0], f.axis[1])
                   : std::string("tensors about the centroid, spin axis z:\n");
  s += tensor_line("inertia", v.inertia) + tensor_line("zhukovsky", v.zhukovsky) + tensor_line("sum_rule", v.sum_rule) +
       tensor_line("geostrophic", v.geostrophic_re);
  s += "  coupling of each mode below to rotation about x, y, z (H_xx, H_yy, H_zz; E = H_xx + H_yy):\n";
  for (std::size_t i = 0; i < t.size(); ++i)
    s += fmt::format("  {:>4} {:.9e} {:.9e} {:.9e}\n", i + 1, v.coupling_re[9 * i], v.coupling_re[9 * i + 4],
                     v.coupling_re[9 * i + 8]);
  return s;
}

}  // namespace

std::string table_text(const ModeTable& t) {
  std::string dims;
  for (const auto& [k, v] : t.dimensions) dims += fmt::format(" {}={:g}", k, v);
  std::string s = fmt::format(
      "{}{}: order {}, h = {:g}{}, {} dofs, {}\n"
      "volume {:.12g}  centroid_z {:.6g}  A_f {:.12g}  C_f {:.12g}\n"
      "J_zh {:.12g}  sum rule {} {:.12g}  coverage {:.10f}\n"
      "solver: {} (tol {:g}), {:.2f} s\n",
      t.shape, dims, t.fe_order, t.mesh_h,
      t.mesh_h_radial > 0 ? fmt::format(" (axial; structured, radial h = {:g})", t.mesh_h_radial) : std::string(), t.ndof,
      t.volume_cavity.present() ? std::string("3-D (no axial symmetry)") : fmt::format("m = {}", t.m), t.volume, t.centroid_z, t.A_f, t.C_f, t.J_zh,
      t.free_surface.present() ? "A_f + K2 - J_zh" : "A_f - J_zh", t.sum_rule, t.coverage, t.solver, t.tolerance,
      t.wall_seconds);
  if (t.free_surface.present())
    s += fmt::format("partially filled: fill {:g}, free surface r = {:.12g} (rapid spin: the coaxial cylinder on which the "
                     "rigid rotation's pressure is constant, gravity neglected); the frozen liquid above is that "
                     "annulus; K0 {:.12g} K1 {:.12g} K2 {:.12g}, J1 {:.12g} J2 {:.12g}; about a point at height -c "
                     "below the centroid a mode couples with a + c t (docs/physics.md §2, \"Partially filled tanks\")\n",
                     t.free_surface.fill, t.free_surface.radius, t.free_surface.K0, t.free_surface.K1,
                     t.free_surface.K2, t.free_surface.J1, t.free_surface.J2);
  if (t.volume_cavity.present()) s += volume_text(t);
  if (t.viscous())
    s += fmt::format("viscous: Ekman number {:g}, wall element {:g}; each mode decays as exp(-decay t), its coupling "
                     "residue is E + i E_imag (docs/viscous.md)\n", t.ekman, t.mesh_h_wall);
  if (t.has_galerkin())
    s += fmt::format("galerkin: the {} modes' Gram and viscous matrices (chain-rom reduction = \"galerkin\"); viscous "
                     "form against the modes' decays: {:.1e} (docs/viscous.md, \"Galerkin matrices\")\n", t.size(),
                     t.galerkin.dissipation_mismatch);
  if (!t.geometry_source.empty()) {
    const auto lines = std::count(t.geometry_text.begin(), t.geometry_text.end(), '\n');
    s += fmt::format("geometry: {}{}\n", t.geometry_source,
                     t.geometry_text.empty() ? std::string()
                                             : fmt::format(" (its text, {} lines, is stored in the table: "
                                                           "cavity-modes info FILE --geometry prints it)", lines));
  }
  if (!t.command_line.empty()) s += fmt::format("made by: {}\n", t.command_line);
  if (!t.checksummed)
    s += "file format: HDF5's oldest (superblock version 0), whose metadata carry no checksums: damage to it is not "
         "detected on opening (a table written again by this cavity-modes has them)\n";
  const bool conv = !t.converged.empty();
  if (conv)
    s += fmt::format("convergence: against {}, tolerance {:g}; {} of {} clusters converged\n", t.convergence_reference,
                     t.convergence_tolerance, std::count(t.converged.begin(), t.converged.end(), 1), t.size());
  s += fmt::format("{:>4} {:>18} {:>18} {:>18} {:>10} {:>10} {:>4}", "#", "kappa", "lambda", "E", "spread",
                   "residual", "n");
  if (t.viscous()) s += fmt::format(" {:>14} {:>11}", "decay", "E_imag");
  if (t.free_surface.present()) s += fmt::format(" {:>13}", "t");
  s += conv ? fmt::format(" {:>9} {:>9} {:>5}\n", "dlambda", "dE", "conv") : "\n";
  for (std::size_t i = 0; i < t.size(); ++i) {
    s += fmt::format("{:>4} {:>18.12f} {:>18.12f} {:>18.12e} {:>10.2e} {:>10.2e} {:>4}", i + 1, t.kappa[i],
                     t.lambda[i], t.E[i], t.spread.empty() ? 0.0 : t.spread[i], t.residual[i],
                     t.members.empty() ? 1 : t.members[i]);
    if (t.viscous()) s += fmt::format(" {:>14.8e} {:>11.3e}", t.decay[i], t.E_imag[i]);
    if (t.free_surface.present()) s += fmt::format(" {:>13.6e}", t.free_surface.t[i]);
    s += conv ? fmt::format(" {:>9.1e} {:>9.1e} {:>5}\n", t.dlambda[i], t.dE[i], t.converged[i] ? "yes" : "NO")
              : "\n";
  }
  return s;
}

std::string convergence_note(const ModeTable& t) {
  const auto failed = std::count(t.converged.begin(), t.converged.end(), 0);
  if (t.converged.empty() || failed == 0) return {};
  if (t.viscous() && t.volume_cavity.present())  // a 3-D viscous table: no refinement rounds, no 3-D response table
    return fmt::format("note: {} of {} rows did not converge (lambda or E moved more than {:g} against {}): each row's "
                       "dlambda and dE estimate its error from above (about ten times it, measured on a spheroid: "
                       "docs/volume.md section 7); a smaller --mesh-size and --wall-size or a higher --order move them, "
                       "as far as memory allows; the response R_jk(sigma) (--sigma) needs no modes.",
                       failed, t.size(), t.convergence_tolerance, t.convergence_reference);
  const std::string trusted =
      t.viscous() ? "the damped modes marked yes and, for any shape, the response R(sigma) of `cavity-modes response` "
                    "(it converges where single modes do not); `--refine N` makes the table again on finer meshes "
                    "until its rows converge (docs/viscous.md, \"Refinement rounds\")"
                  : t.bands.size() > 0
                        ? fmt::format("J_zh, A_f, A_f - J_zh and the band weights (/bands, {} bands of width {:g}; "
                                      "check them with `cavity-modes compare` against a finer table), and any cluster "
                                      "marked yes", t.bands.size(), t.bands.hi[0] - t.bands.lo[0])
                        // a table without /bands (a partial fill's meridian table): no band weights to point to
                        : std::string("J_zh, A_f, A_f - J_zh (the sum rule), and any cluster marked yes");
  return fmt::format("note: {} of {} clusters did not converge (lambda or E moved more than {:g} against {}): do not "
                     "rely on them one by one. What converges under refinement here: {}. See docs/trust.md.",
                     failed, t.size(), t.convergence_tolerance, t.convergence_reference, trusted);
}

namespace {

// /modes as JSON: one array per column.
nlohmann::json modes_json(const ModeTable& t) {
  nlohmann::json m;
  m["kappa"] = t.kappa;
  m["lambda"] = t.lambda;
  m["E"] = t.E;
  m["a"] = t.a;
  m["N2"] = t.N2;
  m["residual"] = t.residual;
  if (!t.spread.empty()) m["spread"] = t.spread;
  if (t.viscous()) {
    m["decay"] = t.decay;
    m["E_imag"] = t.E_imag;
    m["a_imag"] = t.a_imag;
  }
  if (!t.members.empty()) m["members"] = t.members;
  if (!t.converged.empty()) {
    m["dlambda"] = t.dlambda;
    m["dE"] = t.dE;
    m["converged"] = t.converged;
  }
  return m;
}

}  // namespace

std::string table_json(const ModeTable& t) {
  nlohmann::json j;
  j["format"] = kModeTableFormat;
  j["version"] = t.volume_cavity.present() ? kVolumeTableVersion
                 : t.free_surface.present() ? kFreeSurfaceTableVersion : kModeTableVersion;
  j["shape"] = t.shape;
  for (const auto& [k, v] : t.dimensions) j[k] = v;
  j["fe_order"] = t.fe_order;
  j["mesh_h"] = t.mesh_h;
  if (t.mesh_h_radial > 0) j["mesh_h_radial"] = t.mesh_h_radial;
  j["ndof"] = t.ndof;
  j["m"] = t.m;
  j["volume"] = t.volume;
  j["centroid_z"] = t.centroid_z;
  j["A_f"] = t.A_f;
  j["C_f"] = t.C_f;
  j["J_zh"] = t.J_zh;
  j["sum_rule"] = t.sum_rule;
  j["coverage"] = t.coverage;
  j["solver"] = t.solver;
  j["tolerance"] = t.tolerance;
  j["wall_seconds"] = t.wall_seconds;
  j["normalisation"] = t.normalisation;
  j["ekman"] = t.ekman;
  if (t.mesh_h_wall > 0) j["mesh_h_wall"] = t.mesh_h_wall;
  if (t.mesh_h_near_wall > 0) j["mesh_h_near_wall"] = t.mesh_h_near_wall;
  if (t.response_fit()) {
    j["fit_lo"] = t.fit_lo;
    j["fit_hi"] = t.fit_hi;
    j["fit_error"] = t.fit_error;
    if (t.fit_decay_error >= 0) j["fit_decay_error"] = t.fit_decay_error;
  }
  if (t.has_galerkin())
    j["galerkin"] = {{"gram_re", t.galerkin.gram_re}, {"gram_im", t.galerkin.gram_im},
                     {"viscous_re", t.galerkin.viscous_re}, {"viscous_im", t.galerkin.viscous_im},
                     {"dissipation_mismatch", t.galerkin.dissipation_mismatch}};
  if (t.free_surface.present()) {
    const auto& f = t.free_surface;
    j["free_surface"] = {{"fill", f.fill}, {"radius", f.radius}, {"K0", f.K0}, {"K1", f.K1}, {"K2", f.K2},
                         {"J1", f.J1}, {"J2", f.J2}, {"t", f.t}};
  }
  if (t.volume_cavity.present()) {
    const auto& v = t.volume_cavity;
    j["cavity_3d"] = {{"centroid", v.centroid}, {"tilt", v.tilt}, {"inertia", v.inertia}, {"zhukovsky", v.zhukovsky},
                   {"sum_rule", v.sum_rule}, {"geostrophic_re", v.geostrophic_re},
                   {"geostrophic_im", v.geostrophic_im}, {"coupling_re", v.coupling_re}, {"coupling_im", v.coupling_im}};
  }
  if (!t.geometry_source.empty() || !t.command_line.empty())
    j["provenance"] = {{"geometry_source", t.geometry_source}, {"geometry_text", t.geometry_text},
                       {"command_line", t.command_line}};
  if (!t.converged.empty()) {
    j["convergence_reference"] = t.convergence_reference;
    j["convergence_tolerance"] = t.convergence_tolerance;
  }
  if (t.bands.size() > 0)
    j["bands"] = {{"lo", t.bands.lo}, {"hi", t.bands.hi}, {"E", t.bands.E}, {"lambda_mean", t.bands.lambda_mean}};
  const nlohmann::json m = modes_json(t);
  j["modes"] = m;
  return j.dump(2) + "\n";
}

}  // namespace rc::modes
