// Passivity of response-fit tanks (rom/model/fit_passivity.hpp): Im R(s) >= 0 on the fit's window. A one-pole fit with a
// real residue is passive; one whose residue has a large imaginary part is not, and the smallest Im R found on the
// grid must be the minimum of the closed form Im[E/(s - p)] over the window.
#include "chain_model.hpp"
#include "closed_form_tables.hpp"
#include "fit_passivity.hpp"
#include "scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <sstream>
#include <string>

namespace rc::rom {
namespace {
using cd = std::complex<double>;

// The viscous sphere's table (make_viscous_tables.sh) turned into a one-pole response fit on s in [-1.5, 2].
ChainModel one_pole_fit(cd pole, cd residue, double spin) {
  rc::ModeTable t = rc::read_mode_table(std::string(RC_VISCOUS_TABLES) + "/sphere_ek1e-3.h5");
  t.galerkin = {};  // a response fit's poles are no modes
  t.lambda = {pole.real()};
  t.kappa = {2 / pole.real()};
  t.decay = {pole.imag()};
  t.E = {residue.real()};
  t.E_imag = {residue.imag()};
  const cd a = std::sqrt(residue / 2.0);
  t.a = {a.real()};
  t.a_imag = {a.imag()};
  t.fit_lo = -1.5;
  t.fit_hi = 2;
  t.fit_error = 1e-6;
  const std::string file = std::string(RC_VISCOUS_TABLES) + "/one_pole_fit.h5";
  test::write_table(t, file);
  std::ostringstream s;
  s.precision(17);
  s << "[system]\nkind = \"fixed\"\ngravity = 0.0\n[[body]]\nmass = 0.5\nA = 0.002\nC = 0.001\ncom = 0.0\nspin = " << spin
    << "\n[body.cavity]\ntable = \"" << file << "\"\ndensity = 1000.0\nscale = 0.05\ncenter = 0.0\nviscosity = "
    << 1e-3 * std::abs(spin) * 0.05 * 0.05 << "\n";
  return build_model(parse_scene_text(s.str(), ".", "one-pole-fit"));
}

}  // namespace

TEST(FitPassivity, RealResidueIsPassiveAndATwistedOneIsNot) {
  const cd pole(0.5, 0.05);
  for (const double spin : {100.0, -100.0}) {
    const FitPassivity real = fit_passivity(one_pole_fit(pole, 0.3, spin), 0);
    ASSERT_TRUE(real.checked);
    EXPECT_TRUE(real.passive()) << real.scan.min_im;
    const cd twisted(0.3, -1.0);
    const FitPassivity p = fit_passivity(one_pole_fit(pole, twisted, spin), 0);
    // The closed form on a dense grid: min Im R / max |R| over [-1.5, 2].
    double lowest = 1e300, largest = 0, at = 0;
    for (int i = 0; i <= 700000; ++i) {
      const double s = -1.5 + 3.5 * i / 700000.0;
      const cd R = twisted / (s - pole);
      largest = std::max(largest, std::abs(R));
      if (R.imag() < lowest) lowest = R.imag(), at = s;
    }
    std::printf("  spin %+.0f: real residue min Im R = %.3e max|R|; twisted: %.6e at s = %.5f (closed form %.6e at "
                "%.5f)\n", spin, real.scan.min_im, p.scan.min_im, p.scan.at, lowest / largest, at);
    EXPECT_FALSE(p.passive());
    EXPECT_NEAR(p.scan.min_im, lowest / largest, 1e-3 * std::abs(lowest / largest));
    EXPECT_NEAR(p.scan.at, at, 0.01);
  }
}

}  // namespace rc::rom
