#include "sweep.hpp"

#include <atomic>
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
    "system.gravity, support.friction, body[k].{mass,A,C,com,next_joint,spin}, "
    "body[k].cavity.{density,scale,center,coverage}, joint[k].{stiffness,friction}";

[[noreturn]] void fail(const std::string& option, const std::string& key, const std::string& cause) {
  throw SweepError(option + " " + key + ": " + cause);
}

enum class Range { any, nonneg, pos, unit };  // unit: (0, 1]

Range range_of(const ParamKey& k) {
  using W = ParamKey::Where;
  if (k.where == W::cavity) {
    if (k.field == "center") return Range::any;
    if (k.field == "coverage") return Range::unit;
    return Range::pos;  // density, scale
  }
  if (k.where == W::body && (k.field == "com" || k.field == "next_joint" || k.field == "spin")) return Range::any;
  return Range::nonneg;  // gravity, friction, mass, A, C, stiffness
}

std::string fmt(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

}  // namespace

ParamKey parse_param_key(const std::string& key, const Scene& scene, const std::string& option) {
  using W = ParamKey::Where;
  static const std::regex re_sys(R"(^system\.([A-Za-z_]+)$)"), re_sup(R"(^support\.([A-Za-z_]+)$)"),
      re_body(R"(^body\[(-?[0-9]+)\]\.([A-Za-z_]+)$)"),
      re_cav(R"(^body\[(-?[0-9]+)\]\.cavity\.([A-Za-z_]+)$)"),
      re_joint(R"(^joint\[(-?[0-9]+)\]\.([A-Za-z_]+)$)");
  const std::set<std::string> body_num{"mass", "A", "C", "com", "next_joint", "spin"};
  const std::set<std::string> cav_num{"density", "scale", "center", "coverage"};
  const std::set<std::string> joint_num{"stiffness", "friction"};
  ParamKey k;
  k.text = key;
  std::smatch m;
  auto index = [&](const std::string& s, std::size_t count, const std::string& what) {
    long v = 0;
    try {
      v = std::stol(s);
    } catch (...) {
      fail(option, key, what + " index " + s + " is not a number");
    }
    if (count == 0) fail(option, key, "the scene has no " + what + "s");
    if (v < 1 || v > static_cast<long>(count))
      fail(option, key, what + " index " + s + " out of range 1.." + std::to_string(count) +
                            " (indices count from 1)");
    return static_cast<int>(v - 1);
  };
  auto not_numeric = [&](const std::string& f) {
    if (f == "kind" || f == "table" || f == "static_correction" || f == "modes")
      fail(option, key, "not a sweepable number (" + f + " is " +
                            (f == "modes" ? "an integer" : f == "static_correction" ? "a boolean" : "a string") +
                            "); numeric keys: " + kKeyList);
    fail(option, key, "unknown key; numeric keys: " + std::string(kKeyList));
  };
  if (std::regex_match(key, m, re_sys)) {
    k.where = W::system;
    k.field = m[1];
    if (k.field != "gravity") not_numeric(k.field);
  } else if (std::regex_match(key, m, re_sup)) {
    k.where = W::support;
    k.field = m[1];
    if (k.field != "friction") not_numeric(k.field);
    if (scene.free_chain) fail(option, key, "a free chain has no support");
  } else if (std::regex_match(key, m, re_cav)) {
    k.where = W::cavity;
    k.field = m[2];
    if (!cav_num.count(k.field)) not_numeric(k.field);
    k.index = index(m[1], scene.size(), "body");
    const auto& cav = scene.bodies[k.index].cavity;
    if (!cav) fail(option, key, "body " + std::to_string(k.index + 1) + " has no cavity");
    if (k.field == "coverage" && cav->modes)
      fail(option, key, "the cavity gives modes; coverage can only be swept when modes is absent");
  } else if (std::regex_match(key, m, re_body)) {
    k.where = W::body;
    k.field = m[2];
    if (!body_num.count(k.field)) not_numeric(k.field);
    k.index = index(m[1], scene.size(), "body");
    if (k.field == "next_joint" && k.index + 1 == static_cast<int>(scene.size()))
      fail(option, key, "next_joint of the last body is not used");
  } else if (std::regex_match(key, m, re_joint)) {
    k.where = W::joint;
    k.field = m[2];
    if (!joint_num.count(k.field)) not_numeric(k.field);
    k.index = index(m[1], scene.joints.size(), "joint");
  } else {
    fail(option, key, std::string("unknown key; numeric keys: ") + kKeyList);
  }
  return k;
}

double& param_ref(Scene& s, const ParamKey& k) {
  using W = ParamKey::Where;
  switch (k.where) {
    case W::system: return s.gravity;
    case W::support: return s.support_friction;
    case W::joint: return k.field == "stiffness" ? s.joints[k.index].stiffness : s.joints[k.index].friction;
    case W::cavity: {
      CavitySpec& c = *s.bodies[k.index].cavity;
      if (k.field == "density") return c.density;
      if (k.field == "scale") return c.scale;
      if (k.field == "center") return c.center;
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

SweepResult run_sweep(const Scene& base, TableCache& tables, const SweepAxis& a1,
                      const std::optional<SweepAxis>& a2, int threads, const SweepProgress& progress) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const int n2 = a2 ? a2->steps : 1;
  const long total = static_cast<long>(a1.steps) * n2;
  SweepResult r;
  r.points.resize(total);
  if (threads <= 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<int>(std::min<long>(threads, total));
  r.threads = threads;
  std::atomic<long> next{0}, done{0};
  std::mutex progress_mutex;
  std::atomic<double> last_report{0};

  auto worker = [&]() {
    Scene s = base;  // private copy: only the swept values change
    double& x1 = param_ref(s, a1.key);
    double* x2 = a2 ? &param_ref(s, a2->key) : nullptr;
    for (long p; (p = next.fetch_add(1)) < total;) {
      SweepPoint& pt = r.points[p];
      pt.v1 = a1.value(static_cast<int>(p / n2));
      x1 = pt.v1;
      if (x2) {
        pt.v2 = a2->value(static_cast<int>(p % n2));
        *x2 = pt.v2;
      }
      try {
        pt.verdict = compute_verdict(build_model(s, &tables));
        pt.ok = true;
      } catch (const std::exception& e) {
        pt.error = e.what();
      }
      const long d = ++done;
      if (progress) {
        const double el = std::chrono::duration<double>(clock::now() - t0).count();
        if (el - last_report.load() >= 1.0 && d < total) {
          std::lock_guard<std::mutex> lock(progress_mutex);
          if (el - last_report.load() >= 1.0) {
            last_report.store(el);
            progress(d, total, el);
          }
        }
      }
    }
  };
  // Every table must be in the cache before threads share it (get() then only reads).
  (void)build_model(base, &tables);
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  for (const auto& pt : r.points) r.failed += pt.ok ? 0 : 1;
  r.wall_seconds = std::chrono::duration<double>(clock::now() - t0).count();
  return r;
}

void write_sweep_csv(const SweepResult& r, const SweepAxis& a1, const std::optional<SweepAxis>& a2,
                     const fs::path& out) {
  if (out.has_parent_path() && !fs::is_directory(out.parent_path()))
    throw std::runtime_error(out.string() + ": the output folder does not exist");
  fs::path tmp = out;
  tmp += ".tmp-" + std::to_string(::getpid());
  try {
    {
      std::ofstream os(tmp);
      if (!os) throw std::runtime_error(tmp.string() + ": cannot create");
      os << a1.key.text << (a2 ? "," + a2->key.text : std::string()) << ",stable,margin,nonreal\n";
      char buf[64];
      for (const SweepPoint& p : r.points) {
        os << fmt(p.v1);
        if (a2) os << "," << fmt(p.v2);
        if (p.ok) {
          std::snprintf(buf, sizeof buf, ",%d,%.9e,%d\n", p.verdict.stable ? 1 : 0, p.verdict.margin,
                        p.verdict.nonreal);
          os << buf;
        } else {
          os << ",nan,nan,nan\n";
        }
      }
      os.flush();
      if (!os) throw std::runtime_error(tmp.string() + ": write failed");
    }
    fs::rename(tmp, out);
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
}

}  // namespace rc::rom
