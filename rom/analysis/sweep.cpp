#include "sweep.hpp"

#include "general_system.hpp"

#include "atomic_file.hpp"

#include "root_tracking.hpp"

#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace rc::rom {
namespace fs = std::filesystem;
namespace {

const char* kKeyList =
    "system.gravity, system.spin_factor (all spins times it), support.friction, body[k].{mass,A,C,com,next_joint,spin}, "
    "body[k].cavity.{density,scale,center,coverage}, joint[k].{stiffness,friction}, "
    "body[k].cavity.table=PATTERN (a family of tables)";

// A table pattern holds exactly one printf conversion of a double (%e, %f, %g with optional flags,
// width and precision; %% is a literal %), and nothing that would break the CSV header (the key,
// pattern included, is its column name). Returns the cause, or "" if the pattern is good.
std::string table_pattern_problem(const std::string& p) {
  if (p.empty()) return "empty pattern";
  if (p.find_first_of(",\"\n\r") != std::string::npos) return "the pattern may not contain a comma, quote or newline";
  int conversions = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i] != '%') continue;
    if (i + 1 < p.size() && p[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < p.size() && std::string("-+ #0").find(p[j]) != std::string::npos) ++j;
    while (j < p.size() && std::isdigit(static_cast<unsigned char>(p[j]))) ++j;
    if (j < p.size() && p[j] == '.') {
      ++j;
      while (j < p.size() && std::isdigit(static_cast<unsigned char>(p[j]))) ++j;
    }
    if (j >= p.size() || std::string("eEfFgG").find(p[j]) == std::string::npos)
      return "conversion at '" + p.substr(i, std::min<std::size_t>(j + 1, p.size()) - i) +
             "' is not one of %e, %f, %g (with optional flags, width, precision)";
    ++conversions;
    i = j;
  }
  if (conversions != 1)
    return "needs exactly one %e/%f/%g conversion of the swept value (has " + std::to_string(conversions) +
           "), e.g. cone_h%.2f.h5";
  return "";
}

[[noreturn]] void fail(const std::string& option, const std::string& key, const std::string& cause) {
  throw SweepError(option + " " + key + ": " + cause);
}

enum class Range { any, nonneg, pos, unit };  // unit: (0, 1]

Range range_of(const ParamKey& k) {
  using W = ParamKey::Where;
  if (k.where == W::cavity) {
    if (k.field == "center" || k.field == "table") return Range::any;
    if (k.field == "coverage") return Range::unit;
    return Range::pos;  // density, scale
  }
  if (k.where == W::body && (k.field == "com" || k.field == "next_joint" || k.field == "spin")) return Range::any;
  if (k.is_spin_factor()) return Range::any;
  return Range::nonneg;  // gravity, friction, mass, A, C, stiffness
}

std::string fmt(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

}  // namespace

namespace {

// The 0-based index of "what[s]" (1-based in the key), refused in one line when not a number or out of range.
int key_index(const std::string& s, std::size_t count, const std::string& what, const std::string& option,
              const std::string& key) {
  long v = 0;
  try {
    v = std::stol(s);
  } catch (...) {
    fail(option, key, what + " index " + s + " is not a number");
  }
  if (count == 0) fail(option, key, "the scene has no " + what + "s");
  if (v < 1 || v > static_cast<long>(count))
    fail(option, key, what + " index " + s + " out of range 1.." + std::to_string(count) + " (indices count from 1)");
  return static_cast<int>(v - 1);
}

// A field that is not a sweepable number: why, in one line.
[[noreturn]] void refuse_field(const std::string& f, const std::string& option, const std::string& key) {
  if (f == "kind" || f == "table" || f == "static_correction" || f == "modes")
    fail(option, key, "not a sweepable number (" + f + " is " +
                          (f == "modes" ? "an integer" : f == "static_correction" ? "a boolean" : "a string") +
                          "); keys: " + kKeyList);
  fail(option, key, "unknown key; numeric keys: " + std::string(kKeyList));
}

// body[k].cavity.FIELD (and body[k].cavity.table=PATTERN, a family of tables).
void parse_cavity_key(ParamKey& k, const std::string& key_text, const std::string& key, const std::string& body,
                      const Scene& scene, const std::string& option) {
  static const std::set<std::string> cav_num{"density", "scale", "center", "coverage", "table"};
  if (!cav_num.count(k.field)) refuse_field(k.field, option, key);
  k.index = key_index(body, scene.size(), "body", option, key);
  const auto& cav = scene.bodies[k.index].cavity;
  if (!cav) fail(option, key, "body " + std::to_string(k.index + 1) + " has no cavity");
  if (k.field == "coverage" && cav->modes)
    fail(option, key, "the cavity gives modes; coverage can only be swept when modes is absent");
  if (k.field != "table") return;
  const std::size_t eq = key_text.find('=');
  if (eq == std::string::npos)
    fail(option, key, "a family of tables is swept as " + key +
                          "=PATTERN, PATTERN a file name with one printf conversion of the swept value "
                          "(e.g. " + key + "=cone_h%.2f.h5)");
  k.table_pattern = key_text.substr(eq + 1);
  const std::string problem = table_pattern_problem(k.table_pattern);
  if (!problem.empty()) fail(option, key_text, problem);
}

}  // namespace

ParamKey parse_param_key(const std::string& key_text, const Scene& scene, const std::string& option) {
  using W = ParamKey::Where;
  // body[k].cavity.table=PATTERN: the key proper, then the family's file-name pattern.
  const std::size_t eq = key_text.find('=');
  const std::string key = key_text.substr(0, eq);
  static const std::regex re_sys(R"(^system\.([A-Za-z_]+)$)"), re_sup(R"(^support\.([A-Za-z_]+)$)"),
      re_body(R"(^body\[(-?[0-9]+)\]\.([A-Za-z_]+)$)"),
      re_cav(R"(^body\[(-?[0-9]+)\]\.cavity\.([A-Za-z_]+)$)"),
      re_joint(R"(^joint\[(-?[0-9]+)\]\.([A-Za-z_]+)$)");
  static const std::set<std::string> body_num{"mass", "A", "C", "com", "next_joint", "spin"};
  static const std::set<std::string> joint_num{"stiffness", "friction"};
  ParamKey k;
  k.text = key_text;
  std::smatch m;
  if (std::regex_match(key, m, re_sys)) {
    k.where = W::system;
    k.field = m[1];
    if (k.field == "spin_factor") {  // every body's spin times the value: the scene's own spins are kept in the key
      for (const BodySpec& b : scene.bodies) k.base_spins.push_back(b.spin);
    } else if (k.field != "gravity") {
      refuse_field(k.field, option, key);
    }
  } else if (std::regex_match(key, m, re_sup)) {
    k.where = W::support;
    k.field = m[1];
    if (k.field != "friction") refuse_field(k.field, option, key);
    if (scene.free_chain) fail(option, key, "a free chain has no support");
  } else if (std::regex_match(key, m, re_cav)) {
    k.where = W::cavity;
    k.field = m[2];
    parse_cavity_key(k, key_text, key, m[1], scene, option);
  } else if (std::regex_match(key, m, re_body)) {
    k.where = W::body;
    k.field = m[2];
    if (!body_num.count(k.field)) refuse_field(k.field, option, key);
    k.index = key_index(m[1], scene.size(), "body", option, key);
    if (k.field == "next_joint" && k.index + 1 == static_cast<int>(scene.size()))
      fail(option, key, "next_joint of the last body is not used");
  } else if (std::regex_match(key, m, re_joint)) {
    k.where = W::joint;
    k.field = m[2];
    if (!joint_num.count(k.field)) refuse_field(k.field, option, key);
    k.index = key_index(m[1], scene.joints.size(), "joint", option, key);
  } else {
    fail(option, key, std::string("unknown key; numeric keys: ") + kKeyList);
  }
  if (eq != std::string::npos && !k.is_table())
    fail(option, key_text, "only body[k].cavity.table takes =PATTERN");
  return k;
}

std::filesystem::path table_of(const ParamKey& k, double value) {
  char buf[4096];
  // The pattern was checked by table_pattern_problem: one double conversion, nothing else.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
  const int len = std::snprintf(buf, sizeof buf, k.table_pattern.c_str(), value);
#pragma GCC diagnostic pop
  if (len < 0 || len >= static_cast<int>(sizeof buf)) throw SweepError(k.text + ": file name too long");
  return fs::path(buf);
}

void set_param(Scene& s, const ParamKey& k, double value) {
  if (k.is_table()) s.bodies[k.index].cavity->table = table_of(k, value);
  else if (k.is_spin_factor())
    for (std::size_t b = 0; b < s.bodies.size(); ++b) s.bodies[b].spin = k.base_spins[b] * value;
  else param_ref(s, k) = value;
}

double& param_ref(Scene& s, const ParamKey& k) {
  using W = ParamKey::Where;
  if (k.is_table()) throw SweepError(k.text + ": a table key has no numeric value in the scene");
  if (k.is_spin_factor()) throw SweepError(k.text + ": a factor on every spin, not one value in the scene");
  switch (k.where) {
    case W::system: return s.gravity;
    case W::support: return s.support_friction;
    case W::joint: return k.field == "stiffness" ? s.joints[k.index].stiffness : s.joints[k.index].friction;
    case W::cavity: {
      CavitySpec& c = *s.bodies[k.index].cavity;
      if (k.field == "density") return c.density;
      if (k.field == "scale") return c.scale;
      if (k.field == "center") {
        if (c.origin) throw SweepError(k.text + ": this cavity is placed by origin, not center");
        return c.center;
      }
      if (!c.coverage) c.coverage = 1.0;
      return *c.coverage;
    }
    case W::body: {
      BodySpec& b = s.bodies[k.index];
      if (k.field == "mass") return b.mass;
      if (k.field == "A") return b.A;
      if (k.field == "C") return b.C;
      if (k.field == "com") return b.com;
      if (k.field == "next_joint") return b.next_joint;
      return b.spin;
    }
  }
  throw SweepError(k.text + ": internal error");
}

void check_param_value(const ParamKey& k, double v, const std::string& option) {
  if (!std::isfinite(v)) fail(option, k.text, "value must be finite");
  switch (range_of(k)) {
    case Range::any: return;
    case Range::nonneg:
      if (v < 0) fail(option, k.text, "value " + fmt(v) + " out of range: must be >= 0");
      return;
    case Range::pos:
      if (v <= 0) fail(option, k.text, "value " + fmt(v) + " out of range: must be > 0");
      return;
    case Range::unit:
      if (v <= 0 || v > 1) fail(option, k.text, "value " + fmt(v) + " out of range: must be in (0, 1]");
      return;
  }
}

namespace {

// Where a line of points gets its first roots from: the eigen-solver, or a point evaluated before.
struct Line {
  std::vector<long> points;  // indices into SweepResult::points, in walking order
  long start_from = -1;      // a point evaluated before whose roots start the line; -1: the eigen-solver
};

// The roots the next point on a line is tracked from: the last point's, and the one before for a linear
// prediction (empty once the order of the roots changed, i.e. after the eigen-solver).
struct LineState {
  Eigen::VectorXcd last, before;
  double radius = 0;
};

// The lines of the sweep (run_sweep's comment): `first` is walked alone before the others, in parallel.
void plan_lines(long n1, long n2, int threads, bool track, Line& first, std::vector<Line>& rest) {
  const long total = n1 * n2;
  if (!track) {
    for (long p = 0; p < total; ++p) rest.push_back(Line{{p}, -1});
    return;
  }
  if (n2 > 1) {
    for (long i = 0; i < n1; ++i) first.points.push_back(i * n2);
    for (long i = 0; i < n1; ++i) {
      Line row{{}, i * n2};
      for (long j = 1; j < n2; ++j) row.points.push_back(i * n2 + j);
      rest.push_back(std::move(row));
    }
    return;
  }
  const long stretch = (total + threads - 1) / threads;
  for (long p0 = 0; p0 < total; p0 += stretch) {
    Line l;
    for (long p = p0; p < std::min(total, p0 + stretch); ++p) l.points.push_back(p);
    rest.push_back(std::move(l));
  }
}

// One point: the model, its roots (tracked from the line's state when it has one, else the eigen-solver) and its
// verdict. Updates the line's state; a failure to build or solve is recorded in the point.
void evaluate_point(const Scene& s, TableCache& tables, bool track, SweepPoint& pt, LineState& st,
                    std::string& fallback_why) {
  try {
    if (needs_general_chain(s, tables)) {  // the chain without axial symmetry: its own roots, no tracking
      pt.verdict = general_spectrum(build_general_chain(s, &tables)).verdict;
      pt.ok = true;
      st = LineState{};
      return;
    }
    const ChainModel m = build_model(s, &tables);
    Eigen::VectorXcd roots;
    if (track && st.last.size() > 0) {
      const Eigen::VectorXcd start =
          st.before.size() == st.last.size() ? Eigen::VectorXcd(2.0 * st.last - st.before) : st.last;
      TrackedRoots t = track_roots(m, start, st.radius);
      if (t.ok) {
        roots = std::move(t.sigma);
        pt.tracked = true;
      } else if (fallback_why.empty()) {
        fallback_why = t.why;
      }
    }
    if (!pt.tracked) roots = verdict_roots(m);
    pt.verdict = verdict_from_roots(m, roots);
    if (pt.verdict.stable && !m.dissipative()) {
      const KreinGap g = krein_gap(m, roots, pt.verdict.tolerance);
      if (g.defined) pt.gap = g.gap;
    }
    pt.ok = true;
    st.before = pt.tracked ? std::move(st.last) : Eigen::VectorXcd();
    st.last = std::move(roots);
    st.radius = verdict_radius(pt.verdict);
  } catch (const std::exception& e) {
    pt.error = e.what();
    st = LineState{};
  }
}

}  // namespace

namespace {

// Every table must be in the cache before threads share it (get() then only reads): the scene's own, then every
// member of a swept family.
void load_tables(const Scene& base, TableCache& tables, const SweepAxis& a1, const std::optional<SweepAxis>& a2) {
  if (needs_general_chain(base, tables)) (void)build_general_chain(base, &tables);
  else (void)build_model(base, &tables);
  for (const SweepAxis* ax : {&a1, a2 ? &*a2 : nullptr}) {
    if (!ax || !ax->key.is_table()) continue;
    for (int i = 0; i < ax->steps; ++i) {
      const fs::path file = table_of(ax->key, ax->value(i));
      try {
        (void)tables.get(file);
      } catch (const std::exception& e) {
        throw SweepError(ax->key.text + ": table of value " + fmt(ax->value(i)) + ": " + e.what());
      }
    }
  }
}

// The sweep's progress from any thread, at most once a second (and not for the last point).
class ThrottledProgress {
 public:
  ThrottledProgress(const SweepProgress& progress, std::chrono::steady_clock::time_point t0)
      : progress_(progress), t0_(t0) {}
  void done(long d, long total) {
    if (!progress_) return;
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    if (el - last_.load() < 1.0 || d >= total) return;
    std::lock_guard<std::mutex> lock(mutex_);
    if (el - last_.load() < 1.0) return;
    last_.store(el);
    progress_(d, total, el);
  }

 private:
  const SweepProgress& progress_;
  std::chrono::steady_clock::time_point t0_;
  std::atomic<double> last_{0};
  std::mutex mutex_;
};

}  // namespace

namespace {

// A body's spin and system.spin_factor both scale the spins: they cannot be the two axes of one map.
void check_axes(const SweepAxis& a1, const std::optional<SweepAxis>& a2) {
  const auto body_spin = [](const ParamKey& k) { return k.where == ParamKey::Where::body && k.field == "spin"; };
  if (a2 && ((a1.key.is_spin_factor() && body_spin(a2->key)) || (body_spin(a1.key) && a2->key.is_spin_factor())))
    throw SweepError("--param2 " + a2->key.text + ": a body's spin and system.spin_factor cannot be swept together");
}

// Walks the map's lines of points, each on its private copy of the scene, the first line before the others (the
// rows start from its end states), the rest shared out to `threads` workers.
class SweepWalk {
 public:
  SweepWalk(const Scene& base, TableCache& tables, const SweepAxis& a1, const std::optional<SweepAxis>& a2, bool track,
            SweepResult& r, ThrottledProgress& report)
      : base_(base), tables_(tables), a1_(a1), a2_(a2), n2_(a2 ? a2->steps : 1), track_(track), r_(r),
        report_(report), end_state_(r.points.size()) {}

  void run(int threads) {
    plan_lines(a1_.steps, n2_, threads, track_, first_, lines_);
    if (!first_.points.empty()) walk(first_);
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back([this] { work(); });
    work();
    for (auto& th : pool) th.join();
  }

 private:
  void work() {
    for (long l; (l = next_.fetch_add(1)) < static_cast<long>(lines_.size());) walk(lines_[l]);
  }
  void walk(const Line& line) {
    Scene s = base_;  // private copy: only the swept values change
    LineState st = line.start_from >= 0 ? end_state_[line.start_from] : LineState{};
    std::string why;
    const long total = static_cast<long>(r_.points.size());
    for (const long p : line.points) {
      SweepPoint& pt = r_.points[p];
      pt.v1 = a1_.value(static_cast<int>(p / n2_));
      set_param(s, a1_.key, pt.v1);
      if (a2_) {
        pt.v2 = a2_->value(static_cast<int>(p % n2_));
        set_param(s, a2_->key, pt.v2);
      }
      evaluate_point(s, tables_, track_, pt, st, why);
      if (&line == &first_) end_state_[p] = st;
      report_.done(++done_, total);
    }
    if (!why.empty()) {
      std::lock_guard<std::mutex> lock(fallback_mutex_);
      if (r_.first_fallback.empty()) r_.first_fallback = why;
    }
  }

  const Scene& base_;
  TableCache& tables_;
  const SweepAxis& a1_;
  const std::optional<SweepAxis>& a2_;
  const int n2_;
  const bool track_;
  SweepResult& r_;
  ThrottledProgress& report_;
  Line first_;
  std::vector<Line> lines_;
  // The roots the first line's points ended with: the rows start from them once the first line is done.
  std::vector<LineState> end_state_;
  std::atomic<long> next_{0}, done_{0};
  std::mutex fallback_mutex_;
};

}  // namespace

SweepResult run_sweep(const Scene& base, TableCache& tables, const SweepAxis& a1,
                      const std::optional<SweepAxis>& a2, int threads, const SweepProgress& progress, bool track) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  check_axes(a1, a2);
  const long total = static_cast<long>(a1.steps) * (a2 ? a2->steps : 1);
  SweepResult r;
  r.points.resize(total);
  if (threads <= 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<int>(std::min<long>(threads, total));
  r.threads = threads;
  // A family of tables changes the poles themselves from point to point: nothing to track.
  track = track && !a1.key.is_table() && !(a2 && a2->key.is_table());
  ThrottledProgress report(progress, t0);
  load_tables(base, tables, a1, a2);
  SweepWalk(base, tables, a1, a2, track, r, report).run(threads);
  for (const auto& pt : r.points) {
    r.failed += pt.ok ? 0 : 1;
    r.tracked += pt.tracked ? 1 : 0;
  }
  r.wall_seconds = std::chrono::duration<double>(clock::now() - t0).count();
  return r;
}

void write_sweep_csv(const SweepResult& r, const SweepAxis& a1, const std::optional<SweepAxis>& a2,
                     const fs::path& out) {
  write_text_atomically(out, [&](std::ostream& os) {
    os << a1.key.text << (a2 ? "," + a2->key.text : std::string()) << ",stable,margin,nonreal,gap\n";
    char buf[96];
    for (const SweepPoint& p : r.points) {
      os << fmt(p.v1);
      if (a2) os << "," << fmt(p.v2);
      if (p.ok) {
        std::snprintf(buf, sizeof buf, ",%d,%.9e,%d,%.9e\n", p.verdict.stable ? 1 : 0, p.verdict.margin,
                      p.verdict.nonreal, p.gap);
        os << buf;
      } else {
        os << ",nan,nan,nan,nan\n";
      }
    }
  });
}

}  // namespace rc::rom
