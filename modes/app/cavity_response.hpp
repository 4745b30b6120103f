// `cavity-modes response SHAPE ...`: the fluid's moment response R(σ) = Σ_l E_l/(σ − λ_l) (+ a constant for the
// viscous fluid) at given complex frequencies, for one cavity, by the method the request names:
//   viscous (--ekman):      forced solves on the Taylor–Hood wall-layer mesh (viscous/viscous_response.hpp);
//   ideal, --method mesh:   forced solves of the Poincaré problem on the gmsh mesh, no modes (ideal/ideal_response.hpp);
//   ideal, separable:       the cylinder's sum over EVERY eigenpair of the separated problem (separable_cylinder.hpp),
//                           the independent mode-sum check of the forced solves (docs/viscous.md, "Response function").
#pragma once

#include "meridian_mesh.hpp"
#include "mode_table.hpp"
#include "window_fit.hpp"

#include <complex>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace rc::modes {

struct ResponseRequest {
  geometry::ShapeSpec shape;
  geometry::MeshOptions mesh;   // resolved: the viscous mesh, or the ideal mesh/grid (0 = the method's defaults)
  double ekman = 0;             // 0: ideal fluid
  bool separable = false;       // ideal cylinder: the separable mode sum instead of forced solves
  double fill = 1;              // below 1 a partially filled tank: R about the liquid's centroid and its offset parts
  // A partially filled tank's response fit: R about a point at height −offset below the centroid (table units),
  // R_ff + 2c R_fg + c² R_gg; 0: about the centroid.
  double offset = 0;
  std::vector<std::complex<double>> sigmas;
  // A Krylov response table's frequencies where its R must be the fluid's own (viscous/krylov_response.hpp).
  std::vector<std::complex<double>> exact_at;
  // A response-fit table's forced solves kept as they are made (viscous/response_samples.hpp); empty: not kept.
  std::filesystem::path samples_file;
};

struct CavityResponse {
  std::vector<std::complex<double>> R;
  // A partially filled tank (fill < 1): R about a point at height −c below the liquid's centroid is
  // R + 2c R_fg + c² R_gg (viscous_response.hpp, OffsetResponse); empty otherwise.
  std::vector<std::complex<double>> R_fg, R_gg;
  std::string method;  // one line: what computed R and on which discretisation (the CSV's header)
  long unknowns = 0;   // real unknowns of the forced solves (0 for the separable sum)
};

// Throws std::runtime_error / std::invalid_argument with a one-line cause.
CavityResponse compute_cavity_response(const ResponseRequest& request);

// The viscous response sampled on FROM:TO:N (real σ, N >= 9) and fitted by a rational function on every other
// sample (viscous/rational_fit.hpp), its error measured on the samples in between: a viscous mode table whose
// modes are the fit's poles and residues, with the window and the error as root attributes (fit_lo, fit_hi,
// fit_error) and the ideal table's frozen-fluid integrals and J_zh from the ideal mesh. Throws std::runtime_error
// with a one-line cause, also when the fit error exceeds `max_error`: the forced solves are then still in
// request.samples_file, which the same command reads back (the caller removes it once the table is written).
ModeTable response_fit_table(const ResponseRequest& request, double max_error);

// A response table's window (req.sigmas): --ekman given, N >= 9 increasing real frequencies; else one line starting
// with `what` ("a response-fit table").
void check_response_window(const ResponseRequest& request, const std::string& what);

// A response table before its rows: the ideal problem's frozen-fluid integrals and J_zh (the shape's default mesh),
// the viscous mesh's description, `unknowns`, and the window as fit_lo, fit_hi.
ModeTable response_table_start(const ResponseRequest& request, long unknowns);

// "FROM:TO:N" (N evenly spaced real parts, every one with imaginary part `imag`) or a comma-separated list of
// complex numbers "0.5+0.1i,1.2,-0.3-2e-2i" (then `imag` must be 0). Throws std::runtime_error naming the
// malformed item.
std::vector<std::complex<double>> parse_sigma_spec(const std::string& spec, double imag);

// `cavity-modes response SHAPE ... --ekman Ek --serve`: assembles the viscous forms once, writes one line
// "ready: <the method line>" on `out`, then answers each line of `in` (one complex sigma, written as --sigma's list
// items are) with one line "R_re R_im" (17 significant digits; a partially filled tank, fill < 1: "R_re R_im R_fg_re
// R_fg_im R_gg_re R_gg_im", R about the liquid's centroid and its offset parts), flushed, until end of input or an
// empty line. A line
// it cannot answer (not a number, a failed factorisation) gets "error: <one line>" and the session goes on. Serial
// only; chain-rom confirm drives it (docs/rom.md, "Confirmed roots"). Throws std::runtime_error without --ekman.
void serve_response(const ResponseRequest& request, std::istream& in, std::ostream& out);

// CSV: `#` lines (the method, the definition), then sigma_re, sigma_im, R_re, R_im per line, and for a partially
// filled tank R_fg_re, R_fg_im, R_gg_re, R_gg_im after them. Written to a temporary name and renamed, so no
// half-written file is ever left.
void write_response(const std::string& path, const std::vector<std::complex<double>>& sigma, const CavityResponse& R);

}  // namespace rc::modes
