#include "confirmed_sweep.hpp"

#include "atomic_file.hpp"

#include "chain_model.hpp"
#include "mesh_study.hpp"
#include "root_confirmation.hpp"
#include "spectrum.hpp"
#include "tank_responses.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>

namespace rc::rom {
namespace {
using cd = std::complex<double>;

bool viscous_cavity(const BodySpec& b) { return b.cavity && b.cavity->viscosity; }

// The scene with each viscous tank's viscosity set so that its table's Ek holds at this point's spin and scale:
// the table's modes scaled to this point, which give the starting roots (the fluid there is the served one).
Scene at_table_ekman(Scene s, TableCache& tables) {
  for (BodySpec& b : s.bodies)
    if (viscous_cavity(b) && b.spin != 0)
      b.cavity->viscosity = tables.get(b.cavity->table).ekman * std::abs(b.spin) * b.cavity->scale * b.cavity->scale;
  return s;
}

bool near_any(cd z, const std::vector<FollowedRoot>& roots, double rel) {
  for (const FollowedRoot& r : roots)
    if (std::abs(r.sigma - z) <= rel * std::abs(z)) return true;
  return false;
}

// The starts of a point: first the table's body and growing roots at this point (its modes scaled to this spin:
// near the true roots, since only the Ekman number differs), then the roots followed from the point before,
// extrapolated linearly from the two points before, which confirm_point tries only where no root confirmed from
// the table's is near (a root the table's spectrum does not show as a body or growing root).
std::vector<FollowedRoot> table_starts(const Spectrum& sp) {
  std::vector<FollowedRoot> starts;
  for (const Root& r : sp.roots) {
    if (std::abs(r.sigma) <= sp.tolerance) continue;
    if (r.owner.rfind("body", 0) == 0 || -r.sigma.imag() > sp.noise) starts.push_back({r.owner, r.sigma, false});
  }
  return starts;
}

std::vector<FollowedRoot> followed_starts(const std::vector<ConfirmedSweepPoint>& done) {
  std::vector<FollowedRoot> starts;
  if (done.empty() || !done.back().ok) return starts;
  const ConfirmedSweepPoint& last = done.back();
  const ConfirmedSweepPoint* before = done.size() > 1 && done[done.size() - 2].ok ? &done[done.size() - 2] : nullptr;
  for (const FollowedRoot& r : last.roots) {
    if (!r.converged) continue;
    FollowedRoot s = r;
    // The same root at the point before: the nearest confirmed one, if it is nearer than any other root now.
    if (before) {
      const FollowedRoot* prev = nullptr;
      for (const FollowedRoot& q : before->roots)
        if (q.converged && (!prev || std::abs(q.sigma - r.sigma) < std::abs(prev->sigma - r.sigma))) prev = &q;
      if (prev) s.sigma = 2.0 * r.sigma - prev->sigma;
    }
    starts.push_back(s);
  }
  return starts;
}

// Per body: the smallest Ek of its viscous tank over the sweep (0 for the others): the one mesh of every point.
std::vector<double> sweep_mesh_ekman(const Scene& base, const SweepAxis& axis) {
  std::vector<double> least(base.bodies.size(), 0.0);
  for (int i = 0; i < axis.steps; ++i) {
    Scene s = base;
    set_param(s, axis.key, axis.value(i));
    for (std::size_t b = 0; b < s.bodies.size(); ++b) {
      const BodySpec& body = s.bodies[b];
      if (!viscous_cavity(body) || body.spin == 0) continue;
      const double ek = *body.cavity->viscosity / (std::abs(body.spin) * body.cavity->scale * body.cavity->scale);
      least[b] = least[b] == 0 ? ek : std::min(least[b], ek);
    }
  }
  return least;
}

// The point's verdict from its confirmed roots: the largest growth, how many grow, how many are not confirmed; with a
// mesh study, the error of the largest growth rate.
void judge(ConfirmedSweepPoint& p) {
  p.growth = -std::numeric_limits<double>::infinity();
  p.growing = p.unconfirmed = 0;
  p.growth_error = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t j = 0; j < p.roots.size(); ++j) {
    const FollowedRoot& r = p.roots[j];
    if (!r.converged) { ++p.unconfirmed; continue; }
    if (-r.sigma.imag() > p.growth) {
      p.growth = -r.sigma.imag();
      if (p.mesh_measured()) p.growth_error = p.errors[j].error;
    }
    if (-r.sigma.imag() > p.noise) ++p.growing;
  }
  p.stable = p.growing == 0;
  p.ok = std::isfinite(p.growth);
  if (!p.ok) p.error = "no root confirmed";
}

// The point's confirmed roots as a mesh study's level 0 (NaN where a root was not confirmed: no level follows it).
std::vector<cd> level0_roots(const ConfirmedSweepPoint& p) {
  std::vector<cd> out;
  for (const FollowedRoot& r : p.roots)
    out.push_back(r.converged ? r.sigma : cd(std::numeric_limits<double>::quiet_NaN(), 0.0));
  return out;
}

// The mesh study's levels of the point's roots, levels[l][j]: each root's error, and the roots and the verdict on
// the finest level where each converged.
void take_study(ConfirmedSweepPoint& p, const std::vector<std::vector<cd>>& levels, const MeshStudy& study) {
  p.errors = level_errors(levels, study, p.noise);
  for (std::size_t j = 0; j < p.roots.size(); ++j)
    if (p.roots[j].converged) p.roots[j].sigma = p.errors[j].sigma;
  judge(p);
}

// What the sweep does, its log's first line.
std::string sweep_heading(const SweepAxis& axis, bool moves, const MeshStudy& study) {
  return "chain-rom sweep: each point's roots by (22) with the fluid's own response (forced solves; docs/rom.md, " +
         (moves ? "\"Spin sweeps with viscous tanks\"): " + axis.key.text + " moves the Ekman numbers, so each point "
                  "is served at its own, on one mesh per tank with its wall layers made for the sweep's smallest Ek"
                : std::string("\"Confirmed roots\"): the tanks served once for every point")) +
         (study.refine > 0 ? "; then on " + std::to_string(study.refine) + " finer mesh level" +
                                 (study.refine == 1 ? "" : "s") + " for each growth rate's mesh error"
                           : std::string("; mesh error NOT MEASURED (--refine 0)"));
}

// The scene at the sweep's value `v`. Throws SweepError where a viscous tank does not spin (Ek undefined).
Scene scene_at(const Scene& base, const SweepAxis& axis, double v) {
  Scene s = base;
  set_param(s, axis.key, v);
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    if (viscous_cavity(s.bodies[b]) && s.bodies[b].spin == 0)
      throw SweepError(axis.key.text + " = " + std::to_string(v) + ": body " + std::to_string(b + 1) +
                       " does not spin there, and its viscous tank has no Ekman number");
  return s;
}

// A sweep whose points share served tanks (a key that leaves the Ekman numbers alone): the study level by level for
// the whole sweep, each level's tanks served once (the level before shut first) and every point's roots iterated on
// it from the level before's.
void study_shared_levels(const Scene& base, const SweepAxis& axis, std::vector<ConfirmedSweepPoint>& points,
                         const MeshStudy& study, const std::string& binary, const std::filesystem::path& scratch,
                         const ConfirmSettings& settings, TableCache& tables, std::ostream& log) {
  std::vector<std::vector<std::vector<cd>>> levels(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) levels[i].push_back(level0_roots(points[i]));
  std::string failure;
  for (int level = 1; level <= study.refine && failure.empty(); ++level) {
    log << level_title(level, study.by_order) << std::endl;
    try {
      TankResponses tanks = serve_tanks(base, build_model(base, &tables), binary, scratch, log, {}, &tables,
                                        level_mesh(study, level));
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (!points[i].ok) continue;
        const Scene s = scene_at(base, axis, points[i].value);
        const int before = tanks.solves();
        std::ostringstream quiet;  // the roots' lines: the points' own lines below say what came of them
        levels[i].push_back(iterate_roots(build_model(at_table_ekman(s, tables), &tables), tanks.responses,
                                          levels[i].back(), settings, quiet));
        points[i].solves += tanks.solves() - before;
      }
    } catch (const SceneError&) {
      throw;
    } catch (const std::exception& e) {
      failure = "mesh level " + std::to_string(level) + " could not be served: " + e.what();
      log << "  " << failure << std::endl;
    }
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].ok) continue;
    points[i].mesh_failure = failure;
    take_study(points[i], levels[i], study);
  }
}

// A point served at its own Ek: its roots on the study's finer levels (study_mesh: each level served for this point).
void study_point(const Scene& s, const ChainModel& m, ConfirmedSweepPoint& p, const MeshStudy& study,
                 const std::string& binary, const std::filesystem::path& scratch, const ConfirmSettings& settings,
                 std::ostream& log) {
  const MeshStudyResult r = study_mesh(s, m, level0_roots(p), {}, std::numeric_limits<double>::quiet_NaN(), study,
                                       binary, scratch, settings, p.noise, log);
  p.solves += r.solves;
  p.mesh_failure = r.failure;
  take_study(p, r.levels, study);
}

// The point's roots with `tanks` serving each viscous tank at the point's Ekman number; `m` is the point's model with
// the tables' own Ekman numbers (at_table_ekman), whose roots start the iterations.
ConfirmedSweepPoint evaluate(const Scene& s, const ChainModel& m, double value,
                             const std::vector<ConfirmedSweepPoint>& done, TankResponses& tanks,
                             const ConfirmSettings& settings) {
  const auto t0 = std::chrono::steady_clock::now();
  const int solves_before = tanks.solves();
  ConfirmedSweepPoint p;
  p.value = value;
  const Spectrum sp = compute_spectrum(m);
  for (const BodySpec& b : s.bodies)
    if (viscous_cavity(b)) p.ekman.push_back(*b.cavity->viscosity / (std::abs(b.spin) * b.cavity->scale * b.cavity->scale));
  const auto confirm = [&](const FollowedRoot& start) {
    const ConfirmedRoot c = confirm_root(m, tanks.responses, start.sigma, settings);
    if (c.converged && near_any(c.sigma, p.roots, 1e-8)) return;  // two starts, one root
    p.roots.push_back({start.owner, c.converged ? c.sigma : start.sigma, c.converged});
  };
  for (const FollowedRoot& start : table_starts(sp)) confirm(start);
  for (const FollowedRoot& start : followed_starts(done))
    if (!near_any(start.sigma, p.roots, 2e-2)) confirm(start);
  p.noise = sp.noise;
  judge(p);
  p.solves = tanks.solves() - solves_before;
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}
}  // namespace

bool ConfirmedSweepPoint::mesh_converged() const {
  if (!mesh_measured() || !mesh_failure.empty()) return false;
  for (std::size_t j = 0; j < roots.size(); ++j)
    if (roots[j].converged && !errors[j].converged) return false;
  return true;
}

bool ConfirmedSweepPoint::sign_settled() const {
  for (std::size_t j = 0; j < errors.size(); ++j)
    if (roots[j].converged && !errors[j].sign_settled) return false;
  return true;
}

bool moves_viscous_ekman(const Scene& scene, const ParamKey& key) {
  using W = ParamKey::Where;
  if (key.is_spin_factor())
    return std::any_of(scene.bodies.begin(), scene.bodies.end(), viscous_cavity);
  if (key.where == W::body && key.field == "spin") return viscous_cavity(scene.bodies[key.index]);
  if (key.where == W::cavity && key.field == "scale") return viscous_cavity(scene.bodies[key.index]);
  return false;
}

std::vector<ConfirmedSweepPoint> run_confirmed_sweep(const Scene& base, const SweepAxis& axis, const std::string& binary,
                                                     double tolerance, const MeshStudy& study, std::ostream& log) {
  TableCache tables;
  ConfirmSettings settings;
  settings.tolerance = tolerance;
  std::vector<ConfirmedSweepPoint> points;
  const bool moves = moves_viscous_ekman(base, axis.key);
  const std::vector<double> mesh_ekman = moves ? sweep_mesh_ekman(base, axis) : std::vector<double>{};
  MeshStudy point_study = study;  // each point's own study (a key that moves Ek): its levels made for the sweep's Ek
  point_study.mesh_ekman = mesh_ekman;
  log << sweep_heading(axis, moves, study) << std::endl;
  // A key that leaves the Ekman numbers alone: one served process per tank for the whole sweep.
  const ScratchFolder scratch;
  std::optional<TankResponses> shared;
  if (!moves)
    shared = serve_tanks(base, build_model(base, &tables), binary, scratch.path, log, {}, &tables, level_mesh(study, 0));
  for (int i = 0; i < axis.steps; ++i) {
    const double v = axis.value(i);
    const Scene s = scene_at(base, axis, v);
    ConfirmedSweepPoint p;
    try {
      const ChainModel m = build_model(at_table_ekman(s, tables), &tables);  // once a point
      if (shared) {
        p = evaluate(s, m, v, points, *shared, settings);
      } else {
        std::ostringstream quiet;  // the served meshes are said once, at the first point
        std::ostream& said = points.empty() ? log : quiet;
        {
          TankResponses own = serve_tanks(s, m, binary, scratch.path, said, mesh_ekman, &tables, level_mesh(study, 0));
          p = evaluate(s, m, v, points, own, settings);
        }  // its solvers shut before the finer levels are served
        if (study.refine > 0 && p.ok) study_point(s, m, p, point_study, binary, scratch.path, settings, said);
      }
    } catch (const SceneError& e) {
      throw;  // a table that cannot be served: the same at every point
    } catch (const std::exception& e) {
      p.value = v;
      p.error = e.what();
    }
    log_sweep_point(log, axis, p, i, std::to_string(p.solves) + " forced solves");
    points.push_back(p);
  }
  if (shared && study.refine > 0) {
    shared.reset();  // level 0's solvers shut: one level in memory at a time
    study_shared_levels(base, axis, points, study, binary, scratch.path, settings, tables, log);
    log << "with the mesh study:" << std::endl;
    for (std::size_t i = 0; i < points.size(); ++i)
      log_sweep_point(log, axis, points[i], static_cast<int>(i), std::to_string(points[i].solves) + " forced solves");
  }
  return points;
}

void log_sweep_point(std::ostream& log, const SweepAxis& axis, const ConfirmedSweepPoint& p, int index,
                     const std::string& work) {
  log << std::setprecision(6) << "  " << axis.key.text << " = " << p.value << ": ";
  if (!p.ok) {
    log << "not evaluated: " << p.error;
  } else {
    log << p.roots.size() << " roots" << (p.unconfirmed ? " (" + std::to_string(p.unconfirmed) + " NOT confirmed)" : "")
        << ", largest growth " << p.growth;
    if (p.mesh_measured())
      log << std::setprecision(2) << " ± " << p.growth_error << std::setprecision(6);
    log << " 1/s" << (p.stable ? " (stable)" : " (unstable)");
    if (p.mesh_measured())
      log << (p.mesh_converged() ? ", mesh converged" : ", NOT CONVERGED in the mesh")
          << (p.sign_settled() ? "" : " (sign not settled)");
    log << ", " << work << ", " << std::setprecision(3) << p.seconds << " s";
  }
  log << " [" << index + 1 << "/" << axis.steps << "]" << std::endl;
}

void write_confirmed_sweep(const std::vector<ConfirmedSweepPoint>& points, const SweepAxis& axis,
                           const std::filesystem::path& out) {
  // Each file under a temporary name, then renamed: never a half-written CSV.
  const auto write = [](const std::filesystem::path& file, const std::string& text) {
    write_text_atomically(file, [&](std::ostream& os) { os << text; });
  };
  std::ostringstream main, roots;
  main << std::setprecision(17) << axis.key.text << ",stable,margin,nonreal,margin_error,mesh_converged\n";
  roots << std::setprecision(17) << axis.key.text << ",owner,sigma_re,sigma_im,confirmed,growth_error,mesh_converged\n";
  // nan where no mesh study ran (--refine 0, or a chain without axial symmetry)
  const auto flag = [](bool measured, bool yes) { return measured ? std::string(yes ? "1" : "0") : std::string("nan"); };
  for (const ConfirmedSweepPoint& p : points) {
    if (!p.ok) {
      main << p.value << ",nan,nan,nan,nan,nan\n";
      continue;
    }
    main << p.value << "," << (p.stable ? 1 : 0) << "," << p.growth << "," << p.roots.size() << "," << p.growth_error
         << "," << flag(p.mesh_measured(), p.mesh_converged()) << "\n";
    for (std::size_t j = 0; j < p.roots.size(); ++j) {
      const FollowedRoot& r = p.roots[j];
      const bool measured = p.mesh_measured() && r.converged;
      roots << p.value << "," << r.owner << "," << r.sigma.real() << "," << r.sigma.imag() << "," << (r.converged ? 1 : 0)
            << "," << (measured ? p.errors[j].error : std::numeric_limits<double>::quiet_NaN()) << ","
            << flag(measured, measured && p.errors[j].converged) << "\n";
    }
  }
  write(out, main.str());
  std::filesystem::path rpath = out;
  rpath.replace_extension(".roots.csv");
  write(rpath, roots.str());
}

}  // namespace rc::rom
