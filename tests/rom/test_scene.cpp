// Scene parsing and model assembly: fluid mass properties, mode selection, one-line errors.
#include "rom_test_util.hpp"

#include <gtest/gtest.h>

#include <fstream>

using namespace rc::rom;
using namespace rc::rom::test;

namespace {
std::string error_of(const std::string& text) {
  try {
    model_of(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}
void expect_error(const std::string& text, const std::string& key, const std::string& cause = "") {
  const std::string msg = error_of(text);
  std::printf("  error: %s\n", msg.c_str());
  EXPECT_NE(msg.find(key), std::string::npos) << "expected key " << key << " in: " << msg;
  EXPECT_NE(msg.find(cause), std::string::npos) << "expected cause " << cause << " in: " << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << "not one line: " << msg;
}
}  // namespace

TEST(Scene, FluidMassPropertiesFollowSpecScaling) {
  // Spheroid a = 1, c = 2 (table units), density 800, scale 0.1, centroid 0.25 m from O_1.
  Body b;
  b.mass = 2; b.A = 0.05; b.C = 0.03; b.com = 0.1; b.spin = 50;
  b.table = spheroid_file(1, 2); b.density = 800; b.scale = 0.1; b.center = 0.25;
  const ChainModel m = model_of(scene_text({b}, {}, 9.81));
  const rc::ModeTable t = spheroid_table(1, 2);
  const double L3 = 1e-3, L5 = 1e-5, mf = 800 * L3 * t.volume;
  const double m_exp = 2 + mf, c_exp = (2 * 0.1 + mf * 0.25) / m_exp;
  const double A_exp = 0.05 + 800 * L5 * t.A_f + mf * 0.25 * 0.25, C_exp = 0.03 + 800 * L5 * t.C_f;
  const double E_exp = 800 * L5 * t.E[0], lam_exp = 50 * t.lambda[0];
  std::printf("  m %.3e  c %.3e  A %.3e  C %.3e  E %.3e  lambda %.3e (relative errors)\n",
              std::abs(m.bodies[0].m - m_exp) / m_exp, std::abs(m.bodies[0].c - c_exp) / c_exp,
              std::abs(m.bodies[0].A - A_exp) / A_exp, std::abs(m.bodies[0].C - C_exp) / C_exp,
              std::abs(m.modes[0].E - E_exp) / E_exp, std::abs(m.modes[0].lambda - lam_exp) / lam_exp);
  EXPECT_NEAR(m.bodies[0].m, m_exp, 1e-14 * m_exp);
  EXPECT_NEAR(m.bodies[0].c, c_exp, 1e-14 * c_exp);
  EXPECT_NEAR(m.bodies[0].A, A_exp, 1e-14 * A_exp);
  EXPECT_NEAR(m.bodies[0].C, C_exp, 1e-14 * C_exp);
  ASSERT_EQ(m.n_modes(), 1);
  EXPECT_NEAR(m.modes[0].E, E_exp, 1e-14 * E_exp);
  EXPECT_NEAR(m.modes[0].lambda, lam_exp, 1e-14 * lam_exp);
  EXPECT_NEAR(m.a[0], m_exp * c_exp, 1e-14 * m_exp * c_exp);
  EXPECT_NEAR(m.M_eff(0, 0), A_exp - E_exp, 1e-13 * A_exp);
}

TEST(Scene, OnlyWhatTheSceneUsesEntersTheModel) {
  // A 4-mode synthetic table; modes = 2 keeps the two largest, coverage picks the fewest modes.
  const rc::ModeTable t = four_mode_table();
  const double S = t.A_f - t.J_zh;
  write_table(t, test_dir() / "four_modes.h5");
  Body with; with.table = "four_modes.h5"; with.spin = 10;
  Body without;
  with.modes = 2;
  ChainModel m = model_of(scene_text({with, without}, {{}}, 9.81));
  EXPECT_EQ(m.n_modes(), 2);
  EXPECT_EQ(m.modes[1].table_index, 1);
  EXPECT_FALSE(m.bodies[1].has_fluid);
  EXPECT_EQ(build_first_order(m).dim(), 2 * 2 + 2);  // a body without a cavity has no fluid coordinates
  with.modes = 0;
  std::string text = scene_text({with, without}, {{}}, 9.81);
  text.replace(text.find("center = 0.0\n"), 13, "center = 0.0\ncoverage = 0.9\n");
  m = model_of(text);
  EXPECT_EQ(m.n_modes(), 3);  // 0.5 + 0.3 + 0.15 >= 0.9
  EXPECT_NEAR(m.bodies[0].coverage, 0.95, 1e-12);
  // Static correction: the remainder of the sum rule becomes frequency-independent inertia.
  with.modes = 1; with.static_correction = true;
  m = model_of(scene_text({with, without}, {{}}, 9.81));
  const double rem = m.bodies[0].sum_rule - m.bodies[0].E_kept;
  std::printf("  static correction %.6e, expected %.6e\n", m.bodies[0].E_rem, 0.5 * 1000 * std::pow(0.05, 5) * S);
  EXPECT_NEAR(m.bodies[0].E_rem, rem, 1e-15);
  EXPECT_NEAR(m.bodies[0].E_rem, 0.5 * 1000 * std::pow(0.05, 5) * S, 1e-12 * rem);
}

TEST(Scene, BadInputGivesOneLineErrorNamingTheKey) {
  Body b; b.table = spheroid_file(1, 2);
  const std::string good = scene_text({b, Body{}}, {{}}, 9.81);
  EXPECT_EQ(error_of(good), "");
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    const auto p = t.find(from);
    EXPECT_NE(p, std::string::npos) << from;
    return t.replace(p, from.size(), to);
  };
  expect_error(with("mass = 1.0", "mass = -1.0"), "body[1].mass", ">= 0");
  expect_error(with("mass = 1.0", "mass = nan"), "body[1].mass", "finite");
  expect_error(with("A = 0.10000000000000001", "A = 0.1\nbogus = 3"), "body[1].bogus", "unknown key");
  expect_error(with("density = 1000.0", "density = 1000.0\ncolour = \"red\""), "body[1].cavity.colour", "unknown key");
  expect_error(with("gravity = 9.8100000000000005", "gravity = 9.81\nwind = 1"), "system.wind", "unknown key");
  expect_error(with("density = 1000.0", "density = 1000.0\nmodes = 5"), "body[1].cavity.modes", "holds 1");
  expect_error(with("[[joint]]", "[[joint]]\n[[joint]]"), "joint", "needs 1");
  expect_error(good + "[initial]\ntilt = [[0.01, 0.0]]\n", "initial.tilt", "has 1 entries");
  expect_error(with("kind = \"fixed\"", "kind = \"loose\""), "system.kind");
  expect_error(with("spin = 0.0", "spin = \"fast\""), "body[1].spin", "number");
  expect_error(good + "[run]\nt_end = 1.0\n", "run.output_step", "missing");
  // A file that is not a mode table.
  { std::ofstream(test_dir() / "not_a_table.h5") << "hello"; }
  expect_error(with(b.table, "not_a_table.h5"), "body[1].cavity.table", "not an HDF5 file");
  expect_error(with(b.table, "missing.h5"), "body[1].cavity.table");
  expect_error("[system\nkind=1", "syntax error");
}

// `origin` places the tank by the table's own z = 0: the centroid follows as origin + scale·centroid_z, the same
// model as `center` given by hand (docs/scene-format.md). Both keys, or neither, are one-line errors.
TEST(Scene, OriginPlacesTheTankByTheTableOrigin) {
  rc::ModeTable shifted = spheroid_table(1, 0.7);
  shifted.centroid_z = 0.7;  // as if the geometry's z = 0 were 0.7 table units below the fluid's centroid
  write_table(shifted, test_dir() / "spheroid_shifted.h5");
  Body b;
  b.mass = 2; b.A = 0.05; b.C = 0.03; b.com = 0.1; b.spin = 40;
  b.table = "spheroid_shifted.h5"; b.scale = 0.1; b.center = 0.1 + 0.1 * 0.7;
  const std::string by_center = scene_text({b}, {}, 9.81);
  std::string by_origin = by_center;
  by_origin.replace(by_origin.find("center = "), by_origin.find('\n', by_origin.find("center = ")) - by_origin.find("center = "),
                    "origin = 0.1");
  const ChainModel a = model_of(by_center), o = model_of(by_origin);
  std::printf("  c: center %.15g, origin %.15g; A: %.15g, %.15g\n", a.bodies[0].c, o.bodies[0].c, a.bodies[0].A,
              o.bodies[0].A);
  EXPECT_NEAR(o.bodies[0].c, a.bodies[0].c, 1e-15);
  EXPECT_NEAR(o.bodies[0].A, a.bodies[0].A, 1e-15);
  EXPECT_NEAR(o.bodies[0].fluid_center, 0.17, 1e-15);
  std::string both = by_center;
  both.replace(both.find("center = "), 0, "origin = 0.1\n");
  expect_error(both, "body[1].cavity.origin", "give either center or origin, not both");
  std::string neither = by_center;
  neither.erase(neither.find("center = "), neither.find('\n', neither.find("center = ")) - neither.find("center = ") + 1);
  expect_error(neither, "body[1].cavity.center", "missing (or give origin");
}
