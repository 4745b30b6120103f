// Scene file of chain-rom (docs/physics.md §4, documented key by key in docs/scene-format.md).
// parse_scene() validates everything and throws SceneError with a one-line cause naming the key.
#pragma once

#include <array>
#include <complex>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rc::rom {

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CavitySpec {
  std::filesystem::path table;     // resolved against the scene file's folder
  double density = 0;              // kg/m^3
  double scale = 0;                // metres per table length unit
  double center = 0;               // O_k -> fluid centroid along the axis (m); or, with origin:
  std::optional<double> origin;    // O_k -> the table's z = 0 along the axis (m): the centroid then follows
                                   // from the table, center = origin + scale * centroid_z (chain_model.cpp)
  std::optional<int> modes;        // keep the first `modes` modes (table is sorted by E)
  std::optional<double> coverage;  // or: the fewest leading modes whose sum E >= coverage*sum_rule
  bool static_correction = false;  // add the unkept remainder (A_f - J_zh) - sum E as inertia
  // A response table's rows that no root needs (their summed contribution on the window under 1 % of its fit
  // error: rom/model/response_row_pruning.hpp) are left out; false keeps every row.
  bool prune = true;
  std::filesystem::path companion; // optional: the same cavity's table on a coarser mesh; `spectrum` marks the roots
                                   // that move when it replaces `table` (companion_check.hpp)
  std::optional<double> viscosity; // kinematic viscosity nu (m^2/s): the table must then be viscous with
                                   // ekman = nu/(spin scale^2) (docs/rom.md, "Viscous tanks")
  bool galerkin = false;           // reduction = "galerkin": the kept modes as a Galerkin basis, with the fluid's
                                   // energy and dissipation (docs/rom.md, "Galerkin tanks"); "modal" (default): not
  bool bands = false;              // reduction = "bands": a 3-D table's coupling in λ-bands, each band one pseudo-mode
                                   // at its mean λ (dense spectra; docs/rom.md, "Bodies and tanks without axial
                                   // symmetry")
  // The centroid's distance from the body's axis, (x, y) in the body's axes (m): a tank off the axis (the chain without
  // axial symmetry only, docs/rom.md "Bodies and tanks without axial symmetry").
  std::optional<std::array<double, 2>> offset;
};

// An external moment on a body (N m; nonlinear model only): `axial` about the body's axis, `space` fixed in space,
// `harmonic` · sin(2π frequency t) in space.
struct MomentSpec {
  double axial = 0;
  std::array<double, 3> space{0, 0, 0}, harmonic{0, 0, 0};
  double frequency = 0;  // Hz
};

// An external force on a body (N; Batyr (1)-(7)'s F_k), applied at the point `at` (m) along its axis from O_k: `space`
// fixed in space plus `harmonic` · sin(2π frequency t) (docs/rom.md, "External forces").
struct ForceSpec {
  std::array<double, 3> space{0, 0, 0}, harmonic{0, 0, 0};
  double frequency = 0;  // Hz
  double at = 0;         // m along the body's axis from O_k
};

// A projectile's aerodynamic moments in linear theory (docs/rom.md, "A projectile's aerodynamic moments"): about the
// body's fixed point, the reference direction of the yaw the chain's vertical (the flight direction).
struct AeroSpec {
  double static_moment = 0;  // N m per radian of yaw: > 0 overturning (a spin-stabilised shell), < 0 restoring (a fin)
  double pitch_damping = 0;  // N m per rad/s of transverse angular velocity, >= 0
  double magnus = 0;         // N m per radian of yaw per rad/s of spin: the Magnus moment, along the yaw's direction
};

struct BodySpec {
  double mass = 0;        // shell mass
  double A = 0;           // shell transverse inertia about O_k
  std::optional<double> B;  // the second transverse moment about O_k (default A; B != A: the general chain or the
                            // nonlinear model, docs/rom.md "Bodies and tanks without axial symmetry")
  double C = 0;           // shell axial inertia
  // The shell's inertia tensor's off-diagonal entries about O_k in its axes (kg m², I_xy = −∫xy dm): a tank tilted
  // against the spin axis is balanced by them (the general chain only; 0 by default).
  double Ixy = 0, Ixz = 0, Iyz = 0;
  bool asymmetric() const { return (B && *B != A) || Ixy != 0 || Ixz != 0 || Iyz != 0; }
  double com = 0;         // O_k -> shell centre of mass
  double next_joint = 0;  // s_k
  double spin = 0;        // omega_k0, rad/s
  std::optional<CavitySpec> cavity;
  std::vector<CavitySpec> more_cavities;  // [[body.cavity]] beyond the first: several tanks on one body (the chain
                                          // without axial symmetry only)
  std::optional<MomentSpec> moment;
  std::optional<ForceSpec> force;
  std::optional<AeroSpec> aero;
};

struct JointSpec {
  double stiffness = 0;  // kappa_k^2
  double friction = 0;   // alpha_{k+1}
  double axial_friction = 0;  // on the relative spin of bodies k, k+1 (nonlinear model only)
};

struct RunSpec {
  bool present = false;
  double t_end = 0;
  double output_step = 0;
  std::string method = "exact";  // exact | gauss | rk45
  double tolerance = 1e-10;
  std::string model = "linear";  // linear (system (26)) | nonlinear (rom/nonlinear/nonlinear_chain.hpp)
  bool nonlinear() const { return model == "nonlinear"; }
};

// A uniform body-force field (Batyr's f(t, x), uniform in space): an acceleration in m/s² acting on every mass
// besides gravity, `space` constant plus `harmonic` · sin(2π frequency t) — the inertial force of a support's or a
// craft's acceleration (docs/rom.md, "A uniform force field").
// `gradient` G (1/s², row-major, symmetric) adds the non-uniform part G x, x from the space origin (O_1 of a fixed
// chain): a potential field's first-order variation, e.g. an orbit's gravity gradient (docs/rom.md, "A field that
// varies in space").
struct FieldSpec {
  std::array<double, 3> space{0, 0, 0}, harmonic{0, 0, 0};
  double frequency = 0;  // Hz
  std::array<double, 9> gradient{};
  bool has_gradient() const {
    for (const double g : gradient)
      if (g != 0) return true;
    return false;
  }
};

struct Scene {
  std::filesystem::path file;
  bool free_chain = false;
  double gravity = 0;
  std::optional<FieldSpec> field;
  std::vector<BodySpec> bodies;
  std::vector<JointSpec> joints;  // n - 1
  double support_friction = 0;    // alpha_1
  double support_axial_friction = 0;  // on body 1's spin (nonlinear model only)
  std::vector<std::complex<double>> tilt, rate;  // u_k(0), du_k/dt(0); zeros when absent
  std::vector<std::complex<double>> fluid;        // z_kl(0) of the kept modes, body by body (empty: at rest)
  std::vector<double> axial_rate;                 // ω_k(0) − ω_k0, rad/s: the spins' change at t = 0 (zeros when absent)
  RunSpec run;
  std::size_t size() const { return bodies.size(); }
};

// The one-line refusal of a scene's key by the layers above the parser: throws SceneError("<file>: <key>: <cause>").
[[noreturn]] inline void fail(const Scene& s, const std::string& key, const std::string& cause) {
  throw SceneError(s.file.string() + ": " + key + ": " + cause);
}

// Parses and validates a scene file. Throws SceneError("<file>: <key>: <cause>").
Scene parse_scene(const std::filesystem::path& file);
// Same, from TOML text; `base` is the folder that relative table paths are taken from.
Scene parse_scene_text(const std::string& text, const std::filesystem::path& base,
                       const std::string& name = "<scene>");

}  // namespace rc::rom
