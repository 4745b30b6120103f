// Stability maps (chain-rom sweep): keys, boundaries against closed forms, tables read once.
#include "rom_test_util.hpp"
#include "sweep.hpp"

#include <gtest/gtest.h>

#include <fstream>

using namespace rc::rom;
using namespace rc::rom::test;

namespace {

Scene scene_of(const std::string& text) { return parse_scene_text(text, test_dir(), "test-scene"); }

SweepAxis axis(const Scene& s, const std::string& key, double from, double to, int steps) {
  return SweepAxis{parse_param_key(key, s), from, to, steps};
}

}  // namespace

// Heavy (Lagrange) top without fluid: stable iff C^2 w^2 > 4 A' a g (A' = A for one body, a = m c).
// The sweep's boundary (midpoint between the last unstable and the first stable grid value) must lie
// within half a grid step of w* = sqrt(4 A' a g) / C on both sides of w = 0, and the margin on the
// unstable side must be the closed form sqrt(4 A' a g - C^2 w^2) / (2 A').
TEST(Sweep, HeavyTopSpinBoundaryMatchesClosedForm) {
  Body b; b.mass = 2; b.A = 0.05; b.C = 0.03; b.com = 0.1;
  const Scene s = scene_of(scene_text({b}, {}, 9.81));
  const double A = 0.05, a = 0.2, g = 9.81, C = 0.03;
  const double w_star = std::sqrt(4 * A * a * g) / C;  // 20.880 rad/s
  const int K = 801;
  const SweepAxis ax = axis(s, "body[1].spin", -40, 40, K);
  const double h = 80.0 / (K - 1);
  TableCache tables;
  const SweepResult r = run_sweep(s, tables, ax, std::nullopt, 2);
  ASSERT_EQ(r.points.size(), static_cast<std::size_t>(K));
  ASSERT_EQ(r.failed, 0);
  std::vector<double> boundaries;
  double worst_margin = 0;
  for (int i = 0; i < K; ++i) {
    const SweepPoint& p = r.points[i];
    EXPECT_DOUBLE_EQ(p.v1, ax.value(i));
    const double d = 4 * A * a * g - C * C * p.v1 * p.v1;
    if (std::abs(d) > 1e-9) {
      EXPECT_EQ(p.verdict.stable, d < 0) << "spin " << p.v1;
    }
    EXPECT_EQ(p.verdict.nonreal, p.verdict.stable ? 0 : 2);
    const double exact = d > 0 ? std::sqrt(d) / (2 * A) : 0.0;
    worst_margin = std::max(worst_margin, std::abs(p.verdict.margin - exact));
    if (i > 0 && p.verdict.stable != r.points[i - 1].verdict.stable)
      boundaries.push_back(0.5 * (p.v1 + r.points[i - 1].v1));
  }
  ASSERT_EQ(boundaries.size(), 2u);
  const double err = std::max(std::abs(boundaries[0] + w_star), std::abs(boundaries[1] - w_star));
  std::printf("  w* = %.6f rad/s; sweep boundaries %.4f, %.4f (grid step %.3f): error %.4f <= h/2; "
              "worst margin error %.2e rad/s\n", w_star, boundaries[0], boundaries[1], h, err, worst_margin);
  EXPECT_LE(err, h / 2 + 1e-12);
  EXPECT_LT(worst_margin, 1e-9);
}

// The same boundary through gravity: unstable iff g > C^2 w^2 / (4 A' a).
TEST(Sweep, HeavyTopGravityBoundaryMatchesClosedForm) {
  Body b; b.mass = 2; b.A = 0.05; b.C = 0.03; b.com = 0.1; b.spin = 20;
  const Scene s = scene_of(scene_text({b}, {}, 9.81));
  const double g_star = 0.03 * 0.03 * 400 / (4 * 0.05 * 0.2);  // 9.0 m/s^2
  const int K = 201;
  TableCache tables;
  const SweepResult r = run_sweep(s, tables, axis(s, "system.gravity", 0, 20, K), std::nullopt, 1);
  double boundary = -1;
  for (int i = 1; i < K; ++i)
    if (r.points[i].verdict.stable != r.points[i - 1].verdict.stable) {
      EXPECT_LT(boundary, 0) << "more than one boundary";
      boundary = 0.5 * (r.points[i].v1 + r.points[i - 1].v1);
      EXPECT_TRUE(r.points[i - 1].verdict.stable);
    }
  std::printf("  g* = %.4f; sweep boundary %.4f (grid step 0.1)\n", g_star, boundary);
  EXPECT_LE(std::abs(boundary - g_star), 0.05 + 1e-12);
}

// Greenhill (massless shell, spheroidal cavity, no gravity): the verdict depends on the aspect c/a
// alone, which is the table's (not a sweep key). Swept over spin and density, prolate c/a = 2 is
// unstable everywhere and oblate c/a = 0.5 stable everywhere; every root scales with the spin, so
// margin / spin is constant.
TEST(Sweep, GreenhillVerdictIndependentOfSpinAndDensity) {
  for (double ratio : {2.0, 0.5}) {
    Body b; b.mass = 0; b.A = 0; b.C = 0; b.com = 0; b.spin = 20;
    b.table = spheroid_file(1.0, ratio); b.scale = 0.1; b.density = 1000; b.center = 0;
    const Scene s = scene_of(scene_text({b}, {}, 0.0));
    TableCache tables;
    const SweepResult r = run_sweep(s, tables, axis(s, "body[1].spin", 5, 50, 10),
                                    axis(s, "body[1].cavity.density", 500, 1500, 3), 2);
    ASSERT_EQ(r.points.size(), 30u);
    const double ref = r.points[0].verdict.margin / r.points[0].v1;
    double spread = 0;
    for (const SweepPoint& p : r.points) {
      ASSERT_TRUE(p.ok) << p.error;
      EXPECT_EQ(p.verdict.stable, ratio < 1) << "spin " << p.v1 << " density " << p.v2;
      if (ratio > 1) spread = std::max(spread, std::abs(p.verdict.margin / p.v1 - ref) / ref);
    }
    std::printf("  c/a = %.1f: margin/spin %.6e, relative spread %.2e\n", ratio, ref, spread);
    EXPECT_LT(spread, 1e-10);
  }
}

// 2D: K x K2 rows, first key outer; the CSV has a header and one line per point.
TEST(Sweep, TwoDimensionalSweepHasKTimesK2RowsInOrder) {
  Body b1; b1.mass = 3; b1.A = 0.2; b1.C = 0.15; b1.com = 0.12; b1.next = 0.3; b1.spin = 80;
  Body b2; b2.mass = 1.5; b2.A = 0.04; b2.C = 0.03; b2.com = 0.08; b2.spin = 120;
  const Scene s = scene_of(scene_text({b1, b2}, {{4.0, 0}}, 9.81));
  const SweepAxis a1 = axis(s, "body[2].spin", 0, 200, 7), a2 = axis(s, "joint[1].stiffness", 0, 10, 5);
  TableCache tables;
  const SweepResult r = run_sweep(s, tables, a1, a2, 2);
  ASSERT_EQ(r.points.size(), 35u);
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 5; ++j) {
      EXPECT_DOUBLE_EQ(r.points[i * 5 + j].v1, a1.value(i));
      EXPECT_DOUBLE_EQ(r.points[i * 5 + j].v2, a2.value(j));
    }
  const auto out = std::filesystem::path(RC_ROM_TEST_DIR) / "sweep2d.csv";
  write_sweep_csv(r, a1, a2, out);
  std::ifstream in(out);
  std::string line, header;
  std::getline(in, header);
  EXPECT_EQ(header, "body[2].spin,joint[1].stiffness,stable,margin,nonreal,gap");
  int rows = 0;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 35);
}

// Every point of a sweep gives the verdict that compute_spectrum gives for the scene with that
// value written into it (the fast eigenvalues-only path, real without friction, against the full one).
TEST(Sweep, VerdictAgreesWithFullSpectrum) {
  Body b1; b1.mass = 2; b1.A = 0.1; b1.C = 0.08; b1.com = 0.1; b1.next = 0.3; b1.spin = 50;
  b1.table = spheroid_file(1.0, 1.6); b1.scale = 0.05; b1.center = 0.12;
  Body b2; b2.mass = 1; b2.A = 0.03; b2.C = 0.02; b2.com = 0.06; b2.spin = 70;
  b2.table = spheroid_file(1.0, 0.7); b2.scale = 0.04; b2.center = 0.05;
  for (double friction : {0.0, 0.05}) {
    const Scene s = scene_of(scene_text({b1, b2}, {{3.0, friction}}, 9.81));
    const SweepAxis ax = axis(s, "body[1].spin", 0, 150, 31);
    TableCache tables;
    const SweepResult r = run_sweep(s, tables, ax, std::nullopt, 2);
    int stable = 0;
    for (const SweepPoint& p : r.points) {
      ASSERT_TRUE(p.ok) << p.error;
      Scene t = s;
      t.bodies[0].spin = p.v1;
      const Spectrum sp = compute_spectrum(build_model(t));
      EXPECT_EQ(p.verdict.stable, sp.stable) << "spin " << p.v1;
      EXPECT_EQ(p.verdict.nonreal, sp.nonreal) << "spin " << p.v1;
      EXPECT_NEAR(p.verdict.margin, sp.margin, 1e-8 * (1 + sp.margin)) << "spin " << p.v1;
      stable += p.verdict.stable;
    }
    std::printf("  friction %.2f: %d of 31 points stable\n", friction, stable);
  }
}

// system.spin_factor multiplies every body's spin: each point's verdict, non-real count and margin are those of
// `spectrum` on the scene with all spins scaled by hand; with a body's spin on the other axis it is refused.
TEST(Sweep, SpinFactorScalesEverySpin) {
  Body b1; b1.mass = 2; b1.A = 0.1; b1.C = 0.08; b1.com = 0.1; b1.next = 0.3; b1.spin = 50;
  b1.table = spheroid_file(1.0, 1.6); b1.scale = 0.05; b1.center = 0.12;
  Body b2; b2.mass = 1; b2.A = 0.03; b2.C = 0.02; b2.com = 0.06; b2.spin = 70;
  b2.table = spheroid_file(1.0, 0.7); b2.scale = 0.04; b2.center = 0.05;
  const Scene s = scene_of(scene_text({b1, b2}, {{3.0, 0.0}}, 9.81));
  const SweepAxis ax = axis(s, "system.spin_factor", 0, 3, 61);
  TableCache tables;
  const SweepResult r = run_sweep(s, tables, ax, std::nullopt, 2);
  int stable = 0;
  double worst = 0;
  for (const SweepPoint& p : r.points) {
    ASSERT_TRUE(p.ok) << p.error;
    Scene t = s;
    t.bodies[0].spin = 50 * p.v1;
    t.bodies[1].spin = 70 * p.v1;
    const Spectrum sp = compute_spectrum(build_model(t));
    EXPECT_EQ(p.verdict.stable, sp.stable) << "factor " << p.v1;
    EXPECT_EQ(p.verdict.nonreal, sp.nonreal) << "factor " << p.v1;
    worst = std::max(worst, std::abs(p.verdict.margin - sp.margin) / (1 + sp.margin));
    stable += p.verdict.stable;
  }
  std::printf("  %d of 61 factors stable, %ld tracked; margins against spectrum on the scaled scene: %.1e\n", stable,
              r.tracked, worst);
  EXPECT_LT(worst, 1e-8);
  EXPECT_GT(stable, 0);
  EXPECT_LT(stable, 61);
  const SweepAxis spin = axis(s, "body[2].spin", 10, 20, 2);
  EXPECT_THROW(run_sweep(s, tables, ax, spin, 1), SweepError);
  Scene copy = s;
  EXPECT_THROW(param_ref(copy, ax.key), SweepError);
}

// Tables are read once: after the first model is built the table file can disappear and the sweep
// (over a cavity value, which changes the fluid's scaling) still runs from the cache.
TEST(Sweep, ReadsEachTableOnce) {
  const auto file = test_dir() / "sweep_once.h5";
  write_table(spheroid_table(1.0, 0.6), file);
  Body b; b.mass = 2; b.A = 0.05; b.C = 0.08; b.com = 0.05; b.spin = 200;
  b.table = "sweep_once.h5"; b.scale = 0.04; b.center = 0.05;
  const Scene s = scene_of(scene_text({b, b}, {{1.0, 0}}, 9.81));  // both bodies name the table
  TableCache tables;
  (void)build_model(s, &tables);
  EXPECT_EQ(tables.size(), 1u);
  std::filesystem::remove(file);
  const SweepResult r = run_sweep(s, tables, axis(s, "body[2].cavity.density", 500, 1500, 5), std::nullopt, 2);
  EXPECT_EQ(r.failed, 0);
  EXPECT_EQ(tables.size(), 1u);
}

// Keys: the documented forms resolve to the scene's values; bad ones give one line naming the key.
TEST(Sweep, KeysResolveAndBadKeysNameThemselves) {
  Body b1; b1.spin = 10; b1.table = spheroid_file(1.0, 0.6);
  Body b2; b2.spin = 20;
  Scene s = scene_of(scene_text({b1, b2}, {{7.0, 0.5}}, 9.81, false, 0.25));
  EXPECT_EQ(param_ref(s, parse_param_key("body[2].spin", s)), 20);
  EXPECT_EQ(param_ref(s, parse_param_key("joint[1].stiffness", s)), 7);
  EXPECT_EQ(param_ref(s, parse_param_key("joint[1].friction", s)), 0.5);
  EXPECT_EQ(param_ref(s, parse_param_key("system.gravity", s)), 9.81);
  EXPECT_EQ(param_ref(s, parse_param_key("support.friction", s)), 0.25);
  EXPECT_EQ(param_ref(s, parse_param_key("body[1].cavity.density", s)), 1000);
  param_ref(s, parse_param_key("body[1].A", s)) = 0.7;
  EXPECT_EQ(s.bodies[0].A, 0.7);
  auto msg = [&](const std::string& key) {
    try {
      parse_param_key(key, s);
    } catch (const SweepError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(msg("body[3].spin").rfind("--param body[3].spin: body index 3 out of range 1..2", 0), 0u);
  EXPECT_EQ(msg("body[0].spin").rfind("--param body[0].spin: body index 0 out of range", 0), 0u);
  EXPECT_EQ(msg("joint[2].stiffness").rfind("--param joint[2].stiffness: joint index 2 out of range 1..1", 0), 0u);
  EXPECT_EQ(msg("body[1].colour").rfind("--param body[1].colour: unknown key", 0), 0u);
  EXPECT_EQ(msg("spin").rfind("--param spin: unknown key", 0), 0u);
  EXPECT_EQ(msg("body[1].cavity.table").rfind("--param body[1].cavity.table: a family of tables is swept as", 0), 0u);
  EXPECT_EQ(msg("body[1].cavity.modes").rfind("--param body[1].cavity.modes: not a sweepable number", 0), 0u);
  EXPECT_EQ(msg("body[1].cavity.table=c.h5").rfind("--param body[1].cavity.table=c.h5: needs exactly one", 0), 0u);
  EXPECT_EQ(msg("body[1].cavity.table=c%d.h5").rfind("--param body[1].cavity.table=c%d.h5: conversion at '%d'", 0), 0u);
  EXPECT_NE(msg("body[1].cavity.table=c%g_%g.h5").find("(has 2)"), std::string::npos);
  EXPECT_NE(msg("body[1].cavity.table=a,%g.h5").find("comma"), std::string::npos);
  EXPECT_EQ(msg("body[1].spin=%g").rfind("--param body[1].spin=%g: only body[k].cavity.table takes =PATTERN", 0), 0u);
  EXPECT_EQ(msg("body[1].cavity.table=c_100%%_%.1f.h5"), "no error");
  EXPECT_EQ(table_of(parse_param_key("body[1].cavity.table=c_100%%_%.1f.h5", s), 2.5).string(), "c_100%_2.5.h5");
  EXPECT_EQ(msg("system.kind").rfind("--param system.kind: not a sweepable number", 0), 0u);
  EXPECT_EQ(msg("body[2].cavity.density").rfind("--param body[2].cavity.density: body 2 has no cavity", 0), 0u);
  EXPECT_EQ(msg("body[2].next_joint").rfind("--param body[2].next_joint: next_joint of the last body", 0), 0u);
  for (const char* k : {"body[3].spin", "body[1].colour", "body[1].cavity.table"})
    EXPECT_EQ(msg(k).find('\n'), std::string::npos);
  const ParamKey mass = parse_param_key("body[1].mass", s);
  EXPECT_THROW(check_param_value(mass, -1, "--from"), SweepError);
  EXPECT_NO_THROW(check_param_value(mass, 0, "--from"));
  EXPECT_THROW(check_param_value(parse_param_key("body[1].cavity.density", s), 0, "--to"), SweepError);
}

// A family of tables: the spheroid's polar semi-axis c swept through the file name
// (body[1].cavity.table=<dir>/greenhill_c%.2f.h5). Greenhill (massless shell, no gravity): unstable
// iff a < c < 3a, whatever the spin. Every point must give that verdict and the verdict, margin and
// non-real count of compute_spectrum on a scene that names the member table directly.
TEST(Sweep, FamilyOfTablesFollowsGreenhillAcrossTheAspect) {
  const std::string pattern = (test_dir() / "greenhill_c%.2f.h5").string();
  const int K = 36;  // c = 0.45 .. 3.95 in steps of 0.1: no value on a boundary (c = 1, 3)
  for (int i = 0; i < K; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "greenhill_c%.2f.h5", 0.45 + 0.1 * i);
    write_table(spheroid_table(1.0, 0.45 + 0.1 * i), test_dir() / name);
  }
  Body b; b.mass = 0; b.A = 0; b.C = 0; b.com = 0; b.spin = 20;
  b.table = "greenhill_c0.45.h5"; b.scale = 0.1; b.density = 1000; b.center = 0;
  const Scene s = scene_of(scene_text({b}, {}, 0.0));
  const SweepAxis fam = axis(s, "body[1].cavity.table=" + pattern, 0.45, 3.95, K);
  TableCache tables;
  const SweepResult r = run_sweep(s, tables, fam, axis(s, "body[1].spin", 10, 40, 4), 2);
  ASSERT_EQ(r.points.size(), static_cast<std::size_t>(4 * K));
  EXPECT_EQ(tables.size(), static_cast<std::size_t>(K));  // the scene's own table is in the family
  int unstable = 0;
  double worst_margin = 0;
  for (const SweepPoint& p : r.points) {
    ASSERT_TRUE(p.ok) << p.error;
    const bool greenhill_unstable = p.v1 > 1 && p.v1 < 3;
    EXPECT_EQ(p.verdict.stable, !greenhill_unstable) << "c = " << p.v1 << ", spin " << p.v2;
    unstable += !p.verdict.stable;
    Scene t = s;
    t.bodies[0].spin = p.v2;
    char name[64];
    std::snprintf(name, sizeof name, "greenhill_c%.2f.h5", p.v1);
    t.bodies[0].cavity->table = test_dir() / name;
    const Spectrum sp = compute_spectrum(build_model(t));
    EXPECT_EQ(p.verdict.stable, sp.stable);
    EXPECT_EQ(p.verdict.nonreal, sp.nonreal);
    worst_margin = std::max(worst_margin, std::abs(p.verdict.margin - sp.margin) / (1 + sp.margin));
  }
  std::printf("  c/a 0.45..3.95 x spin 10..40: %d of %d points unstable (Greenhill: 20 values x 4 spins = 80); "
              "margin vs spectrum %.2e\n", unstable, 4 * K, worst_margin);
  EXPECT_EQ(unstable, 80);
  EXPECT_LT(worst_margin, 1e-9);

  // A member missing from the family: one line naming the key and the value, before any point.
  const SweepAxis beyond = axis(s, "body[1].cavity.table=" + pattern, 0.45, 4.45, 41);
  TableCache t2;
  try {
    run_sweep(s, t2, beyond, std::nullopt, 1);
    ADD_FAILURE() << "missing member accepted";
  } catch (const SweepError& e) {
    const std::string m = e.what();
    std::printf("  missing member: %s\n", m.c_str());
    EXPECT_NE(m.find("table of value 4.05"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos);
  }
}
