// `chain-rom response`: each body's tilt per unit harmonic moment on one body over a range of frequencies (a Bode
// plot), from the characteristic matrix itself (docs/rom.md, "Frequency response").
#include "commands.hpp"

#include "atomic_file.hpp"
#include "chain_model.hpp"
#include "external_programs.hpp"
#include "frequency_response.hpp"
#include "general_chain.hpp"
#include "general_response.hpp"
#include "load_scene.hpp"
#include "scene.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rc::rom::app {
namespace {

struct ResponseOptions {
  std::string scene, freq, out, png;
  int body = 0;
};

struct FrequencyRange {
  double from = 0, to = 0;
  int steps = 0;
};

// --freq FROM:TO:N, N >= 2 frequencies (rad/s), FROM < TO.
FrequencyRange parse_range(const std::string& text) {
  const auto bad = [&](const std::string& why) { return std::runtime_error("--freq " + text + ": " + why); };
  const auto c1 = text.find(':'), c2 = text.find(':', c1 == std::string::npos ? 0 : c1 + 1);
  if (c1 == std::string::npos || c2 == std::string::npos) throw bad("expected FROM:TO:N");
  FrequencyRange r;
  try {
    std::size_t used = 0;
    r.from = std::stod(text.substr(0, c1), &used);
    if (used != c1) throw bad("FROM is not a number");
    r.to = std::stod(text.substr(c1 + 1, c2 - c1 - 1), &used);
    if (used != c2 - c1 - 1) throw bad("TO is not a number");
    r.steps = std::stoi(text.substr(c2 + 1), &used);
    if (used != text.size() - c2 - 1) throw bad("N is not an integer");
  } catch (const std::logic_error&) {
    throw bad("expected FROM:TO:N with numbers");
  }
  if (!std::isfinite(r.from) || !std::isfinite(r.to) || !(r.from < r.to)) throw bad("need finite FROM < TO");
  if (r.steps < 2 || r.steps > 1000000) throw bad("N must be in 2..1000000");
  return r;
}

// `mirror` (the chain without axial symmetry): each body's mirror tilt A₋ at −σ − 2ω0 too (general_response.hpp);
// `sideband` (at two spins): the root mean square tilt at every other frequency (periodic_response.hpp).
void write_response_csv(const FrequencyResponse& r, const std::string& out, const Eigen::MatrixXcd* mirror = nullptr,
                        const Eigen::MatrixXd* sideband = nullptr) {
  write_text_atomically(out, [&](std::ostream& os) {
    // Resonances as comment lines (numpy's loadtxt and genfromtxt skip them): the plot marks them.
    for (std::size_t j = 0; j < r.resonances.size(); ++j) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "# resonance %.12g growth %.6g\n", r.resonances[j], r.resonance_growth[j]);
      os << buf;
    }
    os << "sigma";
    for (Eigen::Index k = 0; k < r.tilt.cols(); ++k) os << ",abs_" << k + 1 << ",phase_deg_" << k + 1;
    if (mirror)
      for (Eigen::Index k = 0; k < r.tilt.cols(); ++k) os << ",mirror_abs_" << k + 1 << ",mirror_phase_deg_" << k + 1;
    if (sideband)
      for (Eigen::Index k = 0; k < r.tilt.cols(); ++k) os << ",sideband_rms_" << k + 1;
    os << "\n";
    for (std::size_t i = 0; i < r.sigma.size(); ++i) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.12g", r.sigma[i]);
      os << buf;
      for (Eigen::Index k = 0; k < r.tilt.cols(); ++k) {
        const auto u = r.tilt(static_cast<Eigen::Index>(i), k);
        std::snprintf(buf, sizeof buf, ",%.9e,%.6f", std::abs(u), std::arg(u) * 180 / std::numbers::pi);
        os << buf;
      }
      for (Eigen::Index k = 0; mirror && k < mirror->cols(); ++k) {
        const auto u = (*mirror)(static_cast<Eigen::Index>(i), k);
        std::snprintf(buf, sizeof buf, ",%.9e,%.6f", std::abs(u), std::arg(u) * 180 / std::numbers::pi);
        os << buf;
      }
      for (Eigen::Index k = 0; sideband && k < sideband->cols(); ++k) {
        std::snprintf(buf, sizeof buf, ",%.9e", (*sideband)(static_cast<Eigen::Index>(i), k));
        os << buf;
      }
      os << "\n";
    }
  });
}

void print_summary(const FrequencyResponse& r, const ResponseOptions& o) {
  std::printf("tilt per unit moment on body %d (rad per N m; moment F e^{i sigma t}, sigma in [%g, %g] rad/s, %zu "
              "frequencies)\n", r.body + 1, r.sigma.front(), r.sigma.back(), r.sigma.size());
  for (Eigen::Index k = 0; k < r.tilt.cols(); ++k) {
    Eigen::Index at = 0;
    double peak = -1;
    for (Eigen::Index i = 0; i < r.tilt.rows(); ++i)
      if (std::abs(r.tilt(i, k)) > peak) peak = std::abs(r.tilt(i, k)), at = i;
    std::printf("  body %ld: largest |u| %.6g at sigma = %.6g rad/s\n", static_cast<long>(k + 1), peak,
                r.sigma[static_cast<std::size_t>(at)]);
  }
  std::printf("resonances in the range (the real parts of the chain's roots): %zu", r.resonances.size());
  for (std::size_t j = 0; j < r.resonances.size() && j < 8; ++j)
    std::printf("%s%.6g (growth %.3g 1/s)", j ? ", " : ": ", r.resonances[j], r.resonance_growth[j]);
  std::printf("%s\n", r.resonances.size() > 8 ? ", ... (all in the CSV)" : "");
  if (r.singular) std::printf("%d frequencies hit a root or a pole exactly (nan in the CSV)\n", r.singular);
  std::printf("wrote %s\n", o.out.c_str());
}

int run_response(const ResponseOptions& o) {
  const FrequencyRange range = parse_range(o.freq);
  const Scene scene = load_scene(o.scene);
  if (o.body < 1 || o.body > static_cast<int>(scene.bodies.size()))
    throw std::runtime_error("--body " + std::to_string(o.body) + ": the scene has bodies 1.." +
                             std::to_string(scene.bodies.size()));
  const std::filesystem::path out(o.out);
  if (out.has_parent_path() && !std::filesystem::is_directory(out.parent_path()))
    throw std::runtime_error(o.out + ": the output folder does not exist");
  if (!o.png.empty()) check_plot_tools(RC_PLOT_RESPONSE_SCRIPT, "Bode plot");
  TableCache tables;
  if (needs_general_chain(scene, tables)) {
    const GeneralChain chain = build_general_chain(scene, &tables);
    const GeneralFrequencyResponse g =
        general_frequency_response(chain, o.body - 1, range.from, range.to, range.steps);
    const FrequencyResponse r{g.body, g.sigma, g.tilt, g.resonances, g.resonance_growth, g.singular};
    const bool periodic = chain.periodic();
    write_response_csv(r, o.out, &g.mirror, periodic ? &g.sideband : nullptr);
    std::printf("chain without axial symmetry: the tilt A+ at sigma and the mirror tilt A- at -sigma - 2 spin "
                "(docs/rom.md, \"Frequency response\"); resonances from every root of the turning frame\n");
    if (periodic) {
      const double nu = 2 * std::numbers::pi / chain.period;
      std::printf("two spins: the coefficients are periodic (period %g s), so the steady tilt also holds the frequencies "
                  "sigma + k %g and -sigma - 2 spin + k %g rad/s (k != 0): their root mean square in sideband_rms_k; "
                  "%d sixth-order Magnus steps a period (docs/rom.md, \"Frequency response at two spins\")\n",
                  chain.period, nu, nu, g.steps_per_period);
    }
    print_summary(r, o);
  } else {
    const ChainModel m = build_model(scene, &tables);
    const FrequencyResponse r = frequency_response(m, o.body - 1, range.from, range.to, range.steps);
    write_response_csv(r, o.out);
    print_summary(r, o);
  }
  if (!o.png.empty()) draw_plot(RC_PLOT_RESPONSE_SCRIPT, o.out, o.png);
  return 0;
}

}  // namespace

Command add_response_command(CLI::App& app) {
  auto o = std::make_shared<ResponseOptions>();
  auto* cmd = app.add_subcommand("response", "frequency response: each body's tilt per unit harmonic moment on one "
                                             "body, with the resonances (docs/rom.md, \"Frequency response\")");
  cmd->add_option("SCENE", o->scene, "scene file (TOML)")->required();
  cmd->add_option("--body", o->body, "the body the moment acts on (1-based)")->required();
  cmd->add_option("--freq", o->freq, "FROM:TO:N: N frequencies sigma (rad/s) of the moment F e^{i sigma t}; "
                                     "sigma < 0 turns the other way")->required();
  cmd->add_option("-o,--output", o->out, "CSV: sigma, then |u_k| and its phase (degrees) for every body")->required();
  cmd->add_option("--png", o->png, "also draw the Bode plot (scripts/plot_response.py with /usr/bin/python3)");
  return {cmd, [o] { return run_response(*o); }};
}

}  // namespace rc::rom::app
