#include "general_chain.hpp"

#include "free_recoil.hpp"
#include "general_system.hpp"
#include "general_tank.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

namespace rc::rom {
namespace {

std::string body_key(int k) { return "body[" + std::to_string(k + 1) + "]"; }

constexpr double kProductTolerance = 1e-5;

const rc::ModeTable& read_table(const Scene& scene, const std::string& key, const CavitySpec& cav, TableCache& tables) {
  try {
    return tables.get(cav.table);
  } catch (const std::exception& e) {
    fail(scene, key + ".table", e.what());
  }
}

// A body whose coefficients turn with it in any other frame: without axial symmetry, or with tanks (a 3-D tank's modes,
// or several or off-axis tanks, are fixed in it).
bool turns_the_frame(const BodySpec& b) { return b.asymmetric() || b.cavity.has_value(); }

// The frame's rate: the first spin of a body that turns it (else body[1]'s). Each body that turns the frame turns against it
// at ω_k − ω0; the chain's coefficients are periodic when one such rate is not zero (two spins: a dual-spin craft whose
// rotor lacks axial symmetry or carries a tank, period 2π/|ω_k − ω0|) and quasi-periodic with two rates of different
// size (three spins), which is refused. `frame` (tests) puts F at another rate.
struct FrameRates {
  double spin = 0;    // ω0
  double period = 0;  // 2π/|ω_k − ω0|, 0 when the coefficients are constant
};

FrameRates frame_rates(const Scene& scene, std::optional<double> frame = std::nullopt) {
  const std::string later = " (docs/rom.md, \"Bodies at different spins\")";
  FrameRates f;
  int first = -1;
  for (int k = 0; k < static_cast<int>(scene.size()); ++k)
    if (turns_the_frame(scene.bodies[k])) { first = k; break; }
  f.spin = frame.value_or(scene.bodies[first < 0 ? 0 : first].spin);
  int rotor = -1;
  for (int k = 0; k < static_cast<int>(scene.size()); ++k) {
    if (!turns_the_frame(scene.bodies[k])) continue;
    const double rate = std::abs(scene.bodies[k].spin - f.spin);
    if (rate <= 1e-12 * std::max(std::abs(f.spin), std::abs(scene.bodies[k].spin))) continue;
    if (rotor < 0) {
      rotor = k;
      f.period = 2 * M_PI / rate;
    } else if (std::abs(2 * M_PI / rate - f.period) > 1e-12 * f.period) {
      fail(scene, body_key(k) + ".spin", "a third spin among the bodies without axial symmetry or with tanks: the "
           "chain's coefficients are then quasi-periodic in every frame, not modelled; give it the spin of " +
           body_key(first) + " or " + body_key(rotor) + " (an axisymmetric body without tanks may spin at its own rate)" + later);
    }
  }
  return f;
}

// The general chain's scope: the chain's own inertia, gravity, joints, modal tanks, ideal or viscous (general_tank.hpp
// checks each tank's keys), a projectile's aerodynamic moments and a uniform field's axial stiffness (both isotropic
// about the spin axis: (26)'s terms carried into the turning frame, as they stand in build_model's chain), at the spins
// frame_rates allows. External moments, forces and a field's transverse parts drive the chain without changing its
// roots: a linear run refuses them (general_run.hpp), the other commands do not depend on them, as for (26).
void require_general_scene(const Scene& scene) {
  frame_rates(scene);
  // A field varying in space turns a body through its whole inertia tensor (∫ r × (G r) dm), which without axial
  // symmetry is not isotropic: (26)'s term, built on the mean transverse moment, would miss its anisotropic part.
  if (scene.field && scene.field->has_gradient())
    fail(scene, "field.gradient", "a field varying in space acts on a body's whole inertia tensor, which the chain "
                                  "without axial symmetry does not take yet (docs/rom.md, \"Aerodynamic moments, "
                                  "fields and external loads\"); [run] model = \"nonlinear\" takes it");
}
// Shell k's inertia tensor about O_k in its axes.
Eigen::Matrix3d shell_inertia(const BodySpec& b) {
  Eigen::Matrix3d I;
  I << b.A, b.Ixy, b.Ixz, b.Ixy, b.B.value_or(b.A), b.Iyz, b.Ixz, b.Iyz, b.C;
  return I;
}

// Body k's tanks: [body.cavity] and every further [[body.cavity]], each with its scene key.
std::vector<std::pair<CavitySpec, std::string>> body_tanks(const BodySpec& b, int k) {
  std::vector<std::pair<CavitySpec, std::string>> out;
  if (!b.cavity) return out;
  const bool several = !b.more_cavities.empty();
  out.emplace_back(*b.cavity, body_key(k) + (several ? ".cavity[1]" : ".cavity"));
  for (std::size_t i = 0; i < b.more_cavities.size(); ++i)
    out.emplace_back(b.more_cavities[i], body_key(k) + ".cavity[" + std::to_string(i + 2) + "]");
  return out;
}

// A body spins steadily about its axis only with its centre of mass on it and no products I_xz, I_yz about its joint
// (else gravity or the spin's centrifugal moments turn it). A 3-D table's tensor holds the mesh's error (products
// ~1e-6 of the trace on an upright ellipsoid at the default order): below kProductTolerance of the trace the products
// are taken as that error and dropped.
void require_balanced(const Scene& scene, int k, const Eigen::Matrix3d& I, const Eigen::Vector2d& first_moment,
                      double mass_arm, bool meshed) {
  // A 3-D table's liquid is meshed, and its centroid carries that error: two P3 meshes of one half-full sphere placed
  // 0.6 m either side of the axis leave 6e-5 of the arm (2026-12-02; docs/volume.md §8), two full P3 spheres there
  // 3.5e-6 (2026-12-07), which is their error, not an imbalance. Axisymmetric tables keep 1e-6.
  if (first_moment.norm() > (meshed ? 1e-4 : 1e-6) * mass_arm) {
    std::ostringstream os;
    os << "the body's centre of mass with its tanks lies off its axis (mass times offset " << first_moment.transpose()
       << " kg m): it cannot spin steadily about its axis; place the tanks in balance";
    fail(scene, body_key(k) + ".cavity.offset", os.str());
  }
  if (std::hypot(I(0, 2), I(1, 2)) > kProductTolerance * I.trace()) {
    std::ostringstream os;
    os << "the body with its frozen liquid has products of inertia I_xz, I_yz = " << I(0, 2) << ", " << I(1, 2)
       << " kg m^2 about its joint (more than " << kProductTolerance << " of its inertia's trace): it cannot spin "
       << "steadily about its axis; balance them with the shell's Ixz, Iyz";
    fail(scene, body_key(k) + ".Ixz", os.str());
  }
}

// The scene as (26) sees it: every tank's frozen fluid folded into its shell (mass, centre of mass on the axis,
// inertia), each body's transverse inertia replaced by its mean Ā_k.
Scene axisymmetric_part(const Scene& scene, const std::vector<GeneralBody>& bodies) {
  Scene folded = scene;
  for (int k = 0; k < static_cast<int>(scene.size()); ++k) {
    BodySpec& b = folded.bodies[k];
    const Eigen::Matrix3d& I = bodies[k].inertia;
    b.mass = bodies[k].mass;
    b.com = bodies[k].com;
    b.cavity.reset();
    b.more_cavities.clear();
    b.A = 0.5 * (I(0, 0) + I(1, 1));
    b.B.reset();
    b.C = I(2, 2);
    b.Ixy = b.Ixz = b.Iyz = 0;
  }
  return folded;
}

// A 2 × 2 block of the real form: the complex scalar a + ib acting on v = q_x − i q_y is a I − b J on q.
Eigen::Matrix2d real_block(double a, double b) {
  Eigen::Matrix2d m;
  m << a, b, -b, a;
  return m;
}

}  // namespace

// (26) carried into the turning frame (u = e^{−iω0t} v): M v̈ + (i(G − 2ω0 M) + D) v̇ + (K − ω0² M + ω0 G − iω0 D) v,
// K with its aerodynamic and field terms and the Magnus moments' −i·circulatory (complex_stiffness),
// each complex coefficient as its real block; then each body's anisotropy and, with axial rates, the spins' block
// (axial_rotation.hpp: C_k ψ̈_k + axial friction).
void set_turning_frame_matrices(const ChainModel& cm, const ChainModel& axial, const std::vector<Eigen::Matrix3d>& inertia,
                                GeneralChain& g) {
  const int n = g.n, d = g.dim_q();
  const double w = g.spin;
  g.M.setZero(d, d);
  g.C.setZero(d, d);
  g.K.setZero(d, d);
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i) {
      const double G = (k == i) ? cm.G[k] : 0.0, M = cm.M(k, i), D = cm.D(k, i);
      g.M.block<2, 2>(2 * k, 2 * i) = real_block(M, 0);
      g.C.block<2, 2>(2 * k, 2 * i) = real_block(D, G - 2 * w * M);
      // The Magnus moments' circulatory stiffness −i·circulatory (chain_model.hpp) on the diagonal.
      const double circulatory = (k == i && cm.circulatory.size() > k) ? cm.circulatory[k] : 0.0;
      g.K.block<2, 2>(2 * k, 2 * i) = real_block(cm.K(k, i) - w * w * M + w * G, -w * D - circulatory);
    }
  for (int k = 0; k < static_cast<int>(inertia.size()); ++k) {
    const Eigen::Matrix2d I_tt = inertia[k].topLeftCorner<2, 2>();
    const Eigen::Matrix2d Delta = I_tt - 0.5 * I_tt.trace() * Eigen::Matrix2d::Identity();
    g.anisotropy.push_back(Delta);
    g.M.block<2, 2>(2 * k, 2 * k) -= Delta;
    g.K.block<2, 2>(2 * k, 2 * k) -= w * w * Delta;
  }
  if (!g.axial) return;
  const int spinning = g.spinning();
  for (int k = 0; k < spinning; ++k) g.M(2 * n + k, 2 * n + k) = axial.bodies[k].C;
  g.C.bottomRightCorner(spinning, spinning) = axial.axial.D;
}

std::vector<GeneralBody> general_bodies(const Scene& scene, TableCache& tables) {
  std::vector<GeneralBody> out;
  for (int k = 0; k < static_cast<int>(scene.size()); ++k) {
    const BodySpec& spec = scene.bodies[k];
    GeneralBody b;
    b.mass = spec.mass;
    b.com = spec.com;
    b.inertia = shell_inertia(spec);
    Eigen::Vector2d first_moment = Eigen::Vector2d::Zero();
    double mass_arm = 0;
    bool meshed = false;
    for (const auto& [cav, key] : body_tanks(spec, k)) {
      GeneralTank tank = general_tank(scene, k, cav, key, read_table(scene, key, cav, tables));
      b.com = (b.mass * b.com + tank.mass * tank.centroid.z()) / (b.mass + tank.mass);
      b.mass += tank.mass;
      first_moment += tank.mass * tank.centroid.head<2>();
      // The scale the balance is judged on: the tank's arm and its own size (a meshed centroid errs by a fraction of
      // the tank, wherever it sits: two tanks on the axis have no arm).
      mass_arm += tank.mass * (tank.centroid.norm() + cav.scale);
      meshed = meshed || tank.three_d;
      b.inertia += tank.inertia;
      b.tanks.push_back(std::move(tank));
    }
    require_balanced(scene, k, b.inertia, first_moment, mass_arm, meshed);
    out.push_back(std::move(b));
  }
  return out;
}

bool needs_general_chain(const Scene& scene, TableCache& tables) {
  for (int k = 0; k < static_cast<int>(scene.size()); ++k) {
    const BodySpec& b = scene.bodies[k];
    if (b.asymmetric() || !b.more_cavities.empty()) return true;
    for (const auto& [cav, key] : body_tanks(b, k))
      if (cav.offset || cav.bands || read_table(scene, key, cav, tables).volume_cavity.present()) return true;
  }
  return false;
}

GeneralChain build_general_chain(const Scene& scene, TableCache* tables, std::optional<double> frame) {
  require_general_scene(scene);
  TableCache own;
  TableCache& cache = tables ? *tables : own;
  const std::vector<GeneralBody> bodies = general_bodies(scene, cache);
  const ChainModel cm = build_model(axisymmetric_part(scene, bodies), &cache);  // the shells with their frozen
                                                                                 // fluid: (26) without tanks
  GeneralChain g;
  g.n = cm.n;
  const FrameRates rates = frame_rates(scene, frame);
  g.spin = rates.spin;
  g.period = rates.period;
  g.spins.resize(g.n);
  for (int k = 0; k < g.n; ++k) g.spins[k] = scene.bodies[k].spin;
  g.free_chain = scene.free_chain;
  for (int k = 0; k < g.n; ++k) {
    Eigen::Matrix3d geostrophic = Eigen::Matrix3d::Zero();
    for (const GeneralTank& t : bodies[k].tanks) {
      g.axial = g.axial || t.three_d;
      geostrophic += t.geostrophic;
      g.modes.insert(g.modes.end(), t.modes.begin(), t.modes.end());
      g.coverage.emplace_back(k, t.coverage);
      if (t.pruned_rows > 0) g.pruned_rows.emplace_back(k, t.pruned_rows);
      if (t.unsettled_rows > 0) {
        std::ostringstream os;
        os << "body " << k + 1 << "'s partially filled 3-D tank: " << t.unsettled_rows << " of its kept rows did not "
           << "settle (lambda to " << t.worst_bound << " of itself) and its rows cover " << t.coverage
           << " of its sum rule about the joint";
        g.not_converged.push_back(os.str());
      }
      if (t.window > 0) g.response_window = g.response_window > 0 ? std::min(g.response_window, t.window) : t.window;
    }
    g.geostrophic.push_back(geostrophic);
  }
  g.dissipative = cm.has_friction() || cm.has_circulatory() || (g.axial && cm.axial.D.cwiseAbs().maxCoeff() > 0) ||
                  std::any_of(g.modes.begin(), g.modes.end(), [](const GeneralMode& m) { return m.damped(); });
  g.axial_inertia.resize(g.n);
  for (int k = 0; k < g.n; ++k) g.axial_inertia[k] = cm.bodies[k].C;
  std::vector<Eigen::Matrix3d> inertia;
  for (const GeneralBody& b : bodies) inertia.push_back(b.inertia);
  set_turning_frame_matrices(cm, cm, inertia, g);
  if (std::any_of(bodies.begin(), bodies.end(), [](const GeneralBody& b) {
        return std::any_of(b.tanks.begin(), b.tanks.end(), [](const GeneralTank& t) { return t.recoil; });
      })) {
    if (g.periodic())
      fail(scene, "body", "a free chain with a partially filled tank off its axis at two spins is not modelled yet (its "
                          "base's recoil at periodic coefficients); give its bodies one spin");
    g.recoil = std::make_shared<const GeneralChain>(extend_with_recoil(scene, g, cm, bodies));
  }
  check_effective_inertia(scene, g.recoil ? *g.recoil : g);
  return g;
}

}  // namespace rc::rom
