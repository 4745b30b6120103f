// The linearised chain (docs/physics.md §3): mass properties with the fluid added, the kept fluid modes, and
// the real matrices of system (26) of Kononov (fixed chain) or of its free-chain form
// (docs/free-chain.md), with elastic joints (27) and joint friction (Batyr (43)).
#pragma once

#include "axial_rotation.hpp"
#include "mode_table.hpp"
#include "scene.hpp"

#include "eigen_dense.hpp"

#include <complex>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rc::rom {

struct FluidMode {
  int body = 0;             // 0-based body index k
  int table_index = 0;      // row in the mode table
  double E = 0;             // E_kl scaled by density*scale^5 (kg m^2)
  double lambda = 0;        // lambda_kl = omega_k0 * lambda_table (rad/s), Kononov (21)
  double lambda_table = 0;  // the table's lambda (scale-free, omega0 = 1)
  double nu = 0;            // omega_k0 - lambda_kl
  double a_over_N2 = 0;     // a_kl / N_kl^2 (m), converts the scaled coordinate z back to S'
  // Viscous tables (docs/viscous.md section 1, docs/rom.md "Viscous tanks"): the mode is e^{i lambda_c t} with
  // lambda_c = lambda + i decay (rad/s), its coupling the complex residue E_c = E + i E_imag. Both 0 when ideal.
  double E_imag = 0;        // kg m^2
  double decay = 0;         // omega_k0 * decay_table (1/s)
  int converged = -1;       // the table's flag for this cluster: 1 yes, 0 no, -1 the table has no flags
  // A partially filled tank on a body whose joint moves (docs/physics.md §2, "A tank whose joint moves"): the liquid
  // feels the joint's acceleration, so the mode couples to earlier bodies' tilts u_j too, with weight lever_j against
  // its own body's 1 (complex for a viscous table). Empty: it couples to its own body alone, as every filled tank.
  std::vector<std::pair<int, std::complex<double>>> lever;
  // The same on a free chain's base translation X (1/m; base_translation.hpp): 0 unless the tank is partially filled.
  std::complex<double> lever_base = 0;
  // Its weight on its own body's tilt: 1, or, for a row whose coupling about O_k is smaller than its translation's
  // (|a + c t| < |t|: an even mode with the joint at the equator's height couples to the joint's motion alone), the
  // ratio (a + c t)/t, with E and the levers the translation's (set_lever): the same E w wᵀ, finite where a + c t = 0.
  std::complex<double> own = 1;
  std::complex<double> E_c() const { return {E, E_imag}; }
  std::complex<double> lambda_c() const { return {lambda, decay}; }
  std::complex<double> nu_c() const { return {nu, -decay}; }  // omega_k0 - lambda_c
};

// The mode's coupling row w (w_k = own for its own body k, lever_j for the earlier ones): its forcing is
// wᵀ(ü + iω_k0 u̇) and its term of (22) E w wᵀ. Adds scale · w wᵀ to the square complex matrix A.
template <class Mat, class Scalar>
void add_mode_term(Mat& A, const FluidMode& md, Scalar scale) {
  const Scalar own = static_cast<Scalar>(md.own);
  A(md.body, md.body) += scale * own * own;
  for (const auto& [j, r] : md.lever) {
    const Scalar rj = static_cast<Scalar>(r);
    A(md.body, j) += scale * own * rj;
    A(j, md.body) += scale * own * rj;
    for (const auto& [i, q] : md.lever) A(j, i) += scale * rj * static_cast<Scalar>(q);
  }
}

// wᵀ v: the combination of the bodies' tilt velocities (or accelerations) the mode is forced by.
template <class Vec>
typename Vec::Scalar coupled(const FluidMode& md, const Vec& v) {
  using S = typename Vec::Scalar;
  S out = static_cast<S>(md.own) * v[md.body];
  for (const auto& [j, r] : md.lever) out += static_cast<S>(r) * v[j];
  return out;
}

struct BodyModel {
  // totals with the frozen fluid included (docs/physics.md §3: A_k, C_k, m_k include the fluid)
  double m = 0, A = 0, C = 0, c = 0, s = 0, omega = 0;
  bool has_fluid = false;
  double m_f = 0, A_f = 0, C_f = 0, J_zh = 0, sum_rule = 0;  // scaled fluid data (A_f, J_zh about the centroid)
  double fluid_center = 0;  // O_k -> the fluid's centroid along the axis (m): the scene's center, or origin + L·z_c
  // A partially filled tank (the table's /free_surface): its static inertia K(O_k) (kg m², in A above) and its modes'
  // couplings are about O_k (docs/physics.md §2, "Partially filled tanks").
  bool free_surface = false;
  double K_free_surface = 0;
  // On a body whose joint moves K is a form in (u_k, y), y = Σ_{j<k} s_j u_j the joint's displacement: K(O_k) u_k² +
  // 2 K_cross u_k y + K_shift y² (kg m, kg): ρL⁴(K1 + cK0) and ρL³K0 (docs/physics.md §2, "A tank whose joint moves").
  double K_cross = 0, K_shift = 0;
  double E_kept = 0;         // sum of the kept E_kl
  double E_rem = 0;          // static-correction inertia (0 unless static_correction)
  double static_moment = 0, pitch_damping = 0;  // [body.aero] (in K and D already; kept to report S_g)
  double E_kept_imag = 0, E_rem_imag = 0;  // imaginary parts of the two (viscous tables); E_rem_imag = -E_kept_imag
  double ekman = 0;          // the table's Ek (0: ideal fluid)
  // A response-fit table (docs/viscous.md, "Response fit"): its modes stand for R(s) on s in [fit_lo, fit_hi]
  // (table units, s = (sigma + omega)/omega) to fit_error; outside, the fit is extrapolated. fit_hi > fit_lo marks it.
  double fit_lo = 0, fit_hi = 0, fit_error = 0;
  double fit_decay_error = -1;  // a Krylov table's error of Im R against itself (the decays'); < 0: not measured
  // … and that error at each s of the window (the table's /fit_decay; empty for older tables and other kinds)
  std::vector<double> fit_decay_s, fit_decay_profile;
  // The table's Im R error at s (table units), linear between the profile's frequencies; −1 where it is not known
  // (no profile, or s outside it).
  double fit_decay_error_at(double s) const;
  // Such a table's rows left out as no root needs them (response_row_pruning.hpp).
  int pruned_rows = 0;
  std::string response_kind;  // such a table's: "a Krylov response table", "a Galerkin response table" or "a response fit"
  double coverage = 0;       // E_kept / sum_rule
  int unconverged = 0;       // kept clusters the table flags as not converged
  std::string table;
  // A Galerkin tank's kept modes' fluid energy and dissipation forms in the chain's coordinates z (kg m^2, kg m^2/s;
  // galerkin_fluid.hpp); empty otherwise (an ideal tank's are diag(E) and 0: galerkin_energy.cpp makes them there,
  // off the sweeps' path; a viscous modal tank or a rational fit holds no energy of its own in the model).
  bool galerkin = false;     // reduction = "galerkin": its modes' E are the Galerkin residues
  Eigen::MatrixXcd fluid_energy, fluid_dissipation;
};

struct ChainModel {
  int n = 0;
  bool free_chain = false;
  double g = 0;
  std::vector<BodyModel> bodies;
  std::vector<FluidMode> modes;
  Eigen::VectorXd a;     // a_k = m_k c_k + s_k sum_{i>k} m_i (Kononov after (10))
  Eigen::MatrixXd M;     // inertia matrix of (26) (fixed) or of the free chain
  Eigen::MatrixXd K;     // -diag(a_k g) (fixed only) + elastic joints, Kononov (27)
  // The Magnus moments' circulatory stiffness: −i diag(circulatory) joins K (complex_stiffness); 0 without [body.aero].
  Eigen::VectorXd circulatory;
  Eigen::MatrixXd D;     // joint friction, Batyr (43)
  Eigen::VectorXd G;     // C_k omega_k0 (gyroscopic term of (26))
  Eigen::MatrixXd M_eff; // M - diag(sum_l E_kl + E_rem_k): inertia seen by u-double-dot (its real part)
  Eigen::MatrixXd M_eff_imag;  // -Im(Σ_l E_kl w wᵀ + diag(E_rem)): 0 for ideal tables and with static_correction
  bool viscous = false;  // some cavity has a viscous table (complex lambda_kl, E_kl)
  AxialChain axial;      // the spins' own block (axial_rotation.hpp): decoupled from (26) at first order
  // A free chain with a partially filled tank (base_translation.hpp): the chain with its base's translation as
  // coordinate n, from which Φ, B and the energy are reduced; M and M_eff above are then its Schur complements on X
  // (what the chain's bodies feel at rest). Null otherwise.
  std::shared_ptr<const ChainModel> extended;
  int size() const { return n; }
  int n_modes() const { return static_cast<int>(modes.size()); }
  bool has_friction() const { return D.cwiseAbs().maxCoeff() > 0; }
  bool has_circulatory() const { return circulatory.size() > 0 && circulatory.cwiseAbs().maxCoeff() > 0; }
  // Friction, viscous fluid or a Magnus moment (not conservative): roots leave the real axis, and stable means no
  // growing root.
  bool dissipative() const { return has_friction() || viscous || has_circulatory(); }
};

// The stiffness of (26) with the Magnus moments: K − i diag(circulatory) (docs/rom.md, "A projectile's aerodynamic
// moments"); K itself without them.
Eigen::MatrixXcd complex_stiffness(const ChainModel& m);

// The scene's initial fluid coordinates z_kl(0) (initial.fluid), one per kept mode of the model, body by body; zeros
// when absent. Throws SceneError naming initial.fluid when the count differs from the kept modes'.
Eigen::VectorXcd initial_fluid(const Scene& scene, int n_modes);

// Relative tolerance between the scene's Ek = nu/(|omega_k0| L^2) and a viscous table's ekman.
inline constexpr double kEkmanTolerance = 0.01;

// A viscous table needs the scene's viscosity, and the two must give the same Ekman number
// Ek = nu/(|omega_k0| L^2) within kEkmanTolerance (docs/rom.md, "Viscous tanks"); an ideal table takes none. Throws
// SceneError naming `key`.viscosity otherwise.
void check_viscosity(const Scene& scene, const std::string& key, const CavitySpec& cav, const rc::ModeTable& t,
                     double omega);

// Mode tables read once and kept, for callers that build many models from one scene (sweeps).
// get() reads a file the first time it is asked for (throws what rc::read_mode_table throws);
// once every table is in, concurrent get() calls only read the map.
class TableCache {
 public:
  const rc::ModeTable& get(const std::filesystem::path& file);
  std::size_t size() const { return tables_.size(); }

 private:
  std::map<std::string, rc::ModeTable> tables_;
};

// Builds the model; reads the mode tables (through `tables` when given, else from disk). Throws
// SceneError naming the key on a bad table (not a table, m != 1, modes above the table's count,
// coverage not reachable) or when the effective inertia matrix is not positive definite, and (unless
// linear_keys_only is false: the nonlinear model's totals and fluid, nonlinear_run.hpp) on the keys only the nonlinear
// model takes (B != A, moments, axial friction).
ChainModel build_model(const Scene& scene, TableCache* tables = nullptr, bool linear_keys_only = true);

}  // namespace rc::rom
