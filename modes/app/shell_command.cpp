#include "shell_command.hpp"

#include "atomic_file.hpp"
#include "petsc_handles.hpp"
#include "shell_modes.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <iostream>
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
  const double have = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  if (have > 0 && need > 0.6 * have)
    throw std::runtime_error(fmt::format("{:.0f} unknowns need about {:.1f} GB, beyond 60 % of this machine's {:.1f} GB: "
                                         "a smaller --resolution (or a larger Ekman number)", unknowns, need / 1e9,
                                         have / 1e9));
}

}  // namespace

ShellCommand::ShellCommand(CLI::App& app) {
  app_ = app.add_subcommand("shell", "the viscous fluid in a full sphere or a spherical shell (no-slip walls), by "
                                     "Chebyshev x spherical-harmonic expansion: its damped modes near --target, printed "
                                     "and with -o written as a CSV (docs/spherical.md)");
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
  app_->add_option("-o,--output", output_, "CSV to write (lambda, decay, backward_error, change, converged)");
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
  ShellSettings s;
  s.inner_radius = inner_radius_;
  s.ekman = ekman_;
  s.m = m_;
  s.toroidal_first = symmetry_ == "antisymmetric";
  const auto truncation = [&](double factor) {
    const spherical::Truncation t = spherical::default_truncation(ekman_, inner_radius_, m_, resolution_ * factor);
    ShellSettings r = s;
    r.radial = radial_ > 0 ? static_cast<int>(std::lround(radial_ * factor)) : t.radial;
    r.lmax = lmax_ > 0 ? static_cast<int>(std::lround(lmax_ * factor)) : t.lmax;
    return r;
  };
  const ShellSettings fine = truncation(1.0);
  check_memory(fine);
  // A guess of the decay (the Ekman layer's Ek^1/2 scaling) puts the shift beside the mode rather than on the real axis.
  const std::complex<double> target(target_, 2.6 * std::sqrt(ekman_));
  const Solved main = solve(fine, target, modes_);
  Solved coarse;
  if (convergence_check_) coarse = solve(truncation(0.8), target, modes_);
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

}  // namespace rc::modes
