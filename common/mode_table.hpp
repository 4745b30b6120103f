// The mode table: the contract between cavity-modes (writer) and chain-rom (reader).
// Layout is docs/physics.md §4: root attributes + datasets under /modes, one entry per mode (spectral
// cluster), sorted by E descending. All values for rho = 1 in the geometry's length unit, omega0 = 1.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rc {

inline constexpr const char* kModeTableFormat = "cavity-mode-table";
// Version 2 added the viscous fields (ekman, mesh_h_wall, /modes/decay, E_imag, a_imag); version 1 tables read as
// ideal tables (ekman = 0). Version 3 is written only for a partially filled tank's table (/free_surface), so that
// a reader that does not know the free surface refuses it instead of reading it as a filled tank's.
inline constexpr int kModeTableVersion = 2;
inline constexpr int kFreeSurfaceTableVersion = 3;
// Version 4 is written only for a 3-D cavity's table (/volume), for the same reason: a reader that knows only
// axisymmetric tanks refuses it. Every earlier version stays readable.
inline constexpr int kVolumeTableVersion = 4;

struct ModeTable {
  // --- root attributes -------------------------------------------------------------------
  std::string shape;                         // "sphere", "spheroid", "cylinder", "cone", "section"
  std::map<std::string, double> dimensions;  // e.g. {"radius", 1}, {"height", 2}; each is a root attribute
  int fe_order = 0;
  double mesh_h = 0;
  double mesh_h_radial = 0;  // > 0: structured cylinder mesh with this radial size (mesh_h is then axial)
  long ndof = 0;
  int m = 1;                 // azimuthal number (1: the modes that couple to tilt)
  double volume = 0;         // fluid volume (= mass for rho = 1)
  double centroid_z = 0;     // fluid centroid on the axis, in the geometry's coordinates
  double A_f = 0;            // frozen fluid transverse inertia about the centroid
  double C_f = 0;            // frozen fluid axial inertia
  double J_zh = 0;           // Zhukovsky transverse inertia about the centroid
  double sum_rule = 0;       // A_f - J_zh = sum of E over all m = 1 modes (docs/physics.md §2)
  double coverage = 0;       // sum of the kept E / sum_rule
  std::string solver;        // human-readable description of the eigen-solver used
  double tolerance = 0;      // solver tolerance
  double wall_seconds = 0;
  std::string normalisation; // how a and N2 are normalised (free text, stored in the file)
  std::string convergence_reference;  // the coarser discretisation the clusters were compared with
  double convergence_tolerance = 0;   // a cluster is "converged" if its λ and E moved less than this (relative)
  double ekman = 0;          // Ek = ν/(ω0 L²); 0: ideal fluid (docs/viscous.md)
  double mesh_h_wall = 0;    // > 0: element size at the wall of a wall-graded mesh (viscous tables)
  double mesh_h_near_wall = 0;  // > 0: the near-wall zone's element size (viscous tables; chain-rom confirm serves it)
  // Response-fit tables (`cavity-modes response ... -o FILE.h5`, docs/viscous.md "Response fit"): the modes are
  // the poles and residues of a rational fit of R(s) on the real window [fit_lo, fit_hi], which matches R between
  // its samples to fit_error (max |R − fit| / max |R|). fit_hi > fit_lo marks such a table; 0, 0 otherwise.
  double fit_lo = 0, fit_hi = 0, fit_error = 0;
  // A Krylov table's estimated error of Im R against Im R itself on the window (the decays' relative error;
  // docs/viscous.md, "The error of Im R"); < 0: not measured (attribute fit_decay_error absent).
  double fit_decay_error = -1;
  // … and that estimate at each frequency of the window (/fit_decay: s increasing in [fit_lo, fit_hi], error ≥ 0):
  // what the fit may take from the decay of a chain root at that frequency. Empty: not stored (older tables, fits).
  std::vector<double> fit_decay_s, fit_decay_profile;
  bool response_fit() const { return fit_hi > fit_lo; }
  // Provenance (/provenance, optional; docs/physics.md §4): how the table was made, so that it can be made again.
  // geometry_source: "sphere radius=1" for a built-in shape, the section file's name for `section FILE`;
  // geometry_text: that section file's full text (empty for built-in shapes); command_line: the command as typed.
  // Read from the file: whether its metadata carry checksums (HDF5 superblock version 2 or later, as written since
  // 2026-11-26); an older table reads the same, without that protection (`cavity-modes info` says so).
  bool checksummed = true;
  std::string geometry_source, geometry_text, command_line;

  // --- /modes datasets, one entry per mode ------------------------------------------------
  std::vector<double> kappa, lambda, E, a, N2, residual;
  std::vector<double> spread;  // E-weighted spread of lambda within the cluster (error indicator)
  std::vector<int> members;    // number of discrete eigenpairs in the cluster
  std::vector<double> dlambda, dE;  // relative change of λ and E against the coarser discretisation
  std::vector<int> converged;       // 1 if both changes are within convergence_tolerance
  // Viscous tables only (ekman > 0; empty otherwise): a mode is e^{iλt} with λ = lambda + i·decay, so its
  // amplitude decays as e^{−decay·ω0 t}; its coupling residue is E + i·E_imag (the ideal E is its Ek → 0 limit)
  // and a + i·a_imag its square root times 1/√2 (N2 = 1 in the complex symmetric normalisation).
  std::vector<double> decay, E_imag, a_imag;
  bool viscous() const { return ekman > 0; }

  // --- /galerkin (damped-mode tables, optional): the rows' modes as a Galerkin basis (docs/viscous.md, "Galerkin
  // matrices"). With x_l the row's mode (xᵀ𝓜x = 1, unconjugated), G_lk = x̄_lᵀ 𝓜 x_k (the kinetic-energy Gram
  // matrix, Hermitian positive definite) and V_lk = Ek x̄_lᵀ K x_k (the viscous dissipation form, Hermitian positive
  // semi-definite), each n × n row-major by row order. The reduced fluid G ċ = i (GΛ) c + forcing keeps the energy
  // ½ cᴴGc and dissipates cᴴVc exactly (rom: docs/rom.md, "Galerkin tanks").
  struct Galerkin {
    std::vector<double> gram_re, gram_im, viscous_re, viscous_im;
    // A Galerkin response table's rows (pseudo-modes: cavity-modes response --galerkin) carry their couplings
    // f_l = fᵀx_l here (their E is already the Galerkin residue); empty for damped modes, whose f_l follow from a.
    std::vector<double> coupling_re, coupling_im;
    // max |V − (GΛ − ΛᴴG)/(2i)| / max |V|: V from the viscous matrix against V from the Gram matrix and the rows'
    // λ + i·decay (they agree when the modes are exact eigenvectors); -1 when not measured
    double dissipation_mismatch = -1;
    bool empty() const { return gram_re.empty(); }
  } galerkin;
  bool has_galerkin() const { return !galerkin.empty(); }

  // --- /free_surface (partially filled tanks, optional; docs/physics.md §2, "Partially filled tanks"): the liquid
  // fills the cavity's part r ≥ radius, its free surface the cylinder r = radius (rapid spin). The modes' a and E
  // are then about the liquid's centroid and include the surface's share; about a point O at height −c below the
  // centroid (c in the table's length unit) a mode couples with a + c·t and E(c) = 2(a + c t)²/N2, the tank's
  // static inertia gains K(c) = K2 + 2c K1 + c² K0 and Zhukovsky's inertia (free surface at zero potential) is
  // J_zh + 2c J1 + c² J2 about O (A_f + volume c² for the frozen liquid). sum_rule = A_f + K2 − J_zh.
  struct FreeSurface {
    double fill = 1;      // the liquid's volume fraction of the cavity
    double radius = 0;    // b > 0 marks a partially filled tank's table
    double K0 = 0, K1 = 0, K2 = 0;
    double J1 = 0, J2 = 0;
    std::vector<double> t;       // per mode, with the /modes rows
    std::vector<double> t_imag;  // viscous tables: its imaginary part (a + c t complex as a is), else empty
    bool present() const { return radius > 0; }
    double K(double c) const { return K2 + 2 * c * K1 + c * c * K0; }
  } free_surface;
  // --- /volume (3-D cavities without axial symmetry, optional; docs/volume.md §5): the modes are those with
  // λ > 0 of the complex problem (a mode at −λ is the complex conjugate of one of them: the same real motion), and
  // each carries its Hermitian coupling tensor H = c cᴴ (c_k = ∫ (e_k × r)·V, ‖V‖ = 1, r from the centroid; summed
  // over a cluster), 9 complex entries row-major per mode. The /modes rows then hold E = H_xx + H_yy (the transverse
  // coupling; an axisymmetric cavity's m = 1 E), a = √(E/2), N2 = 1. Tensors are 3 × 3 row-major, about the centroid,
  // in the spin frame (z the spin axis): the frozen fluid's inertia, Zhukovsky's inertia, and their difference
  // sum_rule = Σ over every mode of both signs of H (the tensor sum rule); geostrophic: the part of it at λ = 0.
  // Root A_f = (I_xx + I_yy)/2, C_f = I_zz, J_zh = (J_xx + J_yy)/2.
  struct Volume {
    std::vector<double> centroid;  // 3
    double tilt = 0;               // built-in shapes: the angle of the shape's own axis against z (radians)
    std::vector<double> inertia, zhukovsky, sum_rule, geostrophic_re, geostrophic_im;  // 9 each
    std::vector<double> coupling_re, coupling_im;                                      // 9 per mode
    // The coupling in the /bands' λ-bands (optional; docs/volume.md §5): per band the sum of the survey's Gauss
    // nodes' H with λ > 0 in it (9 complex entries) and their trace-weighted mean λ (0 where empty) — a dense
    // cluster's weight as a whole, light modes included.
    std::vector<double> band_coupling_re, band_coupling_im, band_lambda;
    bool present() const { return !inertia.empty(); }
  } volume_cavity;

  // --- /volume_free_surface (a partially filled 3-D tank, on or off the craft's spin axis, optional; docs/volume.md §8):
  // the liquid fills the part of the cavity beyond the cylinder of `radius` b about the spin axis, a line parallel to z
  // through `axis` (x, y in the table's coordinates). /volume then holds the frozen liquid's inertia about its centroid
  // and, about P0 (the axis's point at the centroid's height), each row's 3 × 3 rotation coupling (E = H_xx + H_yy),
  // sum_rule (I_f − J_D + K), zhukovsky (J_D, the surface at zero potential) and geostrophic. Here the five directions
  // (U_x, U_y, U_z, T̂_x, T̂_y): the rotations about P0 and the offsets along the axis, so that the rotation about the
  // point O = P0 − c ẑ is U_k + c T̂_k — each row's 5 × 5 H (25 complex entries, row-major), their Gram matrix
  // (Σ H over every mode of both signs), the λ = 0 part of it, and surface_gram = b ∫ η_i η_j dS of the directions' free
  // surface parts (the re-centring inertia K(O) = B surface_gram Bᵀ, B = [I₃ | c(e_x, e_y)]).
  struct VolumeFreeSurface {
    double fill = 1;
    double radius = 0;           // b > 0 marks it
    std::vector<double> axis;    // 2
    std::vector<double> coupling_re, coupling_im;  // 25 per mode
    std::vector<double> gram_re, gram_im, geostrophic_re, geostrophic_im, surface_gram;  // 25 each
    bool present() const { return radius > 0; }
  } volume_free_surface;
  // A partially filled tank's table (either kind): its rows may lie beyond |λ| = 2 (surface waves).
  bool partially_filled() const { return free_surface.present() || volume_free_surface.present(); }

  // The sum over every mode of E about O (= E for a filled tank, whatever c): A_f(O) + K(O) − J_zh(O).
  double sum_rule_about(double c) const;

  // --- /bands: the spectral weight in λ-bands covering (−2, 2) (optional) ---------------------
  struct Bands {
    std::vector<double> lo, hi;        // band edges
    std::vector<double> E;             // spectral weight Σ E in the band
    std::vector<double> lambda_mean;   // E-weighted mean λ in the band (0 where E = 0)
    std::size_t size() const { return E.size(); }
  } bands;

  std::size_t size() const { return E.size(); }
  // Throws std::runtime_error if the arrays disagree in length, hold non-finite values or break one of the table's
  // identities (check_identities).
  void validate() const;
  // κλ = 2, λ ≠ 0, N² > 0, E = 2a²/N² (complex for viscous tables), |λ| ≤ 2 for ideal tables, sum_rule = A_f − J_zh,
  // volume > 0, the convergence columns together. Throws std::runtime_error("table identity fails: ...").
  void check_identities() const;
  // Sorts every /modes array (and the /galerkin matrices' rows and columns) by E descending.
  void sort_by_energy();
};

// Why two tables do not describe the same cavity: another shape, other dimensions (names, or values beyond 1e-12
// relative), or, both texts stored, another section file; empty when they do. Whether one may be viscous and the
// other ideal, or at another Ekman number, is the caller's question (cavity-modes compare; chain-rom companions).
std::string cavity_difference(const ModeTable& a, const ModeTable& b);

struct ModeFields;  // mode_fields.hpp

// Writes to a temporary name beside `path` and renames it into place, so a failure never leaves a
// partial table. Throws std::runtime_error with a one-line cause.
// With `fields`, the table also gets /fields and an XDMF companion (xdmf_companion(path)), written and
// renamed the same way; without, a stale companion of ours (it carries kFieldsXdmfMarker) is removed.
void write_mode_table(const ModeTable& table, const std::filesystem::path& path, const ModeFields* fields = nullptr);

// FILE.xdmf beside FILE.h5.
std::filesystem::path xdmf_companion(const std::filesystem::path& table_path);

// Reads and validates a table; throws std::runtime_error("<path>: <cause>") on any problem
// (missing file, not HDF5, wrong format attribute, missing dataset, inconsistent lengths).
// Optional datasets (spread, members, dlambda, dE, converged, /bands) are read when present and left empty
// otherwise.
ModeTable read_mode_table(const std::filesystem::path& path);

}  // namespace rc
