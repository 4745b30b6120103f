#include "general_tank.hpp"

#include "chain_model.hpp"
#include "response_row_pruning.hpp"
#include "row_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rc::rom {
namespace {

using RowMajor3d = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

Eigen::Matrix3d tensor(const std::vector<double>& v) { return Eigen::Map<const RowMajor3d>(v.data()); }

// A 3-D partial fill's five directions (U_x, U_y, U_z, T̂_x, T̂_y) about P0, the spin axis's point at the centroid's
// height, taken to the joint O = P0 − c ẑ: U_O,k = U_k + c T̂_k (docs/volume.md §8, "The table").
using Directions5 = Eigen::Matrix<std::complex<double>, 5, 5>;
Eigen::Matrix<double, 3, 5> fill_about_joint(double c) {
  Eigen::Matrix<double, 3, 5> B = Eigen::Matrix<double, 3, 5>::Zero();
  B.leftCols<3>().setIdentity();
  B(0, 3) = B(1, 4) = c;
  return B;
}

Directions5 fill_block(const std::vector<double>& re, const std::vector<double>& im, std::size_t l) {
  Directions5 H;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      H(i, j) = {re[25 * l + 5 * i + j], im.empty() ? 0.0 : im[25 * l + 5 * i + j]};
  return H;
}

Eigen::Matrix3cd fill_tensor_about_joint(const Directions5& H, double c) {
  const Eigen::Matrix<double, 3, 5> B = fill_about_joint(c);
  return B.cast<std::complex<double>>() * H * B.transpose().cast<std::complex<double>>();
}

// In a free chain the joint O translates too, with velocity V in F: the T̂ directions' amplitude gains τ = J V
// (docs/volume.md §8, "The free chain"). The five velocities (δω, τ) about the joint, τ in m/s: the table's T̂ amplitude
// is τ/L (its lengths in units of L).
Eigen::Matrix<double, 5, 5> fill_with_base(double c, double L) {
  Eigen::Matrix<double, 5, 5> B = Eigen::Matrix<double, 5, 5>::Zero();
  B.topRows<3>() = fill_about_joint(c);
  B(3, 3) = B(4, 4) = 1 / L;
  return B;
}

Directions5 fill_form_with_base(const Directions5& H, double c, double L) {
  const Eigen::Matrix<double, 5, 5> B = fill_with_base(c, L);
  return B.cast<std::complex<double>>() * H * B.transpose().cast<std::complex<double>>();
}

// A row's coupling tensor H about the body's joint: the 3-D table's, or an axisymmetric m = 1 row's
// E/2 (1, i, 0)(1, −i, 0)ᵀ — with a viscous row's complex E + i·E_imag (the rank-one product of its right and left
// couplings, docs/volume.md §7), and a partially filled tank's E = 2(a + c t)²/N² about the joint (row_coupling.hpp);
// a 3-D partial fill's B H Bᵀ (fill_tensor_about_joint).
Eigen::Matrix3cd row_coupling(const rc::ModeTable& t, std::size_t l, const RowCoupling& about) {
  Eigen::Matrix3cd H = Eigen::Matrix3cd::Zero();
  if (t.volume_free_surface.present())
    return fill_tensor_about_joint(fill_block(t.volume_free_surface.coupling_re, t.volume_free_surface.coupling_im, l), about.c);
  if (!t.volume_cavity.present()) {
    const std::complex<double> E = about.E_c(l), I(0, 1);
    return E / 2.0 * Eigen::Vector3cd(1, I, 0) * Eigen::RowVector3cd(1, -I, 0);
  }
  const rc::ModeTable::Volume& v = t.volume_cavity;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) H(i, j) = {v.coupling_re[9 * l + 3 * i + j], v.coupling_im[9 * l + 3 * i + j]};
  return H;
}

// What the general chain takes of a tank so far: a modal tank, filled; a viscous one at its table's Ekman number, and
// a 3-D viscous one spinning the table's way (spin −ω mirrors the flow, and a 3-D cavity's mirror image is another
// cavity; an axisymmetric one's is itself: docs/rom.md, "Viscous tanks").
// Every refusal of a tank here ends with what the chain does take instead.
const char* const kTanksTaken =
    "; it takes, on or off a body's axis, a full tank's ideal or damped-mode table (axisymmetric or 3-D: cavity-modes "
    "SHAPE|ellipsoid|volume [--ekman Ek] -o T.h5) or a response table (cavity-modes ellipsoid|volume --ekman Ek "
    "--sigma A:B:N -o T.h5, or axisymmetric: cavity-modes response SHAPE --ekman Ek --sigma A:B:N -o T.h5), and on "
    "the chain's first body a partially filled tank, ideal on its axis (3-D, or axisymmetric on a fixed chain) or off "
    "it (3-D: cavity-modes ellipsoid --fill F --axis-distance D -o T.h5), or viscous, 3-D, as its response table "
    "(cavity-modes ellipsoid --fill F --axis-distance D --ekman Ek --sigma 0:TO:N -o T.h5); in a free chain the 3-D "
    "fills sit in a layout that a turn about the spin axis maps onto itself (docs/rom.md, \"Bodies and tanks without "
    "axial symmetry\"; docs/volume.md section 8)";

void require_modal(const Scene& scene, const std::string& w, const CavitySpec& cav, const rc::ModeTable& t, double spin) {
  const std::string later = std::string(" is not in the chain without axial symmetry yet") + kTanksTaken;
  check_viscosity(scene, w, cav, t, spin);
  if (t.viscous() && t.volume_cavity.present() && spin < 0)
    fail(scene, w + ".table", "a 3-D viscous table holds the modes for a positive spin, and spin -w mirrors the "
                              "cavity: turn the scene's axis over (a positive spin) or mesh the mirrored cavity");
  // A response table's rows are its reduced response's poles, each a damped mode of rank one: a 3-D one's
  // (docs/volume.md §7, "The response table"), and an axisymmetric one's (Krylov, Galerkin or fitted: pole λ + i·decay,
  // residue E + i·E_imag, docs/viscous.md "Response fit"), whose window must hold both signs of frequency (a body
  // without axial symmetry drives a tank's m = 1 response at σ and −σ̄ alike).
  if (t.response_fit() && !t.volume_cavity.present() && !(t.fit_lo < 0 && t.fit_hi > 0)) {
    std::ostringstream os;
    os << "an axisymmetric response table's window [" << t.fit_lo << ", " << t.fit_hi << "] (s = σ/ω in the body's "
       << "frame) must hold s = 0: in the chain without axial symmetry a tank is driven at both signs of frequency "
       << "(make it with --sigma FROM:TO:N, FROM < 0 < TO)" << kTanksTaken;
    fail(scene, w + ".table", os.str());
  }
  if (cav.static_correction) fail(scene, w + ".static_correction", "the static correction" + later);
  if (cav.galerkin) fail(scene, w + ".reduction", "the Galerkin reduction" + later);
  if (!cav.companion.empty()) fail(scene, w + ".companion", "a companion table" + later);
  if (t.m != 1) fail(scene, w + ".table", cav.table.string() + " holds m = " + std::to_string(t.m) +
                                  " modes; only m = 1 modes couple to the tilt");
}

// A partially filled tank so far: on the axis of the first body of a fixed chain, whose joint stays put (on a body
// whose joint moves its modes couple to the earlier bodies' tilts too: docs/rom.md, "Partially filled tanks"; off the
// axis its free surface would face the spin axis sideways, which no axisymmetric table describes).
void require_fixed_joint(const Scene& scene, int k, const CavitySpec& cav, const std::string& w, bool three_d) {
  const std::string later = kTanksTaken;
  if (!three_d && cav.offset && ((*cav.offset)[0] != 0 || (*cav.offset)[1] != 0))
    fail(scene, w + ".offset", "an axisymmetric table of a partially filled tank holds it on the spin axis; off the "
                               "axis its free surface faces the spin axis sideways: make its 3-D table with cavity-modes "
                               "ellipsoid --fill F --axis-distance D -o T.h5 (docs/volume.md §8)" + later);
  if (k > 0)
    fail(scene, w + ".table", "a partially filled tank in the chain without axial symmetry sits on the chain's first "
                              "body so far (a moving joint couples its modes to the earlier bodies)" + later);
  if (!three_d && scene.free_chain)
    fail(scene, w + ".table", "an axisymmetric table of a partially filled tank is taken by the chain with axial "
                              "symmetry in a free chain (one tank on the axis, docs/free-chain.md), not by the chain "
                              "without it; a 3-D table (cavity-modes ellipsoid --fill F -o T.h5) is" + later);
}

// A field that moves the free surface sideways (its transverse parts, or a gradient) is not modelled, as in (26)
// (rom/model/chain_model.cpp); an axial field is taken, as gravity is.
void require_axial_field(const Scene& scene) {
  if (!scene.field) return;
  const FieldSpec& f = *scene.field;
  if (f.space[0] != 0 || f.space[1] != 0 || f.harmonic[0] != 0 || f.harmonic[1] != 0)
    fail(scene, "field", "a transverse field moves a partially filled tank's free surface, which the chain does not "
                         "model yet (an axial field is taken, as gravity is)");
  if (f.has_gradient())
    fail(scene, "field.gradient", "a field varying in space moves a partially filled tank's free surface, which the "
                                  "chain does not model yet");
}

// The rows kept, heaviest E first: every one that couples, or the first `modes`, or as many as reach `coverage` of
// the sum rule (a 3-D table's λ = 0 weight counted as kept). Returns the coverage reached in `covered`, and in
// `pruned` how many rows of a response table were left out as no root needs them. A free chain's 3-D fill (`recoil`)
// keeps a row that couples through the base's translation alone too (its rotation coupling zero about the joint).
std::vector<int> kept_rows(const Scene& scene, const std::string& w, const CavitySpec& cav, const rc::ModeTable& t,
                           const RowCoupling& about, bool recoil, double& covered, int& pruned) {
  // About the joint: a partially filled tank's rows weigh E = 2(a + c t)²/N² there, its sum rule A_f + K − J_zh.
  const bool surface = t.free_surface.present(), fill3 = t.volume_free_surface.present();
  const auto& vf = t.volume_free_surface;
  const double total = surface ? about.sum_rule()
                       : fill3 ? 0.5 * fill_tensor_about_joint(fill_block(vf.gram_re, vf.gram_im, 0), about.c)
                                           .topLeftCorner<2, 2>().trace().real()
                               : t.sum_rule;
  const double tiny = 1e-14 * std::max(std::abs(total), 1e-300);
  const auto E = [&](int l) {
    if (fill3) return row_coupling(t, static_cast<std::size_t>(l), about).topLeftCorner<2, 2>().trace().real();
    return surface ? about.E(static_cast<std::size_t>(l)) : t.E[l];
  };
  std::vector<int> idx;
  for (std::size_t l = 0; l < t.size(); ++l)
    if ((recoil ? fill_form_with_base(fill_block(vf.coupling_re, vf.coupling_im, l), about.c, 1.0).norm()
                : row_coupling(t, l, about).norm()) > tiny)
      idx.push_back(static_cast<int>(l));  // a viscous H's trace may vanish
  std::stable_sort(idx.begin(), idx.end(), [&](int i, int j) { return E(i) > E(j); });
  const double geostrophic =
      fill3 ? fill_tensor_about_joint(fill_block(vf.geostrophic_re, vf.geostrophic_im, 0), about.c).topLeftCorner<2, 2>().trace().real() / 2
      : t.volume_cavity.present() ? tensor(t.volume_cavity.geostrophic_re).topLeftCorner<2, 2>().trace() / 2 : 0.0;
  std::size_t keep = idx.size();
  if (cav.modes) {
    if (static_cast<std::size_t>(*cav.modes) > idx.size())
      fail(scene, w + ".modes", std::to_string(*cav.modes) + " requested, the table " + cav.table.filename().string() +
                                    " holds " + std::to_string(idx.size()) + " coupling modes");
    keep = *cav.modes;
  } else if (cav.coverage) {
    double acc = geostrophic;
    keep = 0;
    while (keep < idx.size() && acc < *cav.coverage * total * (1 - 1e-12)) acc += E(idx[keep++]);
    if (acc < *cav.coverage * total * (1 - 1e-12)) {
      std::ostringstream os;
      os << "coverage " << *cav.coverage << " not reachable: the table's modes cover " << acc / total;
      fail(scene, w + ".coverage", os.str());
    }
  }
  idx.resize(keep);
  // An axisymmetric response table's rows that no root needs, left out as the chain with axial symmetry leaves them
  // (rom/model/response_row_pruning.hpp): both chains hold the same rows.
  pruned = 0;
  if (prunable(t, cav)) {
    const PrunedRows p = prune_response_rows(t, idx, kPruneMagnitude, kPruneDissipation);
    idx = p.kept;
    pruned = p.dropped;
  }
  covered = geostrophic;
  for (const int l : idx) covered += E(l);
  covered /= total;
  return idx;
}

// A mode from its coupling over the body's rotation (3) and, for a free chain's partial fill, the base's τ (2 more).
GeneralMode row_mode(int k, int row, std::complex<double> lambda, double lambda_table, double decay_table,
                     const Eigen::VectorXcd& c, const Eigen::VectorXcd& c_left) {
  GeneralMode m{k, row, lambda, lambda_table, decay_table, c.head<3>(), c_left.head<3>()};
  if (c.size() == 5) {
    m.c_base = c.tail<2>();
    m.c_left_base = c_left.tail<2>();
  }
  return m;
}

// A row's H = Σ_j μ_j u_j u_jᴴ as rank-one couplings c_j = √μ_j u_j, c_left = c̄ (one per discrete copy the row's
// cluster sums). H is over the body's rotation, or also over the base's τ (5 × 5: a free chain's partial fill).
void add_ideal_row_modes(int k, int row, const Eigen::MatrixXcd& H, double spin, double lambda_table, double unit,
                         GeneralTank& tank) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> es(H);
  const double top = es.eigenvalues().maxCoeff();
  for (Eigen::Index j = 0; j < H.rows(); ++j) {
    const double mu = es.eigenvalues()[j];
    if (!(mu > 1e-12 * top)) continue;
    const Eigen::VectorXcd c = std::sqrt(mu * unit) * es.eigenvectors().col(j);
    tank.modes.push_back(row_mode(k, row, spin * lambda_table, lambda_table, 0.0, c, c.conjugate()));
  }
}

// A damped mode's H = c c_leftᵀ (rank one, docs/volume.md §7) from its largest singular triple H = s u vᴴ:
// c = √s u, c_left = √s v̄ (any split of the scale between them gives the same chain). Spin −ω (an axisymmetric
// tank only: require_modal) mirrors the flow (x → −x: H → M H M, M = diag(−1, 1, 1)) and writes it as its conjugate,
// λ → −λ̄, H → conj(M H M) = Hᴴ for an axisymmetric row (E_c → Ē_c, as (26)'s; docs/rom.md, "Viscous tanks").
void add_damped_row_mode(const Scene& scene, const std::string& w, int k, int row, Eigen::MatrixXcd H, double spin,
                         double lambda_table, double decay_table, double unit, GeneralTank& tank) {
  if (spin < 0) H = H.adjoint().eval();
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd s = svd.singularValues();
  if (!(s[1] <= 1e-6 * s[0]))
    fail(scene, w + ".table", "row " + std::to_string(row + 1) + "'s coupling tensor is not of rank one (singular "
                              "values " + std::to_string(s[0]) + ", " + std::to_string(s[1]) + "): a viscous row is "
                              "one damped mode");
  const Eigen::VectorXcd c = std::sqrt(s[0] * unit) * svd.matrixU().col(0);
  const Eigen::VectorXcd c_left = std::sqrt(s[0] * unit) * svd.matrixV().col(0).conjugate();
  const std::complex<double> lambda(spin * lambda_table, std::abs(spin) * decay_table);
  tank.modes.push_back(row_mode(k, row, lambda, lambda_table, decay_table, c, c_left));
}

// A response table's window in the turning frame (|Re σ|, rad/s) within which it is the fluid's R: a 3-D table's
// [0, fit_hi] (its rows hold λ > 0, their conjugates the rest); an axisymmetric one's s ∈ [fit_lo, fit_hi] for both
// σ/ω and −σ̄/ω (require_modal). 0: not a response table.
double response_window(const rc::ModeTable& t, double spin) {
  if (!t.response_fit()) return 0;
  const double s = t.volume_cavity.present() ? t.fit_hi : std::min(-t.fit_lo, t.fit_hi);
  return s * std::abs(spin);
}

// The frozen fluid about its centroid and its λ = 0 weight, in the table's units.
void table_tensors(const rc::ModeTable& t, Eigen::Matrix3d& inertia, Eigen::Matrix3d& geostrophic) {
  if (t.volume_cavity.present()) {
    inertia = tensor(t.volume_cavity.inertia);
    geostrophic = tensor(t.volume_cavity.geostrophic_re);
    geostrophic = 0.5 * (geostrophic + geostrophic.transpose()).eval();  // real symmetric up to the table's rounding
  } else {
    inertia = Eigen::Vector3d(t.A_f, t.A_f, t.C_f).asDiagonal();
    geostrophic = Eigen::Vector3d(0, 0, t.C_f).asDiagonal();
  }
}

// reduction = "bands": every λ-band holding weight as one pseudo-mode at its mean λ, its summed H split into rank-one
// parts (docs/volume.md §5: the plain Gauss rule's nodes, a dense cluster's light modes included). Returns the
// coverage (the bands' transverse weight and the λ = 0 weight's half over the sum rule: 1 to rounding).
double add_band_modes(const Scene& scene, const std::string& w, int k, const rc::ModeTable& t, double unit,
                      GeneralTank& tank) {
  const rc::ModeTable::Volume& v = t.volume_cavity;
  if (!v.present() || v.band_lambda.empty())
    fail(scene, w + ".reduction", "\"bands\" needs a 3-D table with band couplings (cavity-modes ellipsoid / volume "
                                  "of this version): " + t.shape + " table " + "without them");
  double covered = tensor(v.geostrophic_re).topLeftCorner<2, 2>().trace() / 2;
  for (std::size_t b = 0; b < v.band_lambda.size(); ++b) {
    Eigen::Matrix3cd H;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) H(i, j) = {v.band_coupling_re[9 * b + 3 * i + j], v.band_coupling_im[9 * b + 3 * i + j]};
    if (!(H.trace().real() > 1e-14 * std::abs(t.sum_rule))) continue;
    add_ideal_row_modes(k, static_cast<int>(b), H, scene.bodies[k].spin, v.band_lambda[b], unit, tank);
    covered += (H(0, 0) + H(1, 1)).real();
  }
  return covered / t.sum_rule;
}

// A 3-D partial fill about its joint (docs/volume.md §8): the surface re-centres on the tilted spin axis, K(O) = B S Bᵀ
// more inertia (S the directions' surface Gram matrix), and the λ = 0 weight is B G Bᵀ.
// In a free chain both forms are kept over the base's τ as well (fill_with_base).
void add_fill_about_joint(const rc::ModeTable& t, double c, double L, double unit, GeneralTank& tank) {
  const auto& vf = t.volume_free_surface;
  tank.inertia += unit * fill_tensor_about_joint(fill_block(vf.surface_gram, {}, 0), c).real();
  const Eigen::Matrix3d G = fill_tensor_about_joint(fill_block(vf.geostrophic_re, vf.geostrophic_im, 0), c).real();
  tank.geostrophic = unit * 0.5 * (G + G.transpose());
  if (!tank.recoil) return;
  tank.surface_form = unit * fill_form_with_base(fill_block(vf.surface_gram, {}, 0), c, L).real();
  const Eigen::Matrix<double, 5, 5> G5 = fill_form_with_base(fill_block(vf.geostrophic_re, vf.geostrophic_im, 0), c, L).real();
  tank.geostrophic_form = unit * 0.5 * (G5 + G5.transpose());
}

// A row's coupling tensor as the chain takes it: about the joint (3 × 3), or with the base's τ (5 × 5) in a free chain.
Eigen::MatrixXcd row_tensor(const rc::ModeTable& t, std::size_t l, const RowCoupling& about, const GeneralTank& tank,
                            double L) {
  if (!tank.recoil) return row_coupling(t, l, about);
  const auto& vf = t.volume_free_surface;
  return fill_form_with_base(fill_block(vf.coupling_re, vf.coupling_im, l), about.c, L);
}

// A 3-D partial fill's table holds its spin axis (the surface is a cylinder about it): the body's axis must be that
// axis, so the tank's horizontal place follows from the table (offset = L (C − axis) for `center`, or −L·axis with
// `origin`: the tank's own centre D·L from the axis, as made with --axis-distance D).
void require_on_the_spin_axis(const Scene& scene, const CavitySpec& cav, const std::string& w, const rc::ModeTable& t,
                              const Eigen::Vector3d& offset, double L) {
  const auto& vf = t.volume_free_surface;
  const auto& C = t.volume_cavity.centroid;
  const Eigen::Vector2d want = cav.origin ? Eigen::Vector2d(-L * vf.axis[0], -L * vf.axis[1])
                                          : Eigen::Vector2d(L * (C[0] - vf.axis[0]), L * (C[1] - vf.axis[1]));
  // To 1e-4 of the tank's scale: a meshed liquid's centroid is off its exact place by the mesh's error (3e-7 on P3).
  if ((offset.head<2>() - want).norm() > 1e-4 * L * std::max(1.0, want.norm() / L)) {
    std::ostringstream os;
    os.precision(10);
    os << "the table's free surface is a cylinder about the spin axis it was made for, so this tank sits at offset = ["
       << want.x() << ", " << want.y() << "] (the " << (cav.origin ? "table's origin" : "liquid's centroid")
       << " from the body's axis; the scene has [" << offset.x() << ", " << offset.y()
       << "]): give that offset, or make the table for this place (cavity-modes ellipsoid --fill F --axis-distance D "
          "--axis-direction DEG)";
    fail(scene, w + ".offset", os.str());
  }
}

// A table scaled to the scene must stay finite: its inertias, and each mode's frequency and couplings.
void require_finite(const Scene& scene, const std::string& w, const GeneralTank& tank) {
  if (!tank.inertia.allFinite() || !(tank.mass > 0) || !tank.geostrophic.allFinite())
    fail(scene, w + ".table", "non-physical table (volume or inertia not positive and finite)");
  for (const GeneralMode& md : tank.modes)
    if (!std::isfinite(std::abs(md.lambda)) || !md.c.allFinite() || !md.c_left.allFinite())
      fail(scene, w + ".table", "a mode scaled to the body's spin and scale overflows double precision (row " +
                                    std::to_string(md.table_row + 1) + ")");
}

}  // namespace

GeneralTank general_tank(const Scene& scene, int k, const CavitySpec& cav, const std::string& w,
                         const rc::ModeTable& t) {
  const double spin = scene.bodies[k].spin;
  require_modal(scene, w, cav, t, spin);
  const double L = cav.scale, unit = cav.density * std::pow(L, 5);  // ρL⁵: the table's inertias to kg m²
  GeneralTank tank;
  tank.three_d = t.volume_cavity.present();
  tank.mass = cav.density * L * L * L * t.volume;
  tank.scale = L;
  const Eigen::Vector3d offset = cav.offset ? Eigen::Vector3d((*cav.offset)[0], (*cav.offset)[1], 0) : Eigen::Vector3d::Zero();
  const Eigen::Vector3d centroid = tank.three_d ? Eigen::Vector3d(t.volume_cavity.centroid.data()) :
                                                  Eigen::Vector3d(0, 0, t.centroid_z);
  tank.centroid = cav.origin ? Eigen::Vector3d(offset + Eigen::Vector3d(0, 0, *cav.origin) + L * centroid) :
                               Eigen::Vector3d(offset + Eigen::Vector3d(0, 0, cav.center));
  Eigen::Matrix3d inertia, geostrophic;
  table_tensors(t, inertia, geostrophic);
  // About O_k: the parallel-axis theorem, m (|d|² I − d dᵀ).
  const Eigen::Vector3d& d = tank.centroid;
  tank.inertia = unit * inertia + tank.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  const RowCoupling about{t, d.z() / L};
  if (t.volume_free_surface.present()) {
    require_fixed_joint(scene, k, cav, w, true);
    require_axial_field(scene);
    require_on_the_spin_axis(scene, cav, w, t, offset, L);
  }
  if (t.free_surface.present()) {
    require_fixed_joint(scene, k, cav, w, false);
    require_axial_field(scene);
    // The surface re-centres on the tilted spin axis: K(O_k) more transverse inertia (docs/physics.md §2).
    const double K = unit * t.free_surface.K(about.c);
    tank.inertia(0, 0) += K;
    tank.inertia(1, 1) += K;
  }
  tank.geostrophic = unit * geostrophic;
  tank.recoil = t.volume_free_surface.present() && scene.free_chain;
  if (t.volume_free_surface.present()) add_fill_about_joint(t, about.c, L, unit, tank);
  tank.window = response_window(t, spin);
  if (cav.bands) {
    tank.coverage = add_band_modes(scene, w, k, t, unit, tank);
  } else {
    double covered = 0;
    for (const int l : kept_rows(scene, w, cav, t, about, tank.recoil, covered, tank.pruned_rows)) {
      const double bound = t.residual[l] / std::max(std::abs(t.lambda[l]), 0.1);
      if (t.volume_free_surface.present() && bound > t.tolerance * (1 + 1e-9)) {  // the survey's own test (docs/volume.md §8)
        ++tank.unsettled_rows;
        tank.worst_bound = std::max(tank.worst_bound, bound);
      }
      const Eigen::MatrixXcd H = row_tensor(t, l, about, tank, L);
      if (t.viscous())
        add_damped_row_mode(scene, w, k, l, H, spin, t.lambda[l], t.decay[l], unit, tank);
      else
        add_ideal_row_modes(k, l, H, spin, t.lambda[l], unit, tank);
    }
    tank.coverage = covered;
  }
  require_finite(scene, w, tank);
  return tank;
}

}  // namespace rc::rom
