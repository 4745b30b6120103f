#include "chain_model.hpp"

#include "base_translation.hpp"
#include "field_gradient.hpp"

#include "galerkin_fluid.hpp"
#include "mode_table.hpp"
#include "response_row_pruning.hpp"
#include "row_coupling.hpp"

#include <algorithm>
#include <complex>
#include <cmath>
#include <sstream>

namespace rc::rom {
namespace {

// The table of body k's cavity: from the cache when there is one, else read here into `own`.
const rc::ModeTable& cavity_table(const Scene& scene, const std::string& w, const CavitySpec& cav, TableCache* tables,
                                  rc::ModeTable& own) {
  const rc::ModeTable* table = nullptr;
  try {
    if (tables) {
      table = &tables->get(cav.table);
    } else {
      own = rc::read_mode_table(cav.table);
      table = &own;
    }
  } catch (const std::exception& e) {
    fail(scene, w + ".table", e.what());
  }
  if (table->volume_cavity.present())
    fail(scene, w + ".table", "a 3-D cavity's table (no axial symmetry): `chain-rom spectrum`, `run` and `sweep` take it "
         "(the chain without axial symmetry, docs/rom.md); this command takes axisymmetric tanks only so far");
  return *table;
}

// ρL⁵: a table's inertias and E to the scene's (docs/physics.md §4), multiplied out as L³·L·L.
double inertia_unit(const CavitySpec& cav) {
  const double L = cav.scale, L3 = L * L * L;
  return cav.density * (L3 * L * L);
}

// The frozen fluid of body k in chain units (docs/physics.md §4: mass ~ ρL³, A_f, C_f, J_zh, E ~ ρL⁵), its centroid
// from O_k and, for a partially filled tank, its re-centring inertia and the sum rule about O_k.
void set_frozen_fluid(const Scene& scene, const std::string& w, const CavitySpec& cav, const rc::ModeTable& t,
                      BodyModel& b) {
  const double rho = cav.density, L = cav.scale, L3 = L * L * L, L5 = L3 * L * L;  // rho L5 as before the split
  b.has_fluid = true;
  b.table = cav.table.string();
  b.m_f = rho * L3 * t.volume;
  b.A_f = rho * L5 * t.A_f;
  b.C_f = rho * L5 * t.C_f;
  b.J_zh = rho * L5 * t.J_zh;
  b.sum_rule = rho * L5 * (t.A_f - t.J_zh);
  // O_k -> the fluid's centroid: given, or placed by the table's origin (the table's z = 0 at `origin`).
  b.fluid_center = cav.origin ? *cav.origin + L * t.centroid_z : cav.center;
  if (!(b.m_f > 0) || b.A_f < 0 || b.C_f < 0 || b.J_zh < 0)
    fail(scene, w + ".table", "non-physical table (volume, A_f, C_f or J_zh not positive)");
  if (t.free_surface.present()) {
    const double c = b.fluid_center / L;
    b.free_surface = true;
    b.K_free_surface = rho * L5 * t.free_surface.K(c);
    b.K_cross = rho * L5 / L * (t.free_surface.K1 + c * t.free_surface.K0);
    b.K_shift = rho * L3 * t.free_surface.K0;
    b.sum_rule = rho * L5 * t.sum_rule_about(c);
  }
}

// The rows the scene keeps, heaviest first about O_k: every coupling one (E = 0 rows, e.g. a spheroid's beyond its
// single mode, are left out), or the first `modes`, or as many as reach `coverage` of the sum rule. On a joint that
// moves (`translates`: a free chain's first body, or a later one) a partially filled tank's row couples through its
// translation t too, and one with E = 0 about O_k (a + c t = 0) but t ≠ 0 is kept.
std::vector<int> kept_rows(const Scene& scene, const std::string& w, const CavitySpec& cav, const rc::ModeTable& t,
                           const RowCoupling& rc, bool translates) {
  const double sum_rule = rc.sum_rule();
  std::vector<int> idx;
  const double tiny = 1e-14 * std::max(sum_rule, 1e-300);
  const auto moves_with_joint = [&](std::size_t l) {
    if (!translates || !t.free_surface.present() || t.N2[l] == 0) return false;
    const std::complex<double> tc(t.free_surface.t[l], t.viscous() ? t.free_surface.t_imag[l] : 0.0);
    return std::abs(2.0 * tc * tc / t.N2[l]) > tiny;
  };
  // A viscous mode's residue may have a negative real part (docs/viscous.md section 5): kept by its modulus.
  for (std::size_t l = 0; l < t.size(); ++l)
    if ((t.viscous() ? std::abs(rc.E_c(l)) > tiny : rc.E(l) > tiny) || moves_with_joint(l))
      idx.push_back(static_cast<int>(l));
  // About O_k a free-surface table's rows weigh otherwise than about its centroid, where they are sorted.
  if (t.free_surface.present())
    std::stable_sort(idx.begin(), idx.end(), [&](int i, int j) { return rc.E(i) > rc.E(j); });
  std::size_t keep = idx.size();
  if (cav.modes) {
    if (static_cast<std::size_t>(*cav.modes) > idx.size())
      fail(scene, w + ".modes", std::to_string(*cav.modes) + " requested, the table " +
                                    cav.table.filename().string() + " holds " +
                                    std::to_string(idx.size()) + " coupling modes");
    keep = *cav.modes;
  } else if (cav.coverage) {
    const double target = *cav.coverage * sum_rule;
    double acc = 0;
    keep = 0;
    while (keep < idx.size() && acc < target * (1 - 1e-12)) acc += rc.E(idx[keep++]);
    if (acc < target * (1 - 1e-12)) {
      std::ostringstream os;
      os << "coverage " << *cav.coverage << " not reachable: the table's modes cover " << acc / sum_rule;
      fail(scene, w + ".coverage", os.str());
    }
  }
  idx.resize(keep);
  return idx;
}

// One kept row as a chain mode of body k (λ_kl = ω_k0 λ_l, Kononov (21)), scaled to the body's spin and scale.
FluidMode chain_mode(int k, int l, const rc::ModeTable& t, const RowCoupling& rc, const CavitySpec& cav,
                     double omega) {
  const double L = cav.scale, L5 = inertia_unit(cav);
  FluidMode m;
  m.body = k;
  m.table_index = l;
  m.E = L5 * rc.E(l);
  m.lambda_table = t.lambda[l];
  m.lambda = omega * t.lambda[l];
  m.nu = omega - m.lambda;
  // a ~ rho L^4, N^2 ~ rho L^3 (N^2 carries rho so that E = 2a^2/N^2 ~ rho L^5): a/N^2 ~ L.
  m.a_over_N2 = (t.N2[l] != 0) ? L * rc.a(l) / t.N2[l] : 0.0;
  if (!t.converged.empty()) m.converged = t.converged[l];
  if (t.viscous()) {
    // Spin -omega mirrors the flow (phi -> -phi) and conjugates it: lambda_c -> -conj(lambda_c), so the
    // decay scales with |omega| and E_c -> conj(E_c) (docs/rom.md, "Viscous tanks"; derived, no test yet).
    m.decay = std::abs(omega) * t.decay[l];
    m.E_imag = (omega < 0 ? -1 : 1) * L5 * rc.E_c(l).imag();
  }
  return m;
}

// A partially filled tank on body k > 0: its joint moves by y = Σ_{j<k} s_j u_j, which the liquid feels as it feels
// the centroid's own displacement c u_k (docs/physics.md §2, "A tank whose joint moves"), so the row's coupling about
// O_k, a + c t, gains t y/L: lever_j = (s_j/L) t / (a + c t); on a free chain the base's translation X moves every
// joint: lever_base = (1/L) t / (a + c t) (base_translation.hpp). Spin −ω conjugates a viscous mode's couplings
// (chain_mode) and so its lever.
void set_lever(const Scene& scene, int k, int l, const rc::ModeTable& t, const RowCoupling& rc, const CavitySpec& cav,
               double omega, FluidMode& m) {
  if (k == 0 && !scene.free_chain) return;
  const bool visc = t.viscous();
  std::complex<double> a_c(rc.a(l), visc ? t.a_imag[l] + rc.c * t.free_surface.t_imag[l] : 0.0),
      t_c(t.free_surface.t[l], visc ? t.free_surface.t_imag[l] : 0.0);
  if (omega < 0) {
    a_c = std::conj(a_c);
    t_c = std::conj(t_c);
  }
  // The row's weights over (u_k, u_j, X) are a_c, s_j t_c, t_c/L (table units): E w wᵀ with the largest of a_c and t_c
  // as the pivot, so that a row with a_c = 0 (E = 0 about O_k) still couples through t_c.
  std::complex<double> pivot = a_c;
  if (std::abs(a_c) < std::abs(t_c)) {
    pivot = t_c;
    m.own = a_c / t_c;
    const std::complex<double> E = inertia_unit(cav) * 2.0 * t_c * t_c / t.N2[l];
    m.E = E.real();
    m.E_imag = visc ? E.imag() : 0.0;  // spin −ω conjugates E_c, as chain_mode's: t_c is conjugated already
    m.a_over_N2 = cav.scale * t_c.real() / t.N2[l];
  }
  for (int j = 0; j < k; ++j) {
    const double s = scene.bodies[j].next_joint / cav.scale;
    if (s != 0) m.lever.emplace_back(j, s * t_c / pivot);
  }
  if (scene.free_chain) m.lever_base = t_c / pivot / cav.scale;
}

// A Galerkin tank's fluid energy and dissipation forms in chain units; spin -omega conjugates the flow, the forms
// too. Energy ~ rho L^5, dissipation ~ rho L^5 |omega|.
void set_galerkin_forms(const GalerkinFluid& gf, const CavitySpec& cav, BodyModel& b) {
  const double L5 = inertia_unit(cav);
  const auto chain_units = [&](const Eigen::MatrixXcd& a, double factor) -> Eigen::MatrixXcd {
    return L5 * factor * (b.omega < 0 ? a.conjugate().eval() : a);
  };
  b.galerkin = cav.galerkin;
  if (gf.energy.size() > 0) {
    b.fluid_energy = chain_units(gf.energy, 1.0);
    b.fluid_dissipation = chain_units(gf.dissipation, std::abs(b.omega));
  }
}

// A response table's window, its errors (with the Im R profile) and which reduction made its rows.
void set_response_fit(const rc::ModeTable& t, BodyModel& b) {
  b.fit_lo = t.fit_lo;
  b.fit_hi = t.fit_hi;
  b.fit_error = t.fit_error;
  b.fit_decay_error = t.fit_decay_error;
  b.fit_decay_s = t.fit_decay_s;
  b.fit_decay_profile = t.fit_decay_profile;
  // The table's solver text says which (modes/app/galerkin_response_table.cpp, cavity_response.cpp).
  b.response_kind = t.solver.find("rational Krylov") != std::string::npos ? "a Krylov response table"
                    : t.solver.find("Galerkin") != std::string::npos   ? "a Galerkin response table"
                                                                       : "a response fit";
}

// Fluid of body k: mass, frozen inertia, centre of mass, kept modes (docs/physics.md §4 scaling).
void add_fluid(const Scene& scene, int k, const CavitySpec& cav, BodyModel& b,
               std::vector<FluidMode>& modes, TableCache* tables) {
  const std::string w = "body[" + std::to_string(k + 1) + "].cavity";
  rc::ModeTable own;
  const rc::ModeTable& t = cavity_table(scene, w, cav, tables, own);
  if (t.m != 1) fail(scene, w + ".table", cav.table.string() + " holds m = " + std::to_string(t.m) +
                                 " modes; only m = 1 modes couple to the tilt");
  check_viscosity(scene, w, cav, t, b.omega);
  set_frozen_fluid(scene, w, cav, t, b);
  const double L5 = inertia_unit(cav);
  const RowCoupling rc{t, b.fluid_center / cav.scale};
  std::vector<int> rows = kept_rows(scene, w, cav, t, rc, k > 0 || scene.free_chain);
  // A response table's rows no root needs (prunable, response_row_pruning.hpp).
  if (prunable(t, cav)) {
    const PrunedRows pruned = prune_response_rows(t, rows, kPruneMagnitude, kPruneDissipation);
    rows = pruned.kept;
    b.pruned_rows = pruned.dropped;
  }
  if (cav.bands)
    fail(scene, w + ".reduction", "\"bands\" takes a 3-D table's band couplings, in the chain without axial symmetry "
                                  "(`spectrum`, `run`, `sweep`, `bench`; docs/rom.md); this command takes modal tanks");
  GalerkinFluid gf;
  if (cav.galerkin && t.free_surface.present())  // its forms hold the couplings about the centroid only
    fail(scene, w + ".reduction", "\"galerkin\" does not take a partially filled tank's table yet (the modal tank does)");
  if (cav.galerkin) {
    try {
      gf = galerkin_fluid(t, rows);
    } catch (const std::exception& e) {
      fail(scene, w + ".reduction", cav.table.filename().string() + ": " + e.what());
    }
  }
  set_galerkin_forms(gf, cav, b);
  for (std::size_t j = 0; j < rows.size(); ++j) {
    FluidMode m = chain_mode(k, rows[j], t, rc, cav, b.omega);
    if (m.converged == 0) ++b.unconverged;
    if (cav.galerkin) {  // the Galerkin residue in place of the modal one (galerkin_fluid.hpp)
      m.E = L5 * gf.residue[static_cast<Eigen::Index>(j)].real();
      m.E_imag = (b.omega < 0 ? -1 : 1) * L5 * gf.residue[static_cast<Eigen::Index>(j)].imag();
    }
    b.E_kept += m.E;  // about O_k (set_lever may put a row's E on its translation)
    b.E_kept_imag += m.E_imag;
    if (t.free_surface.present()) set_lever(scene, k, rows[j], t, rc, cav, b.omega, m);
    modes.push_back(m);
  }
  b.ekman = t.ekman;
  set_response_fit(t, b);
  b.coverage = b.sum_rule > 0 ? b.E_kept / b.sum_rule : 1.0;
  // The residues of all modes sum to the real A_f - J_zh (the response's 1/sigma term involves only the
  // real mass and divergence matrices; an argument, not measured: a table holds too few modes to sum), so the
  // remainder of a viscous table is complex too.
  if (cav.static_correction) {
    b.E_rem = std::max(0.0, b.sum_rule - b.E_kept);
    b.E_rem_imag = -b.E_kept_imag;
  }
}

}  // namespace

void check_viscosity(const Scene& scene, const std::string& w, const CavitySpec& cav, const rc::ModeTable& t,
                     double omega) {
  const std::string name = cav.table.filename().string();
  if (cav.viscosity && !t.viscous())
    fail(scene, w + ".viscosity", "given, but " + name + " is an ideal-fluid table (no ekman); make a viscous one with cavity-modes --ekman");
  if (!t.viscous()) return;
  std::ostringstream os;
  if (!cav.viscosity) {
    os << name << " is a viscous table (ekman = " << t.ekman << "): give the fluid's viscosity (m^2/s)";
    fail(scene, w + ".viscosity", os.str());
  }
  if (omega == 0) fail(scene, w + ".viscosity", "a viscous tank needs a spinning body (Ek = nu/(omega L^2))");
  const double ek = *cav.viscosity / (std::abs(omega) * cav.scale * cav.scale);
  if (std::abs(ek / t.ekman - 1) > kEkmanTolerance) {
    os << "Ek = nu/(|spin| scale^2) = " << ek << " but " << name << " was made for ekman = " << t.ekman
       << " (they must agree to " << kEkmanTolerance * 100 << " %)";
    fail(scene, w + ".viscosity", os.str());
  }
}


const rc::ModeTable& TableCache::get(const std::filesystem::path& file) {
  const std::string key = file.lexically_normal().string();
  auto it = tables_.find(key);
  if (it == tables_.end()) it = tables_.emplace(key, rc::read_mode_table(file)).first;
  return it->second;
}

namespace {

// What only the nonlinear model has: the linear system (26) needs axisymmetric bodies; the spins' own motion (axial
// friction and moments) is its separate block (axial_rotation.hpp).
void require_linear_scene(const Scene& scene) {
  if (scene.field && !scene.free_chain && scene.field->frequency > 0 && scene.field->harmonic[2] != 0)
    fail(scene, "field.harmonic", "a time-varying axial field changes the chain's stiffness with time (a parametric "
         "chain, e.g. a vibrating support): the nonlinear model only ([run] model = \"nonlinear\")");
  if (scene.field && scene.field->has_gradient()) {
    if (scene.free_chain)
      fail(scene, "field.gradient", "a field varying in space on a free chain is in the nonlinear model only ([run] model "
           "= \"nonlinear\")");
    if (const std::string why = gradient_asymmetry(*scene.field); !why.empty())
      fail(scene, "field.gradient", why + ": the linearised chain (26) needs a gradient symmetric about the spin axis "
           "(diag(g, g, g_z)); only [run] model = \"nonlinear\" takes any symmetric gradient");
  }
  for (std::size_t k = 0; k < scene.size(); ++k) {
    const BodySpec& b = scene.bodies[k];
    if (b.asymmetric())
      fail(scene, "body[" + std::to_string(k + 1) + (b.B && *b.B != b.A ? "].B" : "].Ixy"), "a body without axial "
           "symmetry: the linearised chain (26) needs axisymmetric bodies; `chain-rom spectrum`, `run`, `sweep` and "
           "`bench` take it (the chain without axial symmetry, docs/rom.md), and [run] model = \"nonlinear\"");
    // Transverse moments are the forced (26) (forced_solution.hpp); axial ones drive the spins' own states
    // (axial_rotation.hpp).
    if (b.aero && scene.free_chain)
      fail(scene, "body[" + std::to_string(k + 1) + "].aero", "aerodynamic moments on a free chain are not modelled "
           "yet: a projectile is one body about its centre of mass (a fixed chain of one body, docs/rom.md)");
    if (b.moment && scene.free_chain)
      fail(scene, "body[" + std::to_string(k + 1) + "].moment", "external moments on a free chain are in the "
           "nonlinear model only ([run] model = \"nonlinear\")");
    if (b.force && scene.free_chain)
      fail(scene, "body[" + std::to_string(k + 1) + "].force", "external forces on a free chain are in the "
           "nonlinear model only ([run] model = \"nonlinear\")");
    if (b.force && b.force->frequency > 0 && b.force->harmonic[2] != 0)
      fail(scene, "body[" + std::to_string(k + 1) + "].force.harmonic", "a time-varying axial force changes the "
           "chain's stiffness with time (a parametric chain): the nonlinear model only ([run] model = \"nonlinear\")");
  }
}

}  // namespace

namespace {
// Each kept mode scaled to its body's spin and scale must be finite: a table's decay of 1e308 (finite, and so accepted
// by the reader) times a spin is infinite, and LAPACK's eigen-solver looped on it without end (fuzz).
void check_modes_finite(const Scene& scene, const std::vector<FluidMode>& modes) {
  for (const FluidMode& md : modes)
    if (!std::isfinite(md.lambda) || !std::isfinite(md.decay) || !std::isfinite(md.E) || !std::isfinite(md.E_imag) ||
        !std::isfinite(md.a_over_N2))
      fail(scene, "body[" + std::to_string(md.body + 1) + "].cavity.table",
           "a mode scaled to the body's spin and scale overflows double precision (row " +
               std::to_string(md.table_index + 1) + " of the table: lambda, decay or E too large)");
}
}  // namespace

namespace {

// Body k with its frozen fluid (docs/physics.md §3: m_k, A_k, C_k include it; A_k about O_k) and its tank's modes.
BodyModel body_model(const Scene& scene, int k, TableCache* tables, bool linear_keys_only,
                     std::vector<FluidMode>& modes) {
  const int n = static_cast<int>(scene.size());
  const BodySpec& bs = scene.bodies[k];
  BodyModel b;
  b.omega = bs.spin;
  b.s = (k + 1 < n) ? bs.next_joint : 0.0;
  double m = bs.mass, first = bs.mass * bs.com, A = bs.A, C = bs.C;
  const std::string only_general = ": `chain-rom spectrum`, `run`, `sweep` and `bench` take it (the chain without "
                                   "axial symmetry, docs/rom.md); the chain (26) and this command take one tank on "
                                   "the body's axis";
  if (!bs.more_cavities.empty())
    fail(scene, "body[" + std::to_string(k + 1) + "].cavity", "several tanks on one body" + only_general);
  if (bs.cavity && bs.cavity->offset)
    fail(scene, "body[" + std::to_string(k + 1) + "].cavity.offset", "a tank off the body's axis" + only_general);
  if (bs.cavity) {
    add_fluid(scene, k, *bs.cavity, b, modes, tables);
    const double d = b.fluid_center;
    m += b.m_f;
    first += b.m_f * d;
    A += b.A_f + b.m_f * d * d;  // parallel-axis theorem: fluid inertia about O_k
    // A partially filled tank's surface re-centres on the tilted spin axis: inertia K(O_k) more (docs/physics.md §2).
    A += b.K_free_surface;
    if (b.free_surface && scene.field && !scene.free_chain &&
        (scene.field->space[0] != 0 || scene.field->space[1] != 0 || scene.field->harmonic[0] != 0 ||
         scene.field->harmonic[1] != 0))
      fail(scene, "field", "a transverse field moves a partially filled tank's free surface, which the chain does not "
           "model yet (body[" + std::to_string(k + 1) + "]'s tank; an axial field is taken, as gravity is)");
    if (b.free_surface && scene.field && scene.field->has_gradient())
      fail(scene, "field.gradient", "a field varying in space moves a partially filled tank's free surface, which the "
           "chain does not model yet (body[" + std::to_string(k + 1) + "]'s tank)");
    if (b.free_surface && (k > 0 || scene.free_chain) && bs.cavity->static_correction)
      fail(scene, "body[" + std::to_string(k + 1) + "].cavity.static_correction",
           "not modelled for a partially filled tank on a body whose joint moves (its remainder would couple to the "
           "earlier bodies too): leave it false, or keep more modes");
    // The nonlinear chain takes the modes about O_k and K in A and B (nonlinear_run.cpp); a moving joint's forcing of
    // the free surface (the modes' levers) is the linear model's only.
    if (b.free_surface && !linear_keys_only && (k > 0 || scene.free_chain))
      fail(scene, "body[" + std::to_string(k + 1) + "].cavity.table",
           "the nonlinear chain takes a partially filled tank on the first body of a fixed chain only (the joint's "
           "motion forces its free surface in the linear model (26) only)");
    C += b.C_f;
  }
  b.m = m;
  b.c = (m > 0) ? first / m : 0.0;
  b.A = A;
  b.C = C;
  return b;
}

// Fixed chain, Kononov after (10) and (26): A'_k = A_k + s_k^2 sum_{i>k} m_i,
// a_k = m_k c_k + s_k sum_{i>k} m_i, M_ki = a_k s_i (i<k), M_ki = s_k a_i (i>k); a free chain's M less a aᵀ/m.
// Returns the total mass.
double set_inertia(const Scene& scene, ChainModel& cm) {
  const int n = cm.n;
  cm.a.resize(n);
  cm.M.setZero(n, n);
  double tail = 0;  // sum_{i>k} m_i
  for (int k = n - 1; k >= 0; --k) {
    const BodyModel& b = cm.bodies[k];
    cm.a[k] = b.m * b.c + b.s * tail;
    cm.M(k, k) = b.A + b.s * b.s * tail;
    tail += b.m;
  }
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < k; ++i) cm.M(k, i) = cm.M(i, k) = cm.a[k] * cm.bodies[i].s;
  // A partially filled tank on body k > 0: its re-centring inertia is a form in (u_k, y), y = Σ_{j<k} s_j u_j
  // (docs/physics.md §2, "A tank whose joint moves"); K(O_k) u_k² is in A_k already.
  for (int k = 1; k < n; ++k) {
    const BodyModel& b = cm.bodies[k];
    if (!b.free_surface) continue;
    for (int j = 0; j < k; ++j) {
      cm.M(k, j) += b.K_cross * cm.bodies[j].s;
      cm.M(j, k) += b.K_cross * cm.bodies[j].s;
      for (int i = 0; i < k; ++i) cm.M(j, i) += b.K_shift * cm.bodies[j].s * cm.bodies[i].s;
    }
  }
  const double mtot = tail;
  if (scene.free_chain) {
    // Free chain (docs/free-chain.md, from Kononov (12)-(14)): the centre of mass of the
    // whole chain stays at rest, which removes a a^T / m from the fixed-chain matrix.
    if (!(mtot > 0)) fail(scene, "body", "a free chain needs a positive total mass");
    cm.M -= cm.a * cm.a.transpose() / mtot;
  }
  return mtot;
}

// Gravity and the joints' stiffness (Kononov (27)) and friction (Batyr (43)); the gyroscopic C_k ω_k0.
void set_stiffness_friction_gyro(const Scene& scene, ChainModel& cm) {
  const int n = cm.n;
  cm.K.setZero(n, n);
  if (!scene.free_chain)  // gravity: - a_k g u_k in (26); a free chain falls freely (no torque)
    for (int k = 0; k < n; ++k) cm.K(k, k) -= cm.a[k] * scene.gravity;
  cm.D.setZero(n, n);
  if (!scene.free_chain) cm.D(0, 0) += scene.support_friction;  // alpha_1, Batyr (43)
  for (int k = 0; k + 1 < n; ++k) {
    const double kap = scene.joints[k].stiffness;  // kappa_k^2, Kononov (27)
    cm.K(k, k) += kap;
    cm.K(k + 1, k + 1) += kap;
    cm.K(k, k + 1) -= kap;
    cm.K(k + 1, k) -= kap;
    const double al = scene.joints[k].friction;  // alpha_{k+1}, Batyr (43)
    cm.D(k, k) += al;
    cm.D(k + 1, k + 1) += al;
    cm.D(k, k + 1) -= al;
    cm.D(k + 1, k) -= al;
  }
  // A constant axial field f_z (m/s², docs/rom.md "A uniform force field") acts as gravity −f_z would: −a_k g → +a_k f_z.
  if (scene.field && !scene.free_chain)
    for (int k = 0; k < n; ++k) cm.K(k, k) += cm.a[k] * scene.field->space[2];
  add_gradient_stiffness(scene, cm);  // a field varying in space (field_gradient.hpp)
  // A constant axial force F_z at `at` on body k (docs/rom.md, "External forces"): its potential −F·x_P, to second order
  // ½F_z(at |u_k|² + Σ_{j<k} s_j |u_j|²), stiffens each tilt that lowers the point as gravity's −m g does.
  for (int k = 0; k < n; ++k)
    if (const auto& f = scene.bodies[k].force; f && !scene.free_chain) {
      cm.K(k, k) += f->space[2] * f->at;
      for (int j = 0; j < k; ++j) cm.K(j, j) += f->space[2] * scene.bodies[j].next_joint;
    }
  // A projectile's aerodynamics (docs/rom.md, "A projectile's aerodynamic moments"): the static moment M_α u (u = the
  // yaw, overturning for M_α > 0) joins the stiffness as gravity's −a g u does, the pitch damping −M_q u̇ the friction,
  // the Magnus moment i M_p ω u (along the yaw's direction, F = M_y + i M_x) the stiffness as −i M_p ω.
  cm.circulatory = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < n; ++k)
    if (scene.bodies[k].aero) {
      cm.K(k, k) -= scene.bodies[k].aero->static_moment;
      cm.D(k, k) += scene.bodies[k].aero->pitch_damping;
      cm.bodies[k].static_moment = scene.bodies[k].aero->static_moment;
      cm.bodies[k].pitch_damping = scene.bodies[k].aero->pitch_damping;
      cm.circulatory[k] = scene.bodies[k].aero->magnus * cm.bodies[k].omega;  // F = i M_p ω u
    }
  cm.G.resize(n);
  for (int k = 0; k < n; ++k) cm.G[k] = cm.bodies[k].C * cm.bodies[k].omega;
}

// M_eff = M − Σ_l E_kl w wᵀ − diag(E_rem), which must stay positive definite: the shells must carry inertia of their
// own. A free chain with a partially filled tank: the extended chain's, reduced on its base (base_translation.hpp).
void set_effective_inertia(const Scene& scene, ChainModel& cm, const Eigen::MatrixXd& M_fixed, double mass) {
  const int n = cm.n;
  for (int k = 0; k < n; ++k) cm.viscous = cm.viscous || cm.bodies[k].ekman > 0;
  bool base = false;
  for (const FluidMode& md : cm.modes) base = base || md.lever_base != 0.0;
  if (base) {
    cm.extended = std::make_shared<const ChainModel>(extend_with_base(cm, M_fixed, cm.a, mass));
    const Eigen::MatrixXcd Me = reduce_on_base(cm.extended->M_eff.cast<std::complex<double>>() +
                                               std::complex<double>(0, 1) * cm.extended->M_eff_imag.cast<std::complex<double>>());
    cm.M = reduce_on_base(cm.extended->M.cast<std::complex<double>>()).real();
    cm.M_eff = Me.real();
    cm.M_eff_imag = Me.imag();
  } else {
    Eigen::MatrixXcd fluid = Eigen::MatrixXcd::Zero(n, n);  // Σ_l E_kl w wᵀ + diag(E_rem)
    for (const FluidMode& md : cm.modes) add_mode_term(fluid, md, md.E_c());
    for (int k = 0; k < n; ++k) fluid(k, k) += std::complex<double>(cm.bodies[k].E_rem, cm.bodies[k].E_rem_imag);
    cm.M_eff = cm.M - fluid.real();
    cm.M_eff_imag = -fluid.imag();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(cm.M_eff, Eigen::EigenvaluesOnly);
  // Against the inertia M with the fluid frozen, not M_eff itself: M_eff = M - diag(sum E) cancels
  // digits, and below ~1e-13 of M what is left is rounding (a shell of 1e-15 around a sphere).
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> em(cm.M, Eigen::EigenvaluesOnly);
  const double lo = es.eigenvalues().minCoeff(),
               hi = std::max(es.eigenvalues().cwiseAbs().maxCoeff(), em.eigenvalues().cwiseAbs().maxCoeff());
  if (!(lo > 1e-13 * std::max(hi, 1e-300))) {
    std::ostringstream os;
    os << "effective inertia matrix M - diag(sum E) is not positive definite (smallest eigenvalue "
       << lo << " kg m^2): the shell carries no inertia beyond what the fluid modes take";
    fail(scene, "body", os.str());
  }
}

// A shell without axial inertia whose spin a friction, an axial moment or an initial change would move: its ideal liquid does not follow
// (docs/physics.md §3, "Axial rotations"), so nothing resists, and the spin's motion is undetermined.
void require_axial_inertia(const Scene& scene, const ChainModel& cm) {
  const AxialChain& a = cm.axial;
  for (Eigen::Index k = 0; k < a.C.size(); ++k) {
    const bool moved = a.D.row(k).cwiseAbs().maxCoeff() > 0 || a.moment[k] != 0 || a.harmonic[k] != 0 || a.start[k] != 0;
    if (a.C[k] > 0 || !moved) continue;
    fail(scene, "body[" + std::to_string(k + 1) + "].C",
         "the shell has no axial inertia, and an axial friction, moment or initial.axial_rate acts on its spin, which its "
         "liquid (if any) "
         "does not follow (docs/physics.md §3, \"Axial rotations\"): give the shell's C > 0");
  }
}

}  // namespace

Eigen::MatrixXcd complex_stiffness(const ChainModel& m) {
  Eigen::MatrixXcd K = m.K.cast<std::complex<double>>();
  for (Eigen::Index k = 0; k < m.circulatory.size(); ++k) K(k, k) -= std::complex<double>(0, m.circulatory[k]);
  return K;
}

double BodyModel::fit_decay_error_at(double s) const {
  const auto& x = fit_decay_s;
  if (x.size() < 2 || !(s >= x.front() && s <= x.back())) return -1;
  const auto hi = std::max<std::ptrdiff_t>(1, std::upper_bound(x.begin(), x.end(), s) - x.begin());
  const auto i = static_cast<std::size_t>(std::min<std::ptrdiff_t>(hi, static_cast<std::ptrdiff_t>(x.size()) - 1));
  const double w = (s - x[i - 1]) / (x[i] - x[i - 1]);
  return (1 - w) * fit_decay_profile[i - 1] + w * fit_decay_profile[i];
}

ChainModel build_model(const Scene& scene, TableCache* tables, bool linear_keys_only) {
  if (linear_keys_only) require_linear_scene(scene);
  ChainModel cm;
  cm.n = static_cast<int>(scene.size());
  cm.free_chain = scene.free_chain;
  cm.g = scene.gravity;
  for (int k = 0; k < cm.n; ++k) cm.bodies.push_back(body_model(scene, k, tables, linear_keys_only, cm.modes));
  const double mass = set_inertia(scene, cm);
  Eigen::MatrixXd M_fixed = cm.M;  // a free chain's before its reduction a aᵀ/m (what base_translation.hpp extends)
  if (scene.free_chain) M_fixed += cm.a * cm.a.transpose() / mass;
  set_stiffness_friction_gyro(scene, cm);
  // The spins' own block takes the shells' axial inertia: an ideal liquid does not follow its tank's turns about the
  // symmetry axis (docs/physics.md §3, "Axial rotations"), although its spin enters the tilts' gyroscopic terms (C_k).
  std::vector<double> axial_inertia;
  for (const BodySpec& b : scene.bodies) axial_inertia.push_back(b.C);
  cm.axial = axial_chain(scene, axial_inertia);
  require_axial_inertia(scene, cm);
  // Scene values that are each in range can still overflow together (mass 1e308 times com times g): the
  // matrices of (26) must be finite before any solver sees them.
  if (!cm.M.allFinite() || !cm.K.allFinite() || !cm.D.allFinite() || !cm.G.allFinite())
    fail(scene, "body", "the chain's inertia, stiffness, friction or gyroscopic terms overflow double precision "
                        "(masses, inertias, lengths, spins or gravity too large together)");
  check_modes_finite(scene, cm.modes);
  set_effective_inertia(scene, cm, M_fixed, mass);
  return cm;
}

Eigen::VectorXcd initial_fluid(const Scene& scene, int n_modes) {
  if (scene.fluid.empty()) return Eigen::VectorXcd::Zero(n_modes);
  if (static_cast<int>(scene.fluid.size()) != n_modes)
    fail(scene, "initial.fluid", "has " + std::to_string(scene.fluid.size()) + " entries, the scene keeps " +
                                     std::to_string(n_modes) + " fluid modes (one [re, im] per kept mode, body by body)");
  Eigen::VectorXcd z(n_modes);
  for (int l = 0; l < n_modes; ++l) z[l] = scene.fluid[l];
  return z;
}

}  // namespace rc::rom
