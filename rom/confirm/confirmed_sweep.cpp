#include "confirmed_sweep.hpp"

#include "atomic_file.hpp"

#include "chain_model.hpp"
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
  p.growth = -std::numeric_limits<double>::infinity();
  for (const FollowedRoot& r : p.roots) {
    if (!r.converged) { ++p.unconfirmed; continue; }
    p.growth = std::max(p.growth, -r.sigma.imag());
    if (-r.sigma.imag() > sp.noise) ++p.growing;
  }
  p.stable = p.growing == 0;
  p.ok = std::isfinite(p.growth);
  if (!p.ok) p.error = "no root confirmed";
  p.solves = tanks.solves() - solves_before;
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}
}  // namespace

bool moves_viscous_ekman(const Scene& scene, const ParamKey& key) {
  using W = ParamKey::Where;
  if (key.is_spin_factor())
    return std::any_of(scene.bodies.begin(), scene.bodies.end(), viscous_cavity);
  if (key.where == W::body && key.field == "spin") return viscous_cavity(scene.bodies[key.index]);
  if (key.where == W::cavity && key.field == "scale") return viscous_cavity(scene.bodies[key.index]);
  return false;
}

std::vector<ConfirmedSweepPoint> run_confirmed_sweep(const Scene& base, const SweepAxis& axis, const std::string& binary,
                                                     double tolerance, std::ostream& log) {
  TableCache tables;
  ConfirmSettings settings;
  settings.tolerance = tolerance;
  std::vector<ConfirmedSweepPoint> points;
  const bool moves = moves_viscous_ekman(base, axis.key);
  const std::vector<double> mesh_ekman = moves ? sweep_mesh_ekman(base, axis) : std::vector<double>{};
  log << "chain-rom sweep: each point's roots by (22) with the fluid's own response (forced solves; docs/rom.md, "
      << (moves ? "\"Spin sweeps with viscous tanks\"): " + axis.key.text + " moves the Ekman numbers, so each point "
                  "is served at its own, on one mesh per tank with its wall layers made for the sweep's smallest Ek"
                : std::string("\"Confirmed roots\"): the tanks served once for every point"))
      << std::endl;
  // A key that leaves the Ekman numbers alone: one served process per tank for the whole sweep.
  const ScratchFolder scratch;
  std::optional<TankResponses> shared;
  if (!moves) shared = serve_tanks(base, build_model(base, &tables), binary, scratch.path, log, {}, &tables);
  for (int i = 0; i < axis.steps; ++i) {
    const double v = axis.value(i);
    Scene s = base;
    set_param(s, axis.key, v);
    for (std::size_t b = 0; b < s.bodies.size(); ++b)
      if (viscous_cavity(s.bodies[b]) && s.bodies[b].spin == 0)
        throw SweepError(axis.key.text + " = " + std::to_string(v) + ": body " + std::to_string(b + 1) +
                         " does not spin there, and its viscous tank has no Ekman number");
    ConfirmedSweepPoint p;
    try {
      const ChainModel m = build_model(at_table_ekman(s, tables), &tables);  // once a point
      if (shared) {
        p = evaluate(s, m, v, points, *shared, settings);
      } else {
        std::ostringstream quiet;  // the served meshes are said once, at the first point
        TankResponses own = serve_tanks(s, m, binary, scratch.path, points.empty() ? log : quiet, mesh_ekman, &tables);
        p = evaluate(s, m, v, points, own, settings);
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
  return points;
}

void log_sweep_point(std::ostream& log, const SweepAxis& axis, const ConfirmedSweepPoint& p, int index,
                     const std::string& work) {
  log << std::setprecision(6) << "  " << axis.key.text << " = " << p.value << ": ";
  if (!p.ok)
    log << "not evaluated: " << p.error;
  else
    log << p.roots.size() << " roots" << (p.unconfirmed ? " (" + std::to_string(p.unconfirmed) + " NOT confirmed)" : "")
        << ", largest growth " << p.growth << " 1/s" << (p.stable ? " (stable)" : " (unstable)") << ", " << work << ", "
        << std::setprecision(3) << p.seconds << " s";
  log << " [" << index + 1 << "/" << axis.steps << "]" << std::endl;
}

void write_confirmed_sweep(const std::vector<ConfirmedSweepPoint>& points, const SweepAxis& axis,
                           const std::filesystem::path& out) {
  // Each file under a temporary name, then renamed: never a half-written CSV.
  const auto write = [](const std::filesystem::path& file, const std::string& text) {
    write_text_atomically(file, [&](std::ostream& os) { os << text; });
  };
  std::ostringstream main, roots;
  main << std::setprecision(17) << axis.key.text << ",stable,margin,nonreal\n";
  roots << std::setprecision(17) << axis.key.text << ",owner,sigma_re,sigma_im,confirmed\n";
  for (const ConfirmedSweepPoint& p : points) {
    if (!p.ok) {
      main << p.value << ",nan,nan,nan\n";
      continue;
    }
    main << p.value << "," << (p.stable ? 1 : 0) << "," << p.growth << "," << p.roots.size() << "\n";
    for (const FollowedRoot& r : p.roots)
      roots << p.value << "," << r.owner << "," << r.sigma.real() << "," << r.sigma.imag() << "," << (r.converged ? 1 : 0)
            << "\n";
  }
  write(out, main.str());
  std::filesystem::path rpath = out;
  rpath.replace_extension(".roots.csv");
  write(rpath, roots.str());
}

}  // namespace rc::rom
