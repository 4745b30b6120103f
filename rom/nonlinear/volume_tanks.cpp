#include "volume_tanks.hpp"

#include "general_chain.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rc::rom {
namespace {

std::string body_key(std::size_t k) { return "body[" + std::to_string(k + 1) + "]"; }

// The liquid of body k's tanks in axes turned by R from the scene's (c' = Rᵀc, G' = RᵀGR).
VolumeFluid turned_liquid(const GeneralBody& b, const Eigen::Matrix3d& R, double spin) {
  VolumeFluid v;
  v.reference_spin = spin;
  for (const GeneralTank& t : b.tanks) {
    v.geostrophic += R.transpose() * t.geostrophic * R;
    for (const GeneralMode& m : t.modes)
      v.modes.push_back({R.transpose().cast<std::complex<double>>() * m.c,
                         R.transpose().cast<std::complex<double>>() * m.c_left, m.lambda_table, m.decay_table});
  }
  v.finish();
  return v;
}

}  // namespace

bool needs_volume_tanks(const Scene& scene, TableCache& tables) {
  for (std::size_t k = 0; k < scene.size(); ++k) {
    const BodySpec& b = scene.bodies[k];
    if (b.Ixy != 0 || b.Ixz != 0 || b.Iyz != 0 || !b.more_cavities.empty()) return true;
    if (!b.cavity) continue;
    if (b.cavity->offset) return true;
    try {
      if (tables.get(b.cavity->table).volume_cavity.present()) return true;
    } catch (const std::exception& e) {
      throw SceneError(scene.file.string() + ": " + body_key(k) + ".cavity.table: " + e.what());
    }
  }
  return false;
}

std::vector<ChainBody> volume_tank_bodies(const Scene& scene, TableCache& tables) {
  std::vector<ChainBody> out;
  const std::vector<GeneralBody> bodies = general_bodies(scene, tables);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const GeneralBody& g = bodies[k];
    ChainBody body;
    body.mass = g.mass;
    body.com = g.com;
    body.next_joint = k + 1 < bodies.size() ? scene.bodies[k].next_joint : 0.0;
    // Principal axes: the turn θ about e3 that makes the transverse block diagonal, tan 2θ = 2 I_xy / (I_xx − I_yy).
    const Eigen::Matrix3d& I = g.inertia;
    body.principal_turn = 0.5 * std::atan2(2 * I(0, 1), I(0, 0) - I(1, 1));
    const Eigen::Matrix3d R = Eigen::AngleAxisd(body.principal_turn, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d principal = R.transpose() * I * R;
    body.A = principal(0, 0);
    body.B = principal(1, 1);
    body.C = principal(2, 2);
    body.volume = turned_liquid(g, R, scene.bodies[k].spin);
    // A viscous tank's decay holds at its table's Ekman number, that is at the scene's spin (nonlinear_run.hpp reports
    // how far the spin moved from it).
    for (const GeneralTank& t : g.tanks)
      if (std::any_of(t.modes.begin(), t.modes.end(), [](const GeneralMode& m) { return m.damped(); }))
        body.table_spin = scene.bodies[k].spin;
    const Eigen::Matrix3d effective = principal - body.volume.share;
    const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(effective).eigenvalues().minCoeff();
    if (!(smallest > 1e-12 * principal.trace())) {
      std::ostringstream os;
      os << "the body's inertia less its liquid's share (what the modes do not carry rigidly) is not positive definite "
            "(smallest eigenvalue " << smallest << " kg m^2): its shell is too light for its tanks, or a table is "
            "not physical";
      throw SceneError(scene.file.string() + ": " + body_key(k) + ".A: " + os.str());
    }
    out.push_back(std::move(body));
  }
  return out;
}

}  // namespace rc::rom
