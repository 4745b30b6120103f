#include "output.hpp"

#include "atomic_file.hpp"

#include "companion_check.hpp"
#include "mesh_study.hpp"

#include <hdf5.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace rc::rom {
namespace fs = std::filesystem;
namespace {

std::string lower_ext(const fs::path& p) {
  std::string e = p.extension().string();
  for (auto& ch : e) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return e;
}

void write_csv(const ChainModel& m, const History& h, const fs::path& tmp) {
  std::ofstream os(tmp);
  if (!os) throw std::runtime_error(tmp.string() + ": cannot create");
  os << std::setprecision(17);
  os << "t";
  for (int k = 0; k < m.n; ++k) os << ",u" << k + 1 << "_re,u" << k + 1 << "_im";
  for (int l = 0; l < m.n_modes(); ++l) {
    const std::string nm = std::to_string(m.modes[l].body + 1) + "_" + std::to_string(l + 1);
    os << ",z" << nm << "_re,z" << nm << "_im";
  }
  // With viscous tanks no energy integral, but the frozen chain's budget (energy_budget.hpp).
  const bool budget = !h.budget.empty(), balance = !h.balance.empty();
  os << (budget ? ",frozen_energy,fluid_power,friction_power,fluid_work" : ",energy")
     << (balance ? ",energy,joint_power,fluid_dissipation,dissipated\n" : "\n");
  for (std::size_t j = 0; j < h.t.size(); ++j) {
    os << h.t[j];
    for (int k = 0; k < m.n; ++k) os << ',' << h.u(j, k).real() << ',' << h.u(j, k).imag();
    for (int l = 0; l < m.n_modes(); ++l) os << ',' << h.z(j, l).real() << ',' << h.z(j, l).imag();
    if (budget)
      os << ',' << h.budget.frozen_energy[j] << ',' << h.budget.fluid_power[j] << ',' << h.budget.friction_power[j]
         << ',' << h.budget.fluid_work[j];
    else
      os << ',' << h.H[j];
    if (balance)  // galerkin_energy.hpp
      os << ',' << h.balance.energy[j] << ',' << h.balance.joint_power[j] << ',' << h.balance.fluid_dissipation[j]
         << ',' << h.balance.dissipated[j];
    os << '\n';
  }
  os.close();
  if (!os) throw std::runtime_error(tmp.string() + ": write failed");
}

struct H5 {
  hid_t id = -1;
  herr_t (*closer)(hid_t) = nullptr;
  ~H5() { if (id >= 0 && closer) closer(id); }
};

void check(herr_t r, const std::string& what) {
  if (r < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

void write_dataset(hid_t file, const std::string& name, const std::vector<double>& data,
                   hsize_t rows, hsize_t cols) {
  hsize_t dims[2] = {rows, cols};
  H5 space{H5Screate_simple(cols > 0 ? 2 : 1, dims, nullptr), H5Sclose};
  H5 ds{H5Dcreate2(file, name.c_str(), H5T_NATIVE_DOUBLE, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose};
  if (ds.id < 0) throw std::runtime_error("HDF5: cannot create dataset " + name);
  if (!data.empty()) check(H5Dwrite(ds.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), name);
}

// N rows of c complex values, stored row after row (one row per output time), as the real datasets NAME_re and
// NAME_im.
void write_complex_rows(hid_t file, const std::string& name, const std::complex<double>* data, hsize_t N, hsize_t c) {
  std::vector<double> re(N * c), im(N * c);
  for (hsize_t j = 0; j < N * c; ++j) { re[j] = data[j].real(); im[j] = data[j].imag(); }
  write_dataset(file, name + "_re", re, N, c);
  write_dataset(file, name + "_im", im, N, c);
}
void write_complex_rows(hid_t file, const std::string& name, const History::Rows& rows) {
  write_complex_rows(file, name, rows.data(), rows.rows(), rows.cols());
}

void write_attr(hid_t obj, const std::string& name, const std::string& value) {
  H5 type{H5Tcopy(H5T_C_S1), H5Tclose};
  check(H5Tset_size(type.id, std::max<std::size_t>(1, value.size())), "string type");
  H5 space{H5Screate(H5S_SCALAR), H5Sclose};
  H5 a{H5Acreate2(obj, name.c_str(), type.id, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  check(H5Awrite(a.id, type.id, value.c_str()), name);
}

void write_attr(hid_t obj, const std::string& name, double value) {
  H5 space{H5Screate(H5S_SCALAR), H5Sclose};
  H5 a{H5Acreate2(obj, name.c_str(), H5T_NATIVE_DOUBLE, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  check(H5Awrite(a.id, H5T_NATIVE_DOUBLE, &value), name);
}

void write_h5(const ChainModel& m, const History& h, const fs::path& tmp) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  H5 file{H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose};
  if (file.id < 0) throw std::runtime_error(tmp.string() + ": cannot create");
  const hsize_t N = h.t.size(), nm = m.n_modes();
  write_attr(file.id, "format", "chain-rom-history");
  write_attr(file.id, "method", h.method_used);
  write_attr(file.id, "convention",
             "u_k = beta_k - i alpha_k (Krylov angles, rad); z_kl fluid coordinate in rad/s with "
             "S'_kl = a_over_N2[l] * z_kl (Kononov (26)); energy: docs/rom.md");
  // With viscous tanks there is no energy integral of the truncated system (docs/rom.md, "Viscous tanks"): nothing
  // is written for it rather than NaN.
  if (!m.viscous) write_attr(file.id, "max_energy_drift", h.max_energy_drift);
  write_attr(file.id, "wall_seconds", h.wall_seconds);
  if (h.nonlinear_difference >= 0) {
    write_attr(file.id, "nonlinear_difference", h.nonlinear_difference);
    write_attr(file.id, "amplitude_at_1_percent", h.amplitude_at_limit);
  } else if (!h.validity_note.empty()) {
    write_attr(file.id, "nonlinear_difference_not_measured", h.validity_note);
  }
  write_dataset(file.id, "t", h.t, N, 0);
  write_complex_rows(file.id, "u", h.u);
  write_complex_rows(file.id, "z", h.z);
  std::vector<double> body(nm), aN(nm), E(nm), lam(nm);
  for (hsize_t l = 0; l < nm; ++l) {
    body[l] = m.modes[l].body + 1; aN[l] = m.modes[l].a_over_N2; E[l] = m.modes[l].E; lam[l] = m.modes[l].lambda;
  }
  write_dataset(file.id, "mode_body", body, nm, 0);
  write_dataset(file.id, "a_over_N2", aN, nm, 0);
  write_dataset(file.id, "mode_E", E, nm, 0);
  write_dataset(file.id, "mode_lambda", lam, nm, 0);
  if (!m.viscous) write_dataset(file.id, "energy", h.H, N, 0);
  if (h.spin.size() > 0) {  // axial_rotation.hpp: steps x n, row after row
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> spin = h.spin, angle = h.axial_angle;
    write_dataset(file.id, "spin", std::vector<double>(spin.data(), spin.data() + spin.size()), N, spin.cols());
    write_dataset(file.id, "axial_angle", std::vector<double>(angle.data(), angle.data() + angle.size()), N,
                  angle.cols());
  }
  if (!h.budget.empty()) {  // energy_budget.hpp
    write_dataset(file.id, "frozen_energy", h.budget.frozen_energy, N, 0);
    write_dataset(file.id, "fluid_power", h.budget.fluid_power, N, 0);
    write_dataset(file.id, "friction_power", h.budget.friction_power, N, 0);
    write_dataset(file.id, "fluid_work", h.budget.fluid_work, N, 0);
    write_attr(file.id, "energy_balance_residual", h.budget.balance_residual);
  }
  if (!h.balance.empty()) {  // galerkin_energy.hpp: the fluid holds an energy, H is written after all
    write_dataset(file.id, "energy", h.balance.energy, N, 0);
    write_dataset(file.id, "joint_power", h.balance.joint_power, N, 0);
    write_dataset(file.id, "fluid_dissipation", h.balance.fluid_dissipation, N, 0);
    write_dataset(file.id, "dissipated", h.balance.dissipated, N, 0);
    write_attr(file.id, "energy_dissipation_residual", h.balance.residual);
  }
}

void write_nonlinear_csv(const NonlinearHistory& nh, int n, const fs::path& tmp) {
  const History& h = nh.base;
  std::ofstream os(tmp);
  if (!os) throw std::runtime_error(tmp.string() + ": cannot create");
  os << std::setprecision(17) << "t";
  for (int k = 1; k <= n; ++k) os << ",u" << k << "_re,u" << k << "_im";
  for (int k = 1; k <= n; ++k) os << ",spin" << k;
  for (int k = 1; k <= n; ++k) os << ",q" << k << "_w,q" << k << "_x,q" << k << "_y,q" << k << "_z";
  const int nm = nh.fluid_modes;
  for (int l = 1; l <= nm; ++l) os << ",zeta" << l << "_re,zeta" << l << "_im";
  os << (nh.integrals_valid ? ",energy\n" : "\n");
  for (std::size_t j = 0; j < h.t.size(); ++j) {
    os << h.t[j];
    for (int k = 0; k < n; ++k) os << ',' << h.u(j, k).real() << ',' << h.u(j, k).imag();
    for (int k = 0; k < n; ++k) os << ',' << nh.spins[j * n + k];
    for (int c = 0; c < 4 * n; ++c) os << ',' << nh.quaternions[j * 4 * n + c];
    for (int l = 0; l < nm; ++l) os << ',' << nh.zeta[j * nm + l].real() << ',' << nh.zeta[j * nm + l].imag();
    if (nh.integrals_valid) os << ',' << h.H[j];
    os << '\n';
  }
  os.close();
  if (!os) throw std::runtime_error(tmp.string() + ": write failed");
}

void write_nonlinear_h5(const NonlinearHistory& nh, int n, const fs::path& tmp) {
  const History& h = nh.base;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  H5 file{H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose};
  if (file.id < 0) throw std::runtime_error(tmp.string() + ": cannot create");
  const hsize_t N = h.t.size();
  write_attr(file.id, "format", "chain-rom-history");
  write_attr(file.id, "model", "nonlinear");
  write_attr(file.id, "method", h.method_used);
  write_attr(file.id, "convention",
             "u_k = n_x - i n_y of body k's axis n_k = R_k e3 (= beta_k - i alpha_k, Krylov angles, to third order); "
             "quaternion (w, x, y, z) of R_k, body -> space; spin = Omega_k . n_k; energy, angular_momentum about "
             "O_1's start; zeta: the fluid coordinates in each body's frame: docs/rom.md, \"Nonlinear chain\"");
  if (nh.integrals_valid) write_attr(file.id, "max_energy_drift", h.max_energy_drift);
  if (nh.momentum_valid) write_attr(file.id, "max_momentum_drift", nh.max_momentum_drift);
  write_attr(file.id, "steps", double(h.integrator_steps));
  write_attr(file.id, "rejected_steps", double(nh.rejected_steps));
  if (nh.viscous_tanks) write_attr(file.id, "viscous_spin_change", nh.viscous_spin_change);
  write_attr(file.id, "wall_seconds", h.wall_seconds);
  write_dataset(file.id, "t", h.t, N, 0);
  write_complex_rows(file.id, "u", h.u);
  write_dataset(file.id, "quaternion", nh.quaternions, N, 4 * n);
  write_dataset(file.id, "spin", nh.spins, N, n);
  write_dataset(file.id, "angular_momentum", nh.momentum, N, 3);
  if (nh.integrals_valid) write_dataset(file.id, "energy", h.H, N, 0);
  write_complex_rows(file.id, "zeta", nh.zeta.data(), N, static_cast<hsize_t>(nh.fluid_modes));
}

}  // namespace

void write_history(const ChainModel& m, const History& h, const fs::path& out) {
  write_file_atomically(out, [&](const fs::path& tmp) {
    if (lower_ext(out) == ".csv") write_csv(m, h, tmp);
    else write_h5(m, h, tmp);
  });
}

void write_nonlinear_history(const NonlinearHistory& h, int n, const fs::path& out) {
  write_file_atomically(out, [&](const fs::path& tmp) {
    if (lower_ext(out) == ".csv") write_nonlinear_csv(h, n, tmp);
    else write_nonlinear_h5(h, n, tmp);
  });
}

namespace {

void write_general_csv(const GeneralChain& g, const GeneralHistory& h, const fs::path& tmp) {
  std::ofstream os(tmp);
  if (!os) throw std::runtime_error(tmp.string() + ": cannot create");
  os << std::setprecision(17) << "t";
  for (int k = 0; k < g.n; ++k) os << ",u" << k + 1 << "_re,u" << k + 1 << "_im";
  for (int l = 0; l < g.n_modes(); ++l) os << ",z" << g.modes[l].body + 1 << "_" << l + 1 << "_re,z" << g.modes[l].body + 1 << "_" << l + 1 << "_im";
  for (int k = 0; k < h.spin.cols(); ++k) os << ",spin" << k + 1;
  os << "\n";
  for (std::size_t j = 0; j < h.t.size(); ++j) {
    os << h.t[j];
    for (int k = 0; k < g.n; ++k) os << ',' << h.u(j, k).real() << ',' << h.u(j, k).imag();
    for (int l = 0; l < g.n_modes(); ++l) os << ',' << h.z(j, l).real() << ',' << h.z(j, l).imag();
    for (int k = 0; k < h.spin.cols(); ++k) os << ',' << h.spin(j, k);
    os << '\n';
  }
  os.close();
  if (!os) throw std::runtime_error(tmp.string() + ": write failed");
}

void write_general_h5(const GeneralChain& g, const GeneralHistory& h, const fs::path& tmp) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  H5 file{H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose};
  if (file.id < 0) throw std::runtime_error(tmp.string() + ": cannot create");
  const hsize_t N = h.t.size(), nm = g.n_modes();
  write_attr(file.id, "format", "chain-rom-history");
  write_attr(file.id, "model", "general");
  write_attr(file.id, "method", "exact (matrix exponential over each output step)");
  write_attr(file.id, "convention",
             "u_k = beta_k - i alpha_k (Krylov angles, rad) in space; z_l the fluid amplitude of mode l (h = 2 Re(z c), "
             "docs/rom.md, \"Bodies and tanks without axial symmetry\")");
  write_attr(file.id, "wall_seconds", h.wall_seconds);
  if (!std::isnan(h.momentum_drift)) write_attr(file.id, "max_momentum_drift", h.momentum_drift);
  write_dataset(file.id, "t", h.t, N, 0);
  write_complex_rows(file.id, "u", h.u);
  write_complex_rows(file.id, "z", h.z);
  std::vector<double> body(nm), lam(nm), decay(nm);
  for (hsize_t l = 0; l < nm; ++l) {
    body[l] = g.modes[l].body + 1;
    lam[l] = g.modes[l].lambda.real();
    decay[l] = g.modes[l].lambda.imag();
  }
  write_dataset(file.id, "mode_body", body, nm, 0);
  write_dataset(file.id, "mode_lambda", lam, nm, 0);
  write_dataset(file.id, "mode_decay", decay, nm, 0);
  if (h.spin.size() > 0) {
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> spin = h.spin;
    write_dataset(file.id, "spin", std::vector<double>(spin.data(), spin.data() + spin.size()), N, spin.cols());
  }
}

}  // namespace

void write_general_history(const GeneralChain& g, const GeneralHistory& h, const fs::path& out) {
  write_file_atomically(out, [&](const fs::path& tmp) {
    if (lower_ext(out) == ".csv") write_general_csv(g, h, tmp);
    else write_general_h5(g, h, tmp);
  });
}

std::string spectrum_json(const ChainModel& m, const Spectrum& sp) {
  nlohmann::ordered_json j;  // keys in the order of docs/physics.md §4
  j["roots"] = nlohmann::ordered_json::array();
  for (const Root& r : sp.roots) j["roots"].push_back({r.sigma.real(), r.sigma.imag()});
  j["stable"] = sp.stable;
  j["margin"] = sp.margin;
  j["det_residual"] = sp.det_residual;
  // beyond docs/physics.md §4: the largest -Im sigma (1/s) and the second root finder's agreement (root_newton.hpp)
  j["growth"] = sp.growth;
  j["growing"] = sp.growing;    // with dissipation: roots growing by more than `noise` (1/s)
  j["noise"] = sp.noise;
  j["root_agreement"] = sp.root_agreement;
  j["newton_failed"] = sp.newton_failed;
  j["outside_fit"] = sp.outside_fit;
  j["unconverged_owners"] = sp.unconverged_owners;
  j["fits_not_passive"] = sp.fits_not_passive;
  // The spins' own roots (axial_rotation.hpp): sigma = 0 `axial_zeros` times with `axial_jordan_chains` chains of
  // length 2, then i mu for each friction rate mu > 0.
  j["axial_roots"] = nlohmann::ordered_json::array();
  for (const auto& r : sp.axial.roots) j["axial_roots"].push_back({r.real(), r.imag()});
  j["axial_zeros"] = sp.axial.zeros;
  j["axial_jordan_chains"] = sp.axial.zeros - sp.axial.zero_eigenvectors;
  // A stable undamped chain's distance to the threshold (rad/s; krein_gap.hpp), null otherwise.
  if (sp.krein.defined) j["krein_gap"] = sp.krein.gap;
  else j["krein_gap"] = nullptr;
  if (sp.certificate_roots >= 0) {
    j["certified_real"] = sp.certified_real;
    j["certificate_roots"] = sp.certificate_roots;
    j["roots_at_zero"] = sp.roots_at_zero;
    j["certificate_disagrees"] = sp.certificate_disagrees();
  }
  // The bodies' coefficients of (22) at full precision, for checks made outside chain-rom: A' = M_kk, C, a_k, spin.
  j["bodies"] = nlohmann::ordered_json::array();
  for (int k = 0; k < m.n; ++k)
    j["bodies"].push_back({{"A_prime", m.M(k, k)}, {"C", m.bodies[k].C}, {"a", m.a[k]}, {"spin", m.bodies[k].omega}});
  // Per root, the Krylov tables' Im R error at its frequency (Root::fit_decay_error), null where no table gives it.
  bool profiled = false;
  for (const Root& r : sp.roots) profiled = profiled || r.fit_decay_error >= 0;
  if (profiled) {
    j["fit_decay_error"] = nlohmann::ordered_json::array();
    for (const Root& r : sp.roots)
      j["fit_decay_error"].push_back(r.fit_decay_error >= 0 ? nlohmann::ordered_json(r.fit_decay_error) : nullptr);
  }
  if (sp.companion_checked) {
    j["companion_moved"] = sp.companion_moved;
    j["companion_worst"] = sp.companion_worst;
    j["companion_shift"] = nlohmann::ordered_json::array();
    j["companion_worst_rate"] = sp.companion_worst_rate;
    for (const Root& r : sp.roots) j["companion_shift"].push_back(r.companion_shift);
    j["companion_rate_shift"] = nlohmann::ordered_json::array();
    for (const Root& r : sp.roots) j["companion_rate_shift"].push_back(r.companion_rate_shift);
  }
  return j.dump();
}

namespace {

// Whether a root is listed without --all: a body's root, one that grows (or, without dissipation, leaves the real
// axis), or one a check marks.
bool listed_by_default(const ChainModel& m, const Spectrum& sp, const Root& r) {
  if (r.owner.rfind("body", 0) == 0 || r.unconverged_owner || r.companion_moved) return true;
  return m.dissipative() ? -r.sigma.imag() > sp.noise && std::abs(r.sigma) > sp.tolerance
                         : std::abs(r.sigma.imag()) > sp.tolerance;
}

// The body a root's owner names ("body 2", "fluid 2.3": body 2), 0-based; −1 for none.
int owner_body(const std::string& owner) {
  const auto space = owner.find(' ');
  if (space == std::string::npos) return -1;
  try {
    return std::stoi(owner.substr(space + 1)) - 1;
  } catch (const std::exception&) {
    return -1;
  }
}

void print_root(std::ostream& os, const ChainModel& m, const Spectrum& sp, const Root& r) {
  os << std::setprecision(12) << "  " << std::setw(20) << r.sigma.real() << "  " << std::setw(20) << r.sigma.imag()
     << "i  " << std::setw(10) << r.owner << (r.unconverged_owner ? "*" : " ") << (r.companion_moved ? "~" : " ")
     << " det residual ";
  if (std::isnan(r.residual)) os << "n/a (sigma = 0 or at a pole of (22))";
  else os << std::setprecision(3) << r.residual;
  // With dissipation the rate a user reads: growth or decay with its e-folding time.
  const double rate = -r.sigma.imag();
  if (m.dissipative() && std::abs(r.sigma) > sp.tolerance && std::abs(rate) > sp.noise) {
    os << std::setprecision(3) << (rate > 0 ? "  grows " : "  decays ") << std::abs(rate) << " 1/s (e-folding "
       << 1 / std::abs(rate) << " s";
    // What the tables' fit alone may take from this rate, relative (the Krylov tables' Im R error here).
    if (r.fit_decay_error >= 0) os << ", table fit " << std::setprecision(2) << r.fit_decay_error << " of it";
    os << ")";
  }
  // The same motion seen in its owner's body frame, which turns at that body's spin: σ + ω_k (docs/rom.md, "Spectrum").
  const int k = owner_body(r.owner);
  if (k >= 0 && k < static_cast<int>(m.bodies.size()) && std::abs(r.sigma) > sp.tolerance)
    os << std::setprecision(9) << "  body frame " << r.sigma.real() + m.bodies[k].omega;
  os << "\n";
}

}  // namespace

// The roots where a response fit is extrapolated: named when a verdict rests on them (the bodies' and the growing
// ones), counted otherwise (most are a fit's heavily damped pseudo-roots far beyond its window).
void print_outside_fit(std::ostream& os, const ChainModel& m, const Spectrum& sp) {
  std::ostringstream named;
  int shown = 0;
  for (const Root& r : sp.roots)
    if (r.outside_fit && listed_by_default(m, sp, r) && shown++ < 6)
      named << " " << r.sigma.real() << std::showpos << r.sigma.imag() << std::noshowpos << "i (" << r.owner << ")";
  if (shown > 0)
    os << "warning: " << shown << " of the roots listed lie outside a tank's response-fit window, where its fit is "
       << "extrapolated (docs/viscous.md, \"Response fit\"):" << named.str() << (shown > 6 ? " and more" : "") << "\n";
  if (sp.outside_fit > shown)
    os << sp.outside_fit - shown << " fluid roots not listed lie outside a fit's window too (no verdict rests on them)\n";
}

void print_roots(std::ostream& os, const ChainModel& m, const Spectrum& sp, bool all) {
  os << "roots sigma (rad/s in space, solutions e^{i sigma t}; 'body frame': sigma + the owner's spin, the same motion "
        "seen from its body)" << (all ? "" : ": the bodies', those that grow and those a check marks") << ":\n";
  int left = 0;
  double slowest = std::numeric_limits<double>::infinity();  // the slowest decay among the roots left out
  for (const Root& r : sp.roots) {
    if (all || listed_by_default(m, sp, r)) {
      print_root(os, m, sp, r);
      continue;
    }
    ++left;
    if (std::abs(r.sigma) > sp.tolerance) slowest = std::min(slowest, r.sigma.imag());
  }
  if (left == 0) return;
  os << std::setprecision(3) << "  and " << left << " fluid roots not listed (--all lists every root, --json gives them)";
  if (m.dissipative() && std::isfinite(slowest)) os << ": none grows, the slowest decays at " << slowest << " 1/s";
  else if (!m.dissipative()) os << ": all real";
  os << "\n";
}

std::string verdict_with_dissipation(const ChainModel& m, const Spectrum& sp) {
  std::ostringstream os;
  os << std::setprecision(6);
  const std::string cause = m.has_friction() ? (m.viscous ? "friction and viscous fluid" : "friction") : "viscous fluid";
  if (!sp.stable) {
    // The fastest-growing root, named (docs/rom.md, "Verdict with dissipation").
    const Root* fastest = nullptr;
    for (const Root& r : sp.roots)
      if (std::abs(r.sigma) > sp.tolerance && (!fastest || r.sigma.imag() < fastest->sigma.imag())) fastest = &r;
    os << "stable: no -- unstable (" << cause << "): " << sp.growing << (sp.growing == 1 ? " root grows" : " roots grow")
       << ", the fastest at " << sp.growth << " 1/s (e-folding " << 1 / sp.growth << " s)";
    if (fastest) os << ": " << fastest->owner << " at " << fastest->sigma.real() << " rad/s";
  } else if (sp.growth < -sp.noise) {
    os << "stable: yes -- every root decays (" << cause << "), the slowest at " << -sp.growth << " 1/s (e-folding "
       << -1 / sp.growth << " s)";
  } else {
    os << "stable: yes -- marginally (" << cause << "): no root grows by more than rounding (" << sp.noise
       << " 1/s), the slowest decays at " << -sp.growth << " 1/s";
  }
  if (sp.at_zero) os << "; " << sp.at_zero << " roots at sigma = 0 (|sigma| <= " << sp.tolerance << ") left out";
  os << "\nlargest growth rate (-Im sigma): " << sp.growth << " 1/s (growth above " << sp.noise
     << " 1/s, rounding of the spectral radius, counts)";
  return os.str();
}

// One body's line of the spectrum's header: its totals, then what its tank is and how its table stands.
static void print_body_line(std::ostream& os, const ChainModel& m, const Spectrum& sp, int k) {
  const BodyModel& b = m.bodies[k];
  os << "  body " << k + 1 << ": m = " << b.m << " kg, A' = " << m.M(k, k)
     << (m.free_chain ? " (free chain: the motion about the system's centre of mass, docs/free-chain.md)" : "")
     << ", C = " << b.C << ", a = " << m.a[k] << ", spin = " << b.omega << " rad/s";
  if (b.has_fluid)
    os << ", fluid " << b.m_f << " kg, A_f = " << b.A_f << ", J_zh = " << b.J_zh
       << ", kept sum E = " << b.E_kept << " (coverage " << b.coverage << ")"
       << (b.E_rem > 0 ? ", static correction " + std::to_string(b.E_rem) : std::string());
  if (b.free_surface)
    os << ", partially filled (free surface; its static inertia K = " << b.K_free_surface << " in A', couplings about "
       << "the joint" << (k > 0 ? ", and through t to the earlier bodies' tilts that move the joint" : "") << ")";
  if (b.static_moment > 0)  // gyroscopic stability factor of linear aeroballistics: > 1 to hold the overturning moment
    os << ", overturning moment " << b.static_moment << " N m/rad (gyroscopic stability factor S_g = C^2 w^2/(4 A' M) = "
       << b.C * b.C * b.omega * b.omega / (4 * m.M(k, k) * b.static_moment) << ")";
  else if (b.static_moment < 0)
    os << ", restoring moment " << -b.static_moment << " N m/rad";
  if (b.pitch_damping > 0) os << ", pitch damping " << b.pitch_damping << " N m s/rad";
  if (m.has_circulatory() && m.circulatory[k] != 0)
    os << ", Magnus moment " << m.circulatory[k] << " N m/rad at this spin";
  if (b.ekman > 0) os << ", viscous (Ek = " << b.ekman << ", kept Im sum E = " << b.E_kept_imag << ")";
  if (b.galerkin) os << ", Galerkin reduction (its E the Galerkin residues)";
  if (b.unconverged > 0)
    os << ", " << b.unconverged << " kept clusters not converged (their roots marked *: docs/cones.md)";
  if (b.fit_hi > b.fit_lo) {
    os << ", the pseudo-modes of " << b.response_kind << " on s in [" << b.fit_lo << ", " << b.fit_hi << "] (error "
       << b.fit_error;
    if (b.fit_decay_error >= 0) {
      os << " of max|R|, of Im R against itself " << b.fit_decay_error << " at most";
      if (!b.fit_decay_s.empty()) os << "; each root's on its line";
    }
    os << ")";
    if (b.pruned_rows > 0)
      os << ", " << b.pruned_rows << (b.pruned_rows == 1 ? " row" : " rows")
         << " left out that no root needs (together under 1e-2 of the fit error and "
            "1e-4 of Im R on the window; prune = false keeps them)";
    const FitPassivity& p = sp.passivity[k];
    if (p.passive())
      os << ", passive on it (Im R >= " << p.scan.min_im << " max|R|)";
    else
      os << ", NOT passive: Im R = " << p.scan.min_im << " max|R| at s = " << p.scan.at
         << " (the fit can feed the chain energy: docs/rom.md, \"Viscous tanks\")";
  }
  os << "\n";
}

// The spins' own roots, apart from the verdict: σ = 0 is neutral there (a new rest angle, or a new steady spin).
void print_axial(std::ostream& os, const ChainModel& m, const AxialSpectrum& a) {
  const int chains = a.zeros - a.zero_eigenvectors;
  os << "axial rotations (apart from the verdict): sigma = 0 x " << a.zeros << " (" << a.zero_eigenvectors
     << (a.zero_eigenvectors == 1 ? " rest angle" : " rest angles");
  if (chains > 0) os << ", " << chains << (chains == 1 ? " Jordan chain" : " Jordan chains") << " of length 2: a uniform "
                     << "change of spin";
  os << ")";
  std::string rates;
  for (Eigen::Index j = 0; j < a.decay.size(); ++j)
    if (a.decay[j] > 0) {
      std::ostringstream r;
      r << std::setprecision(6) << a.decay[j];
      rates += (rates.empty() ? "" : ", ") + r.str();
    }
  if (!rates.empty()) os << "; the spins' perturbations decay at " << rates << " 1/s (axial friction)";
  if (m.axial.moment.cwiseAbs().maxCoeff() > 0 || m.axial.harmonic.cwiseAbs().maxCoeff() > 0)
    os << "; axial moments change the spins (run: /spin)";
  os << "\n";
}

namespace {

// Where a Krylov table's fit alone may put a body root's or a growing root's rate off by more than the 2 % that
// `confirm` holds a mesh to by default (--mesh-tolerance): the worst such root, for the verdict line (docs/viscous.md,
// "The error of Im R"); empty otherwise.
std::string fit_decay_warning(const Spectrum& sp) {
  const Root* worst = nullptr;
  int count = 0;
  for (const Root& r : sp.roots) {
    const bool decides = r.owner.rfind("body", 0) == 0 || -r.sigma.imag() > sp.noise;
    if (!decides || !(r.fit_decay_error > kDefaultMeshTolerance) || std::abs(r.sigma) <= sp.tolerance) continue;
    ++count;
    if (!worst || r.fit_decay_error > worst->fit_decay_error) worst = &r;
  }
  if (!worst) return "";
  std::ostringstream os;
  os << std::setprecision(3) << "; the table's fit alone may put " << worst->owner << "'s rate at "
     << worst->sigma.real() << " rad/s " << 100 * worst->fit_decay_error << " % off"
     << (count > 1 ? " (and " + std::to_string(count - 1) + (count == 2 ? " more root" : " more roots") + " over " +
                         std::to_string(static_cast<int>(100 * kDefaultMeshTolerance)) + " %)"
                   : "")
     << ": chain-rom confirm removes it";
  return os.str();
}

// The verdict lines of `spectrum`: stable or not with the margin and the distance to the threshold, or with
// dissipation the growth rates, a viscous chain's with the word that their mesh error is not measured.
void print_verdict(std::ostream& os, const ChainModel& m, const Spectrum& sp) {
  if (!m.dissipative()) {
    os << "stable: " << (sp.stable ? "yes" : "no") << " (|Im sigma| <= " << sp.tolerance << " counts as real)\n";
    os << "margin (largest |Im sigma|): " << sp.margin << " rad/s\n";
    if (sp.krein.defined)
      os << "distance to the threshold: " << sp.krein.gap << " rad/s between the closest real roots of opposite "
         << "Krein signature (" << sp.krein.left << " and " << sp.krein.right << " rad/s), the only ones that can "
         << "meet and leave the real axis\n";
    return;
  }
  std::string verdict = verdict_with_dissipation(m, sp);
  // A viscous tank's rates are its table mesh's: say so on the line a user reads (docs/rom.md, "Mesh error of
  // confirmed roots").
  if (m.viscous)
    verdict.insert(std::min(verdict.find('\n'), verdict.size()),
                   "; mesh error NOT MEASURED (the tables' mesh only: chain-rom confirm measures it)" +
                       fit_decay_warning(sp));
  os << verdict << "\n";
}

}  // namespace

void print_spectrum(std::ostream& os, const ChainModel& m, const Spectrum& sp, bool all) {
  os << (m.free_chain ? "free" : "fixed") << " chain, " << m.n << " bodies, " << m.n_modes()
     << " fluid modes\n";
  for (int k = 0; k < m.n; ++k) print_body_line(os, m, sp, k);
  // The verdict first, what a user reads; then the roots it rests on and the checks.
  const auto precision = os.precision();
  os << std::setprecision(6);
  print_verdict(os, m, sp);
  print_axial(os, m, sp.axial);
  os << std::setprecision(static_cast<int>(precision));
  print_roots(os, m, sp, all);
  os << std::setprecision(6);
  os << "Newton on det Phi = 0 from every root: worst shift " << sp.root_agreement << " of the spectral radius";
  if (sp.newton_failed) os << ", " << sp.newton_failed << " roots where Newton did not converge";
  os << "\n";
  if (sp.unconverged_owners)
    os << sp.unconverged_owners << " roots (marked *) belong to clusters their tables flag as not converged: their "
       << "frequencies are not reliable (docs/cones.md); the body roots are compared with a finer table in "
       << "docs/rom.md, \"Viscous tanks\"\n";
  if (sp.certificate_roots >= 0) {
    os << "certificate (sign changes of det Phi along the real axis): " << sp.certified_real << " of "
       << sp.certificate_roots << " roots proven real"
       << (sp.roots_at_zero ? " (" + std::to_string(sp.roots_at_zero) + " more at sigma = 0, not counted)" : "")
       << (sp.certified_real == sp.certificate_roots ? ": all real, whatever the tolerance" : "") << "\n";
    if (sp.certificate_disagrees())
      os << "certificate and tolerance DISAGREE: the verdict by tolerance is '" << (sp.stable ? "stable" : "unstable")
         << "', the sign count " << (sp.certified_real == sp.certificate_roots ? "proves every root real"
                                                                                : "does not prove every root real")
         << " (roots too close to tell apart, or a complex pair within the tolerance of the real axis: "
         << "docs/rom.md, \"Spectrum\")\n";
  }
  if (sp.companion_checked)
    os << "companion tables: " << sp.companion_moved << " of the roots the verdict rests on (body and growing roots, "
       << "marked ~) move by more than " << kCompanionTolerance << " in frequency or " << kCompanionRateTolerance
       << " in growth or decay rate (relative) when the tables are replaced by their coarser companions; the largest "
       << "moves " << sp.companion_worst << " and " << sp.companion_worst_rate
       << (sp.companion_moved ? ": those roots depend on the mesh (docs/trust.md)" : "") << "\n";
  if (sp.outside_fit) print_outside_fit(os, m, sp);
  for (int k = 0; k < m.n; ++k)
    if (!sp.passivity[k].passive())
      os << "warning: body " << k + 1 << "'s response fit is NOT passive (Im R = " << sp.passivity[k].scan.min_im
         << " max|R| at s = " << sp.passivity[k].scan.at << "): its roots may grow by the fit alone; check them "
         << "with the fluid's own response: chain-rom confirm SCENE (docs/rom.md, \"Confirmed roots\")\n";
  os << "worst det residual of (22): " << sp.det_residual << " (" << sp.unchecked
     << " roots at sigma = 0 or a pole not checked)\n";
  if (m.viscous)
    os << "these roots are those of the tanks' tables (a response fit holds R only to its fit error): chain-rom confirm "
          "SCENE gives them with the fluid's own response (docs/rom.md, \"Confirmed roots\")\n";
}

}  // namespace rc::rom
