// Scene parser (docs/physics.md §4). Every problem gives one SceneError naming the file and the key.
#include "scene.hpp"

#include <toml++/toml.h>

#include <array>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace rc::rom {
namespace {

struct Ctx {
  std::string name;
  [[noreturn]] void fail(const std::string& key, const std::string& cause) const {
    throw SceneError(name + ": " + key + ": " + cause);
  }
};

void check_keys(const Ctx& c, const toml::table& t, const std::string& where,
                const std::set<std::string>& allowed) {
  for (auto&& [k, v] : t) {
    std::string key(k.str());
    if (!allowed.count(key)) c.fail(where.empty() ? key : where + "." + key, "unknown key");
  }
}

const toml::table* sub_table(const Ctx& c, const toml::table& t, const std::string& key,
                             const std::string& where) {
  const toml::node* n = t.get(key);
  if (!n) return nullptr;
  if (!n->is_table()) c.fail(where, "must be a table");
  return n->as_table();
}

enum class Sign { any, nonneg, pos };

std::optional<double> get_number(const Ctx& c, const toml::table& t, const std::string& key,
                                 const std::string& where, Sign sign, bool required) {
  const toml::node* n = t.get(key);
  if (!n) {
    if (required) c.fail(where, "missing");
    return std::nullopt;
  }
  std::optional<double> v;
  if (n->is_floating_point()) v = n->as_floating_point()->get();
  else if (n->is_integer()) v = static_cast<double>(n->as_integer()->get());
  else c.fail(where, "must be a number");
  if (!std::isfinite(*v)) c.fail(where, "must be finite");
  if (sign == Sign::nonneg && *v < 0) c.fail(where, "must be >= 0 (got " + std::to_string(*v) + ")");
  if (sign == Sign::pos && *v <= 0) c.fail(where, "must be > 0 (got " + std::to_string(*v) + ")");
  return v;
}

// One element of a TOML array as a finite number (integers taken as numbers).
double finite_number(const Ctx& c, const toml::node& e, const std::string& where) {
  double x = 0;
  if (e.is_floating_point()) x = e.as_floating_point()->get();
  else if (e.is_integer()) x = static_cast<double>(e.as_integer()->get());
  else c.fail(where, "must hold numbers");
  if (!std::isfinite(x)) c.fail(where, "must be finite");
  return x;
}

// A vector of three finite numbers, e.g. a moment [x, y, z].
std::array<double, 3> get_vector3(const Ctx& c, const toml::table& t, const std::string& key, const std::string& where) {
  std::array<double, 3> v{0, 0, 0};
  const toml::node* node = t.get(key);
  if (!node) return v;
  const toml::array* arr = node->as_array();
  if (!arr || arr->size() != 3) c.fail(where, "must be an array of three numbers [x, y, z]");
  for (std::size_t j = 0; j < 3; ++j) v[j] = finite_number(c, (*arr)[j], where);
  return v;
}

// One finite number per body, e.g. the spins' initial change (zeros when absent).
std::vector<double> get_number_array(const Ctx& c, const toml::table& t, const std::string& key,
                                     const std::string& where, std::size_t n) {
  std::vector<double> out(n, 0.0);
  const toml::node* node = t.get(key);
  if (!node) return out;
  const toml::array* arr = node->as_array();
  if (!arr || arr->size() != n)
    c.fail(where, "must be an array of " + std::to_string(n) + " numbers, one per body");
  for (std::size_t k = 0; k < n; ++k) out[k] = finite_number(c, (*arr)[k], where);
  return out;
}

std::vector<std::complex<double>> get_complex_array(const Ctx& c, const toml::table& t,
                                                    const std::string& key,
                                                    const std::string& where, std::size_t n) {
  const toml::node* node = t.get(key);
  std::vector<std::complex<double>> out(n, 0.0);
  if (!node) return out;
  const toml::array* arr = node->as_array();
  if (!arr) c.fail(where, "must be an array of [re, im] pairs");
  if (arr->size() != n)
    c.fail(where, "has " + std::to_string(arr->size()) + " entries, the chain has " +
                      std::to_string(n) + " bodies");
  for (std::size_t k = 0; k < n; ++k) {
    const toml::array* p = (*arr)[k].as_array();
    std::string w = where + "[" + std::to_string(k + 1) + "]";
    if (!p || p->size() != 2) c.fail(w, "must be a pair [re, im]");
    out[k] = {finite_number(c, (*p)[0], w), finite_number(c, (*p)[1], w)};
  }
  return out;
}

CavitySpec parse_cavity(const Ctx& c, const toml::table& t, const std::string& where,
                        const std::filesystem::path& base) {
  check_keys(c, t, where, {"table", "companion", "density", "scale", "center", "origin", "modes", "coverage",
                           "static_correction", "viscosity", "reduction", "offset", "prune"});
  CavitySpec cav;
  const toml::node* tab = t.get("table");
  if (!tab) c.fail(where + ".table", "missing");
  if (!tab->is_string()) c.fail(where + ".table", "must be a string");
  std::filesystem::path p = tab->as_string()->get();
  cav.table = p.is_absolute() ? p : base / p;
  if (const toml::node* comp = t.get("companion")) {
    if (!comp->is_string()) c.fail(where + ".companion", "must be a string");
    const std::filesystem::path q = comp->as_string()->get();
    cav.companion = q.is_absolute() ? q : base / q;
  }
  cav.density = *get_number(c, t, "density", where + ".density", Sign::pos, true);
  cav.scale = *get_number(c, t, "scale", where + ".scale", Sign::pos, true);
  // Where the fluid sits: its centroid (center), or the table's own origin (origin), not both.
  const auto center = get_number(c, t, "center", where + ".center", Sign::any, false);
  cav.origin = get_number(c, t, "origin", where + ".origin", Sign::any, false);
  if (center && cav.origin) c.fail(where + ".origin", "give either center or origin, not both");
  if (!center && !cav.origin)
    c.fail(where + ".center", "missing (or give origin: O_k -> the table's z = 0, and the centroid follows from the table)");
  cav.center = center.value_or(0.0);
  if (const toml::node* o = t.get("offset")) {
    const toml::array* arr = o->as_array();
    if (!arr || arr->size() != 2) c.fail(where + ".offset", "must be an array of two numbers [x, y] (m)");
    cav.offset = std::array<double, 2>{finite_number(c, (*arr)[0], where + ".offset"),
                                       finite_number(c, (*arr)[1], where + ".offset")};
  }
  if (const toml::node* m = t.get("modes")) {
    if (!m->is_integer()) c.fail(where + ".modes", "must be an integer");
    auto v = m->as_integer()->get();
    if (v < 1) c.fail(where + ".modes", "must be >= 1");
    cav.modes = static_cast<int>(v);
  }
  cav.coverage = get_number(c, t, "coverage", where + ".coverage", Sign::pos, false);
  if (cav.coverage && *cav.coverage > 1) c.fail(where + ".coverage", "must be in (0, 1]");
  if (cav.modes && cav.coverage) c.fail(where + ".coverage", "give either modes or coverage, not both");
  if (const toml::node* s = t.get("static_correction")) {
    if (!s->is_boolean()) c.fail(where + ".static_correction", "must be true or false");
    cav.static_correction = s->as_boolean()->get();
  }
  if (const toml::node* s = t.get("prune")) {
    if (!s->is_boolean()) c.fail(where + ".prune", "must be true or false");
    cav.prune = s->as_boolean()->get();
  }
  cav.viscosity = get_number(c, t, "viscosity", where + ".viscosity", Sign::pos, false);
  if (const toml::node* r = t.get("reduction")) {
    const auto* v = r->as_string();
    if (!v || (v->get() != "modal" && v->get() != "galerkin" && v->get() != "bands"))
      c.fail(where + ".reduction", "must be \"modal\", \"galerkin\" or \"bands\"");
    cav.galerkin = v->get() == "galerkin";
    cav.bands = v->get() == "bands";
    if (cav.bands && (cav.modes || cav.coverage || cav.static_correction))
      c.fail(where + ".reduction", "\"bands\" keeps the whole coupling measure: give no modes, coverage or "
                                   "static_correction with it");
  }
  return cav;
}

}  // namespace

namespace {

// [system]: kind ("fixed" or "free") and gravity.
void parse_system(Ctx& c, const toml::table& root, Scene& s) {
  const toml::table* sys = sub_table(c, root, "system", "system");
  if (!sys) c.fail("system", "missing");
  check_keys(c, *sys, "system", {"kind", "gravity"});
  if (const toml::node* k = sys->get("kind")) {
    if (!k->is_string()) c.fail("system.kind", "must be \"fixed\" or \"free\"");
    std::string kind = k->as_string()->get();
    if (kind == "free") s.free_chain = true;
    else if (kind != "fixed") c.fail("system.kind", "must be \"fixed\" or \"free\" (got \"" + kind + "\")");
  } else {
    c.fail("system.kind", "missing");
  }
  s.gravity = get_number(c, *sys, "gravity", "system.gravity", Sign::nonneg, false).value_or(0.0);
}

// [body.moment]: the external moments of the nonlinear model.
MomentSpec parse_moment(Ctx& c, const toml::table& mt, const std::string& wm) {
  check_keys(c, mt, wm, {"axial", "space", "harmonic", "frequency"});
  MomentSpec m;
  m.axial = get_number(c, mt, "axial", wm + ".axial", Sign::any, false).value_or(0.0);
  m.space = get_vector3(c, mt, "space", wm + ".space");
  m.harmonic = get_vector3(c, mt, "harmonic", wm + ".harmonic");
  m.frequency = get_number(c, mt, "frequency", wm + ".frequency", Sign::nonneg, false).value_or(0.0);
  if (mt.get("harmonic") && !mt.get("frequency")) c.fail(wm + ".frequency", "missing: a harmonic moment needs it (Hz)");
  return m;
}

// [body.force]: an external force at a point of the body's axis.
ForceSpec parse_force(Ctx& c, const toml::table& ft, const std::string& wf) {
  check_keys(c, ft, wf, {"space", "harmonic", "frequency", "at"});
  ForceSpec f;
  f.space = get_vector3(c, ft, "space", wf + ".space");
  f.harmonic = get_vector3(c, ft, "harmonic", wf + ".harmonic");
  f.frequency = get_number(c, ft, "frequency", wf + ".frequency", Sign::nonneg, false).value_or(0.0);
  f.at = *get_number(c, ft, "at", wf + ".at", Sign::any, true);
  if (ft.get("harmonic") && !ft.get("frequency")) c.fail(wf + ".frequency", "missing: a harmonic force needs it (Hz)");
  return f;
}

// [field]: a uniform body-force field, m/s².
// A 3 × 3 matrix [[..], [..], [..]] (row-major), or zeros when absent.
std::array<double, 9> get_matrix3(const Ctx& c, const toml::table& t, const std::string& key, const std::string& where) {
  std::array<double, 9> m{};
  const toml::node* node = t.get(key);
  if (!node) return m;
  const toml::array* rows = node->as_array();
  if (!rows || rows->size() != 3) c.fail(where, "must be a 3 x 3 matrix [[xx, xy, xz], [yx, yy, yz], [zx, zy, zz]]");
  for (std::size_t i = 0; i < 3; ++i) {
    const toml::array* row = (*rows)[i].as_array();
    if (!row || row->size() != 3) c.fail(where, "must be a 3 x 3 matrix [[xx, xy, xz], [yx, yy, yz], [zx, zy, zz]]");
    for (std::size_t j = 0; j < 3; ++j) m[3 * i + j] = finite_number(c, (*row)[j], where);
  }
  return m;
}

// The gradient of a potential field is symmetric; a field with a curl would drive the liquid's vorticity, which the
// frozen liquid (Batyr's generalised Zhukovsky theorem) does not describe.
void check_symmetric(const Ctx& c, const std::array<double, 9>& g, const std::string& where) {
  double scale = 0;
  for (const double x : g) scale = std::max(scale, std::abs(x));
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(g[3 * i + j] - g[3 * j + i]) > 1e-12 * scale)
        c.fail(where, "is not symmetric: only a potential field's gradient is modelled (a field with a curl would "
                      "stir the liquid, which the frozen liquid of Batyr's generalised Zhukovsky theorem does not take)");
}

FieldSpec parse_field(Ctx& c, const toml::table& ft) {
  check_keys(c, ft, "field", {"space", "harmonic", "frequency", "gradient"});
  FieldSpec f;
  f.space = get_vector3(c, ft, "space", "field.space");
  f.harmonic = get_vector3(c, ft, "harmonic", "field.harmonic");
  f.frequency = get_number(c, ft, "frequency", "field.frequency", Sign::nonneg, false).value_or(0.0);
  f.gradient = get_matrix3(c, ft, "gradient", "field.gradient");
  check_symmetric(c, f.gradient, "field.gradient");
  if (ft.get("harmonic") && !ft.get("frequency")) c.fail("field.frequency", "missing: a harmonic field needs it (Hz)");
  return f;
}

// [body.aero]: a projectile's static and pitch-damping moments (linear aeroballistics).
AeroSpec parse_aero(Ctx& c, const toml::table& at, const std::string& wa) {
  check_keys(c, at, wa, {"static_moment", "pitch_damping", "magnus"});
  AeroSpec a;
  a.static_moment = get_number(c, at, "static_moment", wa + ".static_moment", Sign::any, false).value_or(0.0);
  a.pitch_damping = get_number(c, at, "pitch_damping", wa + ".pitch_damping", Sign::nonneg, false).value_or(0.0);
  a.magnus = get_number(c, at, "magnus", wa + ".magnus", Sign::any, false).value_or(0.0);
  return a;
}

// [body.cavity] (one tank) or [[body.cavity]] (several: the first in `cavity`, the others in `more_cavities`).
void parse_cavities(Ctx& c, const toml::table& bt, const std::string& w, const std::filesystem::path& base, BodySpec& b) {
  const toml::node* node = bt.get("cavity");
  if (!node) return;
  if (const toml::array* arr = node->as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const std::string wi = w + ".cavity[" + std::to_string(i + 1) + "]";
      const toml::table* ct = (*arr)[i].as_table();
      if (!ct) c.fail(wi, "must be a table");
      CavitySpec cav = parse_cavity(c, *ct, wi, base);
      if (i == 0) b.cavity = cav;
      else b.more_cavities.push_back(cav);
    }
    return;
  }
  if (!node->is_table()) c.fail(w + ".cavity", "must be a table ([body.cavity]) or an array of tables ([[body.cavity]])");
  b.cavity = parse_cavity(c, *node->as_table(), w + ".cavity", base);
}

// [[body]] k of n (0-based): its inertias, spin, cavity and moments.
BodySpec parse_body(Ctx& c, const toml::table& bt, std::size_t k, std::size_t n, const std::filesystem::path& base) {
  const std::string w = "body[" + std::to_string(k + 1) + "]";
  check_keys(c, bt, w, {"mass", "A", "B", "C", "Ixy", "Ixz", "Iyz", "com", "next_joint", "spin", "cavity", "moment",
                         "force", "aero"});
  BodySpec b;
  b.mass = *get_number(c, bt, "mass", w + ".mass", Sign::nonneg, true);
  b.A = *get_number(c, bt, "A", w + ".A", Sign::nonneg, true);
  b.B = get_number(c, bt, "B", w + ".B", Sign::nonneg, false);
  b.C = *get_number(c, bt, "C", w + ".C", Sign::nonneg, true);
  b.Ixy = get_number(c, bt, "Ixy", w + ".Ixy", Sign::any, false).value_or(0.0);
  b.Ixz = get_number(c, bt, "Ixz", w + ".Ixz", Sign::any, false).value_or(0.0);
  b.Iyz = get_number(c, bt, "Iyz", w + ".Iyz", Sign::any, false).value_or(0.0);
  b.com = *get_number(c, bt, "com", w + ".com", Sign::any, true);
  auto nj = get_number(c, bt, "next_joint", w + ".next_joint", Sign::any, k + 1 < n);
  b.next_joint = nj.value_or(0.0);
  b.spin = get_number(c, bt, "spin", w + ".spin", Sign::any, false).value_or(0.0);
  parse_cavities(c, bt, w, base, b);
  if (const toml::table* mt = sub_table(c, bt, "moment", w + ".moment")) b.moment = parse_moment(c, *mt, w + ".moment");
  if (const toml::table* ft = sub_table(c, bt, "force", w + ".force")) b.force = parse_force(c, *ft, w + ".force");
  if (const toml::table* at = sub_table(c, bt, "aero", w + ".aero")) b.aero = parse_aero(c, *at, w + ".aero");
  return b;
}

// [[joint]]: one fewer than the bodies.
void parse_joints(Ctx& c, const toml::table& root, std::size_t n, Scene& s) {
  if (const toml::node* joints = root.get("joint")) {
    const toml::array* jarr = joints->as_array();
    if (!jarr || !jarr->is_array_of_tables()) c.fail("joint", "must be an array of tables [[joint]]");
    for (std::size_t k = 0; k < jarr->size(); ++k) {
      const toml::table& jt = *(*jarr)[k].as_table();
      std::string w = "joint[" + std::to_string(k + 1) + "]";
      check_keys(c, jt, w, {"stiffness", "friction", "axial_friction"});
      JointSpec j;
      j.stiffness = get_number(c, jt, "stiffness", w + ".stiffness", Sign::nonneg, false).value_or(0.0);
      j.friction = get_number(c, jt, "friction", w + ".friction", Sign::nonneg, false).value_or(0.0);
      j.axial_friction = get_number(c, jt, "axial_friction", w + ".axial_friction", Sign::nonneg, false).value_or(0.0);
      s.joints.push_back(j);
    }
  }
  if (s.joints.size() != n - 1)
    c.fail("joint", "the chain has " + std::to_string(n) + " bodies and needs " +
                        std::to_string(n - 1) + " [[joint]] entries, got " +
                        std::to_string(s.joints.size()));
}

// [support]: the fixed chain's friction at O_1.
void parse_support(Ctx& c, const toml::table& root, Scene& s) {
  const toml::table* sup = sub_table(c, root, "support", "support");
  if (!sup) return;
  check_keys(c, *sup, "support", {"friction", "axial_friction"});
  s.support_friction = get_number(c, *sup, "friction", "support.friction", Sign::nonneg, false).value_or(0.0);
  s.support_axial_friction =
      get_number(c, *sup, "axial_friction", "support.axial_friction", Sign::nonneg, false).value_or(0.0);
  if (s.free_chain && s.support_friction != 0)
    c.fail("support.friction", "a free chain has no support (must be 0 or absent)");
  if (s.free_chain && s.support_axial_friction != 0)
    c.fail("support.axial_friction", "a free chain has no support (must be 0 or absent)");
}

// [initial]: tilts, rates, the spins' change and the fluid's state.
void parse_initial(Ctx& c, const toml::table& root, std::size_t n, Scene& s) {
  s.tilt.assign(n, 0.0);
  s.rate.assign(n, 0.0);
  s.axial_rate.assign(n, 0.0);
  const toml::table* ini = sub_table(c, root, "initial", "initial");
  if (!ini) return;
  check_keys(c, *ini, "initial", {"tilt", "rate", "fluid", "axial_rate"});
  s.tilt = get_complex_array(c, *ini, "tilt", "initial.tilt", n);
  s.rate = get_complex_array(c, *ini, "rate", "initial.rate", n);
  // The spins' change at t = 0 (Batyr (89): a uniform change of spin is a motion of the chain).
  s.axial_rate = get_number_array(c, *ini, "axial_rate", "initial.axial_rate", n);
  // The fluid's initial state, one pair per kept mode (its count is known once the tables are read: checked there).
  if (const toml::node* fl = ini->get("fluid")) {
    const toml::array* arr = fl->as_array();
    if (!arr) c.fail("initial.fluid", "must be an array of [re, im] pairs, one per kept fluid mode");
    s.fluid = get_complex_array(c, *ini, "fluid", "initial.fluid", arr->size());
  }
}

// [run]: the model, the time span and step, the linear model's method and tolerance.
void parse_run(Ctx& c, const toml::table& root, Scene& s) {
  const toml::table* run = sub_table(c, root, "run", "run");
  if (!run) return;
  check_keys(c, *run, "run", {"t_end", "output_step", "method", "tolerance", "model"});
  if (const toml::node* m = run->get("model")) {
    if (!m->is_string()) c.fail("run.model", "must be \"linear\" or \"nonlinear\"");
    s.run.model = m->as_string()->get();
    if (s.run.model != "linear" && s.run.model != "nonlinear")
      c.fail("run.model", "must be \"linear\" or \"nonlinear\" (got \"" + s.run.model + "\")");
    if (s.run.nonlinear() && run->get("method"))
      c.fail("run.method", "applies to the linear model only (the nonlinear one has its own integrator)");
  }
  s.run.present = true;
  s.run.t_end = *get_number(c, *run, "t_end", "run.t_end", Sign::pos, true);
  s.run.output_step = *get_number(c, *run, "output_step", "run.output_step", Sign::pos, true);
  if (s.run.output_step > s.run.t_end) c.fail("run.output_step", "must not exceed run.t_end");
  if (const toml::node* m = run->get("method")) {
    // The name is checked against the integrators' registry by the layer that has it (linear/integrator.hpp).
    if (!m->is_string()) c.fail("run.method", "must be a string naming the integrator (\"exact\", \"gauss\", \"rk45\")");
    s.run.method = m->as_string()->get();
  }
  s.run.tolerance = get_number(c, *run, "tolerance", "run.tolerance", Sign::pos, false).value_or(1e-10);
}

}  // namespace

Scene parse_scene_text(const std::string& text, const std::filesystem::path& base,
                       const std::string& name) {
  Ctx c{name};
  toml::table root;
  try {
    root = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << name << ": TOML syntax error at line " << e.source().begin.line << ": " << e.description();
    throw SceneError(os.str());
  }
  check_keys(c, root, "", {"system", "field", "body", "joint", "support", "initial", "run"});
  Scene s;
  s.file = name;
  parse_system(c, root, s);
  if (const toml::table* ft = sub_table(c, root, "field", "field")) s.field = parse_field(c, *ft);
  const toml::node* bodies = root.get("body");
  if (!bodies) c.fail("body", "missing: a chain needs at least one [[body]]");
  const toml::array* barr = bodies->as_array();
  if (!barr || !barr->is_array_of_tables() || barr->empty())
    c.fail("body", "must be an array of tables [[body]]");
  const std::size_t n = barr->size();
  for (std::size_t k = 0; k < n; ++k) s.bodies.push_back(parse_body(c, *(*barr)[k].as_table(), k, n, base));
  parse_joints(c, root, n, s);
  parse_support(c, root, s);
  parse_initial(c, root, n, s);
  parse_run(c, root, s);
  return s;
}

Scene parse_scene(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw SceneError(file.string() + ": cannot open the scene file");
  std::stringstream ss;
  ss << in.rdbuf();
  Scene s = parse_scene_text(ss.str(), file.parent_path().empty() ? "." : file.parent_path(),
                             file.string());
  s.file = file;
  return s;
}

}  // namespace rc::rom
