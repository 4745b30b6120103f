#include "shell_command.hpp"

#include "atomic_file.hpp"
#include "cavity_response.hpp"
#include "machine_memory.hpp"
#include "petsc_handles.hpp"
#include "progress.hpp"
#include "shell_modes.hpp"
#include "shell_response.hpp"
#include "shell_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <istream>
#include <stdexcept>
#include <vector>

namespace rc::modes {
namespace {

using spherical::ShellSettings;

struct Solved {
  std::vector<ViscousMode> modes;
  double seconds = 0;
};

Solved solve(const ShellSettings& s, std::complex<double> target, int pairs) {
  const auto start = std::chrono::steady_clock::now();
  Solved out;
  out.modes = spherical::shell_modes_near(s, target, pairs, PETSC_COMM_WORLD);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

// The change of each mode against the coarser run's nearest: max(|Δ Re λ| / |Re λ|, |Δ Im λ| / Im λ).
double change_against(const ViscousMode& mode, const std::vector<ViscousMode>& coarse) {
  double best = INFINITY;
  for (const ViscousMode& c : coarse)
    best = std::min(best, std::max(std::abs(c.lambda.real() - mode.lambda.real()) / std::abs(mode.lambda.real()),
                                   std::abs(c.lambda.imag() - mode.lambda.imag()) / mode.lambda.imag()));
  return best;
}

// Refuses a truncation whose factors would not fit: measured peaks (2026-11-28, this project's 2-core machine) of
// 1.4 GB at 73 170 unknowns (the shell, Ek = 1e-6: about 20 kB each, its stricter pivoting's fill) and 1.6 GB at
// 143 648 (the sphere, 1e-7: 11 kB); with a margin, 30 and 15 kB per unknown against 60 % of the machine's memory.
void check_memory(const ShellSettings& s) {
  const double unknowns = double(s.lmax - std::max(s.m, 1) + 1) * s.radial;
  const double need = unknowns * (s.inner_radius > 0 ? 3e4 : 1.5e4);
  const double have = machine_memory_bytes();
  if (have > 0 && need > 0.6 * have)
    throw std::runtime_error(fmt::format("{:.0f} unknowns need about {:.1f} GB, beyond 60 % of this machine's {:.1f} GB: "
                                         "a smaller --resolution (or a larger Ekman number)", unknowns, need / 1e9,
                                         have / 1e9));
}

}  // namespace

ShellCommand::ShellCommand(CLI::App& app) {
  app_ = app.add_subcommand("shell", "the viscous fluid in a full sphere or a spherical shell (no-slip walls), by "
                                     "Chebyshev x spherical-harmonic expansion: its damped modes near --target, printed "
                                     "and with -o written as a CSV; with --sigma its response R(sigma) to the tilt, "
                                     "or with -o FILE.h5 a response table for chain-rom (docs/spherical.md)");
  app_->add_option("--ekman", ekman_, "Ekman number nu/(Omega R^2) > 0, R the outer radius")->required();
  app_->add_option("--inner-radius", inner_radius_, "inner radius over the outer, in [0, 1) (default 0: the full sphere)");
  app_->add_option("--target", target_, "frequency near which modes are wanted, in the rotating frame (default 1.0: "
                                        "the spin-over mode)");
  app_->add_option("--modes", modes_, "how many damped modes nearest the target (default 1)");
  app_->add_option("--m", m_, "azimuthal wavenumber (default 1)");
  app_->add_option("--symmetry", symmetry_, "equatorial symmetry of the flow: antisymmetric (the spin-over's, "
                                            "default) or symmetric");
  app_->add_option("--resolution", resolution_, "truncation relative to the default (17 Ek^-1/5 Chebyshev and "
                                                "harmonic degrees for a shell, 21 Ek^-1/5 for the sphere; default 1)");
  app_->add_option("--radial", radial_, "Chebyshev coefficients per scalar (overrides --resolution; the full sphere "
                                        "keeps those of one parity, degrees below twice this)");
  app_->add_option("--lmax", lmax_, "highest spherical-harmonic degree (overrides --resolution)");
  app_->add_option("--convergence-tolerance", tolerance_, "a mode is flagged converged if it moves by less than this "
                                                          "(relative, frequency and decay) against 0.8 times the "
                                                          "truncation (default 1e-6)");
  app_->add_flag("--no-convergence-check", [this](std::int64_t) { convergence_check_ = false; },
                 "skip the run at 0.8 times the truncation");
  app_->add_option("--sigma", sigma_, "instead of modes, the fluid's response R(sigma) to the tilt at these "
                                      "frequencies (FROM:TO:N or a list of complex numbers, as cavity-modes response "
                                      "takes them); with -o FILE.h5 a response table for chain-rom on the window "
                                      "FROM:TO:N (docs/spherical.md)");
  app_->add_option("--sigma-imag", sigma_imag_, "imaginary part of every frequency of --sigma FROM:TO:N (default 0)");
  app_->add_option("--max-fit-error", max_fit_error_, "a response table's allowed fit error, relative to max|R| on "
                                                      "the window (default 1e-6)");
  app_->add_flag("--serve", serve_, "answer R(sigma) for each complex sigma read from standard input, one a line "
                                    "(chain-rom confirm drives it; docs/spherical.md)");
  app_->add_option("--mesh-level", mesh_level_, "the truncation raised 1.5 times this many times (a study of the "
                                                "truncation, as --mesh-level refines a mesh; default 0)");
  app_->add_option("--mesh-ekman", mesh_ekman_, "the default truncation as for this Ekman number (at most --ekman: "
                                                "one truncation for several Ekman numbers)");
  app_->add_option("-o,--output", output_, "CSV to write (lambda, decay, backward_error, change, converged; with "
                                           "--sigma sigma and R), or with --sigma FILE.h5: the response table");
}

spherical::ShellSettings ShellCommand::settings_at(double factor) const {
  ShellSettings s;
  s.inner_radius = inner_radius_;
  s.ekman = ekman_;
  s.m = m_;
  s.toroidal_first = symmetry_ == "antisymmetric";
  const double level = std::pow(1.5, mesh_level_);
  const spherical::Truncation t = spherical::default_truncation(mesh_ekman_ > 0 ? mesh_ekman_ : ekman_, inner_radius_,
                                                                m_, resolution_ * factor * level);
  s.radial = radial_ > 0 ? static_cast<int>(std::lround(radial_ * factor * level)) : t.radial;
  s.lmax = lmax_ > 0 ? static_cast<int>(std::lround(lmax_ * factor * level)) : t.lmax;
  return s;
}

int ShellCommand::run(const std::string& command_line) const {
  if (!(ekman_ > 0 && std::isfinite(ekman_))) throw std::runtime_error("--ekman must be a positive number");
  if (!(inner_radius_ >= 0 && inner_radius_ < 1)) throw std::runtime_error("--inner-radius must be in [0, 1)");
  if (symmetry_ != "antisymmetric" && symmetry_ != "symmetric")
    throw std::runtime_error("--symmetry must be antisymmetric or symmetric, not '" + symmetry_ + "'");
  if (modes_ < 1 || modes_ > 50) throw std::runtime_error("--modes must be in 1..50");
  if (!(resolution_ >= 0.25 && resolution_ <= 8)) throw std::runtime_error("--resolution must be in [0.25, 8]");
  if (!(tolerance_ > 0)) throw std::runtime_error("--convergence-tolerance must be positive");
  if (m_ < 0 || m_ > 200) throw std::runtime_error("--m must be in 0..200");
  if (!std::isfinite(target_)) throw std::runtime_error("--target must be a number");
  if (const std::filesystem::path out(output_); out.has_parent_path() && !std::filesystem::is_directory(out.parent_path()))
    throw std::runtime_error(output_ + ": the output folder does not exist");
  if (mesh_level_ < 0 || mesh_level_ > 4) throw std::runtime_error("--mesh-level must be in 0..4");
  if (!(mesh_ekman_ >= 0 && mesh_ekman_ <= ekman_)) throw std::runtime_error("--mesh-ekman must be in (0, --ekman]");
  if (serve_) {
    serve(std::cin, std::cout);
    return 0;
  }
  if (!sigma_.empty()) return run_response(command_line);
  const ShellSettings fine = settings_at(1.0);
  check_memory(fine);
  // A guess of the decay (the Ekman layer's Ek^1/2 scaling) puts the shift beside the mode rather than on the real axis.
  const std::complex<double> target(target_, 2.6 * std::sqrt(ekman_));
  const Solved main = solve(fine, target, modes_);
  Solved coarse;
  if (convergence_check_) coarse = solve(settings_at(0.8), target, modes_);
  if (!is_root_rank()) return 0;
  std::cout << fmt::format("{}: Ek = {:g}, m = {}, {} flow, {} Chebyshev coefficients per scalar, lmax = {}: {} "
                           "unknowns, {:.2f} s{}\n",
                           inner_radius_ > 0 ? fmt::format("shell r_i = {:g}", inner_radius_) : "sphere", ekman_, m_,
                           symmetry_, fine.radial, fine.lmax, (fine.lmax - std::max(m_, 1) + 1) * fine.radial,
                           main.seconds,
                           convergence_check_ ? fmt::format(" (check at 0.8 times: {:.2f} s)", coarse.seconds) : "");
  std::cout << "  lambda (frequency)        decay                   backward   change     converged\n";
  std::vector<double> changes;
  for (const ViscousMode& mode : main.modes) {
    const double change = convergence_check_ ? change_against(mode, coarse.modes) : NAN;
    changes.push_back(change);
    std::cout << fmt::format("  {:<24.16g}  {:<22.16g}  {:<9.2e}  {:<9.2e}  {}\n", mode.lambda.real(),
                             mode.lambda.imag(), mode.residual, change,
                             !convergence_check_ ? "-" : change < tolerance_ ? "yes" : "NO");
  }
  const int unsettled = static_cast<int>(std::count_if(changes.begin(), changes.end(), [&](double c) {
    return convergence_check_ && !(c < tolerance_);
  }));
  if (unsettled > 0)
    std::cout << fmt::format("NOT CONVERGED: {} mode(s) moved by more than {:g} against 0.8 times the truncation; "
                             "raise --resolution\n", unsettled, tolerance_);
  if (!output_.empty())
    write_text_atomically(output_, [&](std::ostream& out) {
      out << "# " << command_line << "\n# radial " << fine.radial << ", lmax " << fine.lmax << "\n";
      out << "lambda,decay,backward_error,change,converged\n";
      for (std::size_t k = 0; k < main.modes.size(); ++k)
        out << fmt::format("{:.17g},{:.17g},{:.3e},{:.3e},{}\n", main.modes[k].lambda.real(),
                           main.modes[k].lambda.imag(), main.modes[k].residual, changes[k],
                           !convergence_check_ ? "" : changes[k] < tolerance_ ? "yes" : "no");
    });
  return 0;
}

namespace {

bool is_h5(const std::string& path) { return std::filesystem::path(path).extension() == ".h5"; }

// The tilt forces the m = 1 flow that is antisymmetric about the equator only (shell_response.hpp).
void check_tilt_flow(int m, const std::string& symmetry, const char* option) {
  if (m != 1 || symmetry != "antisymmetric")
    throw std::runtime_error(std::string(option) + ": the tilt forces only the m = 1 antisymmetric flow (leave out --m "
                             "and --symmetry)");
}

void write_response_csv(const std::string& path, const std::string& command_line, const ShellSettings& s,
                        const std::vector<std::complex<double>>& sigma, const std::vector<std::complex<double>>& R,
                        const std::vector<double>& change) {
  write_text_atomically(path, [&](std::ostream& out) {
    out << "# " << command_line << "\n# spectral forced solves, radial " << s.radial << ", lmax " << s.lmax
        << "; change: |R - R at 0.8 times the truncation| / |R|\nsigma_re,sigma_im,R_re,R_im,change\n";
    for (std::size_t k = 0; k < sigma.size(); ++k)
      out << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.3e}\n", sigma[k].real(), sigma[k].imag(), R[k].real(),
                         R[k].imag(), change[k]);
  });
}

}  // namespace

// One σ a line in, "R_re R_im" (17 digits) out, as `cavity-modes response ... --serve` answers (app/main.cpp's
// serve_response): a line it cannot answer gets "error: <one line>" and the session goes on. Serial only.
void ShellCommand::serve(std::istream& in, std::ostream& out) const {
  if (world_ranks() > 1) throw std::runtime_error("--serve runs serially (one process per tank), not under mpirun");
  check_tilt_flow(m_, symmetry_, "--serve");
  const ShellSettings s = settings_at(1.0);
  check_memory(s);
  spherical::ShellResponse R(s, PETSC_COMM_WORLD);
  out << fmt::format("ready: viscous fluid, Ekman number {:g}, spectral forced solves in the {} ({} Chebyshev "
                     "coefficients per scalar, lmax {}; {} real unknowns)\n", ekman_,
                     inner_radius_ > 0 ? fmt::format("shell r_i = {:g}", inner_radius_) : "sphere", s.radial, s.lmax,
                     2 * R.complex_unknowns())
      << std::flush;
  std::string line;
  while (std::getline(in, line) && !line.empty()) {
    try {
      const std::vector<std::complex<double>> sigma = parse_sigma_spec(line, 0);
      if (sigma.size() != 1) throw std::runtime_error("one complex frequency a line");
      const std::complex<double> r = R(sigma.front());
      out << fmt::format("{:.17g} {:.17g}\n", r.real(), r.imag()) << std::flush;
    } catch (const std::exception& e) {
      out << "error: " << e.what() << "\n" << std::flush;
    }
  }
}

// --sigma: R at the given frequencies (each with its change against 0.8 times the truncation), or a response table.
int ShellCommand::run_response(const std::string& command_line) const {
  check_tilt_flow(m_, symmetry_, "--sigma");
  if (!(max_fit_error_ > 0)) throw std::runtime_error("--max-fit-error must be positive");
  const std::vector<std::complex<double>> sigma = parse_sigma_spec(sigma_, sigma_imag_);
  const ShellSettings fine = settings_at(1.0), check = settings_at(0.8);
  check_memory(fine);
  const auto start = std::chrono::steady_clock::now();
  if (is_h5(output_)) {
    spherical::ShellTableRequest req{fine, check, {}, max_fit_error_};
    for (const auto& x : sigma) {
      if (x.imag() != 0) throw std::runtime_error("a response table needs real frequencies (--sigma FROM:TO:N, no --sigma-imag)");
      req.window.push_back(x.real());
    }
    Progress lines([](const std::string& line) {  // "[  1.2 s] ..." on the root rank's stderr
      if (is_root_rank()) std::cerr << line << std::endl;
    });
    spherical::ShellTable made =
        spherical::shell_response_table(req, [&](const std::string& line) { lines.note(line); });
    made.table.command_line = command_line;
    made.table.geometry_source = made.table.shape == "sphere" ? "sphere radius=1"
                                                              : fmt::format("shell inner_radius={:g} radius=1", inner_radius_);
    if (is_root_rank()) {
      rc::write_mode_table(made.table, output_);
      std::cout << fmt::format("{}: response table of {} pseudo-modes on [{:g}, {:g}], fit error {:.2g}, change against "
                               "0.8 times the truncation {:.2g} of max|R|{}, {:.1f} s\n", output_,
                               made.table.lambda.size(), made.table.fit_lo, made.table.fit_hi, made.table.fit_error,
                               made.truncation_change, made.truncation_change < tolerance_ ? "" : " (NOT CONVERGED: "
                               "raise --resolution)", made.table.wall_seconds);
    }
    return 0;
  }
  spherical::ShellResponse R(fine, PETSC_COMM_WORLD), coarse(check, PETSC_COMM_WORLD);
  std::vector<std::complex<double>> values;
  std::vector<double> change;
  for (const auto& x : sigma) {
    values.push_back(R(x));
    change.push_back(std::abs(values.back() - coarse(x)) / std::abs(values.back()));
  }
  if (!is_root_rank()) return 0;
  if (!output_.empty()) {
    write_response_csv(output_, command_line, fine, sigma, values, change);
    return 0;
  }
  std::cout << fmt::format("R(sigma) by spectral forced solves ({} Chebyshev coefficients per scalar, lmax {}), {:.2f} s\n",
                           fine.radial, fine.lmax,
                           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  std::cout << "  sigma                         R                                       change\n";
  for (std::size_t k = 0; k < sigma.size(); ++k)
    std::cout << fmt::format("  {:<12.8g} {:+.6g}i  {:<20.15g} {:+.15g}i  {:.2e}{}\n", sigma[k].real(), sigma[k].imag(),
                             values[k].real(), values[k].imag(), change[k], change[k] < tolerance_ ? "" : "  NOT CONVERGED");
  return 0;
}

}  // namespace rc::modes
