// Helpers of the chain-rom tests: scene text builders, root matching.
#pragma once

#include "chain_model.hpp"
#include "closed_form_tables.hpp"
#include "scene.hpp"
#include "first_order_system.hpp"
#include "spectrum.hpp"

#include <algorithm>
#include <complex>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace rc::rom::test {

inline std::filesystem::path test_dir() { return std::filesystem::path(RC_ROM_TEST_DIR) / "tables"; }

// A synthetic table of four modes that share the sum rule of a spheroid a = 1, c = 1.5 (0.5, 0.3, 0.15,
// 0.05 of it), for the selection and static-correction tests.
inline rc::ModeTable four_mode_table() {
  rc::ModeTable t = spheroid_table(1, 1.5);
  const double S = t.A_f - t.J_zh;
  t.E = {0.5 * S, 0.3 * S, 0.15 * S, 0.05 * S};
  t.lambda = {0.9, -0.5, 0.3, 0.01};
  t.kappa = {2 / 0.9, 2 / -0.5, 2 / 0.3, 2 / 0.01};
  t.a = {1, 1, 1, 1};
  t.N2 = {2 / t.E[0], 2 / t.E[1], 2 / t.E[2], 2 / t.E[3]};
  t.residual = {0, 0, 0, 0};
  return t;
}

inline std::string num(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  std::string s = os.str();
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

struct Body {
  double mass = 1, A = 0.1, C = 0.05, com = 0.1, next = 0.3, spin = 0;
  std::string table;  // empty: no cavity
  double density = 1000, scale = 0.05, center = 0;
  int modes = 0;      // 0: all
  bool static_correction = false;
};
struct Joint { double stiffness = 0, friction = 0; };

inline std::string scene_text(const std::vector<Body>& bodies, const std::vector<Joint>& joints,
                              double g, bool free_chain = false, double support = 0,
                              const std::string& extra = "") {
  std::ostringstream os;
  os << "[system]\nkind = \"" << (free_chain ? "free" : "fixed") << "\"\ngravity = " << num(g) << "\n";
  for (const Body& b : bodies) {
    os << "[[body]]\nmass = " << num(b.mass) << "\nA = " << num(b.A) << "\nC = " << num(b.C)
       << "\ncom = " << num(b.com) << "\nnext_joint = " << num(b.next) << "\nspin = " << num(b.spin) << "\n";
    if (!b.table.empty()) {
      os << "[body.cavity]\ntable = \"" << b.table << "\"\ndensity = " << num(b.density)
         << "\nscale = " << num(b.scale) << "\ncenter = " << num(b.center) << "\n";
      if (b.modes > 0) os << "modes = " << b.modes << "\n";
      if (b.static_correction) os << "static_correction = true\n";
    }
  }
  for (const Joint& j : joints)
    os << "[[joint]]\nstiffness = " << num(j.stiffness) << "\nfriction = " << num(j.friction) << "\n";
  if (!free_chain) os << "[support]\nfriction = " << num(support) << "\n";
  os << extra;
  return os.str();
}

inline ChainModel model_of(const std::string& text) {
  return build_model(parse_scene_text(text, test_dir(), "test-scene"));
}

inline std::vector<std::complex<double>> roots_of(const Spectrum& sp) {
  std::vector<std::complex<double>> r;
  for (const auto& x : sp.roots) r.push_back(x.sigma);
  return r;
}

// Largest distance between two root sets of equal size (greedy nearest matching), relative to scale.
inline double root_set_distance(std::vector<std::complex<double>> a, std::vector<std::complex<double>> b,
                                double scale) {
  if (a.size() != b.size()) return 1e300;
  double worst = 0;
  for (const auto& x : a) {
    auto it = std::min_element(b.begin(), b.end(), [&](auto p, auto q) { return std::abs(p - x) < std::abs(q - x); });
    worst = std::max(worst, std::abs(*it - x) / scale);
    b.erase(it);
  }
  return worst;
}

inline double spectral_radius(const std::vector<std::complex<double>>& r) {
  double m = 0;
  for (auto x : r) m = std::max(m, std::abs(x));
  return m;
}

// Every root σ of (26) (u ∝ e^{iσt}) is, in the frame turning at ω0, the pair σ + ω0 and −(σ̄ + ω0) of the real
// system (u = e^{−iω0t}(q_x − i q_y)).
inline std::vector<std::complex<double>> turned(const std::vector<std::complex<double>>& sigma, double w) {
  std::vector<std::complex<double>> out;
  for (const auto& s : sigma) {
    out.push_back(s + w);
    out.push_back(-std::conj(s) - w);
  }
  return out;
}

// Drops the n roots closest to zero (fluid integrators, free-chain neutral tilts).
inline std::vector<std::complex<double>> drop_smallest(std::vector<std::complex<double>> r, std::size_t n) {
  std::sort(r.begin(), r.end(), [](auto p, auto q) { return std::abs(p) < std::abs(q); });
  r.erase(r.begin(), r.begin() + static_cast<long>(std::min(n, r.size())));
  return r;
}

}  // namespace rc::rom::test

namespace rc::rom::test {
// Writes (once per process) a closed-form table into the build tree and returns its file name
// relative to test_dir(), for use in scene texts.
inline std::string sphere_file(double R) {
  const std::string name = "sphere_" + num(R) + ".h5";
  if (!std::filesystem::exists(test_dir() / name)) write_table(sphere_table(R), test_dir() / name);
  return name;
}
inline std::string spheroid_file(double a, double c) {
  const std::string name = "spheroid_" + num(a) + "_" + num(c) + ".h5";
  if (!std::filesystem::exists(test_dir() / name)) write_table(spheroid_table(a, c), test_dir() / name);
  return name;
}
}  // namespace rc::rom::test
