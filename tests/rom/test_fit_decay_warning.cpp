// The verdict line of `spectrum` with a Krylov table's Im R profile (docs/viscous.md, "The error of Im R"): each root's
// line gives the table's estimate at its frequency, and where it puts a body root's rate more than 2 % off, the
// verdict line says so; at 0.1 % it says nothing of it.
#include "chain_model.hpp"
#include "closed_form_tables.hpp"
#include "output.hpp"
#include "response_fit_rows.hpp"
#include "scene.hpp"
#include "spectrum.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <cstdio>
#include <sstream>
#include <string>

namespace rc::rom {
namespace {
using cd = std::complex<double>;

// A one-body chain on a three-pole table whose Im R estimate is `error` everywhere on its window.
std::string spectrum_text(double error, const std::string& name) {
  rc::ModeTable t = test::response_fit_rows(rc::read_mode_table(std::string(RC_VISCOUS_TABLES) + "/sphere_ek1e-3.h5"),
                                            {{0.5, 0.02}, {-0.8, 0.05}, {1.4, 0.03}},
                                            {{0.3, 0.01}, {0.1, -0.005}, {0.05, 0.002}}, 1e-4);
  t.fit_decay_error = error;
  t.fit_decay_s = {t.fit_lo, t.fit_hi};
  t.fit_decay_profile = {error, error};
  const std::string file = std::string(RC_VISCOUS_TABLES) + "/" + name;
  test::write_table(t, file);
  std::ostringstream s;
  s << "[system]\nkind = \"fixed\"\ngravity = 0.0\n[[body]]\nmass = 0.5\nA = 0.002\nC = 0.001\ncom = 0.0\nspin = 100"
    << "\n[body.cavity]\ntable = \"" << file << "\"\ndensity = 1000.0\nscale = 0.05\ncenter = 0.0\nviscosity = "
    << 1e-3 * 100 * 0.05 * 0.05 << "\n";
  const ChainModel m = build_model(parse_scene_text(s.str(), ".", "fit-warning"));
  std::ostringstream out;
  print_spectrum(out, m, compute_spectrum(m));
  return out.str();
}

}  // namespace

TEST(FitDecayWarning, TheVerdictLineSaysWhenTheFitMayMoveABodyRate) {
  const std::string loose = spectrum_text(0.05, "fit_warning_loose.h5"), tight = spectrum_text(1e-3, "fit_warning_tight.h5");
  const auto verdict = [](const std::string& text) { return text.substr(text.find("stable:"), text.find('\n', text.find("stable:")) - text.find("stable:")); };
  std::printf("  5 %%: %s\n  0.1 %%: %s\n", verdict(loose).c_str(), verdict(tight).c_str());
  EXPECT_NE(verdict(loose).find("the table's fit alone may put body 1's rate"), std::string::npos);
  EXPECT_NE(verdict(loose).find(" 5 % off"), std::string::npos);
  EXPECT_EQ(verdict(tight).find("the table's fit alone"), std::string::npos);
  EXPECT_NE(tight.find("table fit 0.001 of it"), std::string::npos);
}

}  // namespace rc::rom
