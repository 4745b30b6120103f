#include "viscous_table.hpp"

#include "shear_layers.hpp"

#include "galerkin_projection.hpp"
#include "mesh_broadcast.hpp"
#include "progress.hpp"
#include "poincare_forms.hpp"
#include "taylor_hood_space.hpp"
#include "viscous_fields.hpp"
#include "viscous_memory.hpp"
#include "viscous_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace rc::modes {
namespace {

constexpr double kMinEkman = 1e-8, kMaxEkman = 1e3;
constexpr double kMaxWallSizePerLayer = 4.0;  // a wall element may span at most this many Ek^{1/2}
constexpr double kLayersThickness = 10.0;     // anisotropic wall layers cover this many Ek^{1/2}
constexpr double kNearWallZoneFrom = 1e-5;    // default_near_wall_size: the Ekman numbers where it is given

using geometry::smallest_dimension;  // the liquid's (geometry/meridian_mesh.hpp)

struct Solved {
  std::vector<ViscousMode> rows;  // one per target
  long unknowns = 0;
  GalerkinMatrices galerkin;      // the rows as a Galerkin basis (when solved with keep_block; empty otherwise)
  ModeFields fields;              // with keep_vector, on rank 0: the mesh and one field per row (viscous_fields.hpp)
};

// The imaginary part of the shift: a guess of the damped mode's decay. Boundary-layer theory gives
// decay ≈ Im λ1 Ek^{1/2} with Im λ1 between 1.4 and 3 for the modes measured (docs/viscous.md §4); 2 Ek^{1/2}
// puts the shift within ~Ek^{1/2} of the mode, far closer than the next one. Capped where the modes stop being
// boundary-layer damped (large Ek).
double decay_guess(double ekman) { return std::min(2 * std::sqrt(ekman), 0.5); }

// Two solves reached the same damped mode.
bool same_mode(const ViscousMode& a, const ViscousMode& b) {
  return std::abs(a.lambda - b.lambda) <= 1e-8 * std::abs(a.lambda);
}

// Two ideal targets can lead to the same damped mode (measured on the cone: two neighbouring unconverged ideal
// clusters, one damped mode): it is kept once, with its first target, and the drop is reported.
void drop_repeats(Solved& solved, std::vector<double>& targets, std::vector<double>& energies,
                  const std::function<void(const std::string&)>& report) {
  Solved kept;
  kept.unknowns = solved.unknowns;
  std::vector<int> kept_rows;
  std::vector<ModeFields::Mode> fields = std::move(solved.fields.modes);
  kept.fields = std::move(solved.fields);  // the mesh part, not copied
  kept.fields.modes.clear();
  std::vector<double> kept_targets, kept_energies;
  for (std::size_t i = 0; i < solved.rows.size(); ++i) {
    const auto& m = solved.rows[i];
    const bool repeat =
        std::any_of(kept.rows.begin(), kept.rows.end(), [&](const ViscousMode& k) { return same_mode(k, m); });
    if (repeat) {
      if (report)
        report(fmt::format("the ideal mode at lambda = {:.6f} continues into the damped mode {:.6f}{:+.6f}i, already "
                           "in the table: kept once", targets[i], m.lambda.real(), m.lambda.imag()));
      continue;
    }
    kept.rows.push_back(m);
    kept_rows.push_back(static_cast<int>(i));
    if (i < fields.size()) kept.fields.modes.push_back(std::move(fields[i]));
    kept_targets.push_back(targets[i]);
    kept_energies.push_back(energies[i]);
  }
  if (solved.galerkin.gram.size() > 0) {
    kept.galerkin.gram = solved.galerkin.gram(kept_rows, kept_rows);
    kept.galerkin.viscous = solved.galerkin.viscous(kept_rows, kept_rows);
  }
  solved = std::move(kept);
  targets = std::move(kept_targets);
  energies = std::move(kept_energies);
}

// The damped continuation of one ideal mode (λ0, E0): the mode nearest the complex target, unless its coupling is
// under half of E0 — then a neighbour took its place, and the one of largest |E_c| among `settings.pairs` modes
// near the target is taken. (Asking for one mode first halves the Krylov–Schur work: 0.8 s against 1.8 s on the
// Ek = 1e-4 sphere.)
ViscousMode continue_mode(const ViscousForms& forms, double lambda0, double E0, double ekman,
                          const ViscousSolveSettings& settings) {
  const std::complex<double> target(lambda0, decay_guess(ekman));
  ViscousSolveSettings one = settings;
  one.pairs = 1;
  const auto nearest = viscous_modes_near(forms, target, one);
  if (std::abs(nearest.front().residue) >= 0.5 * E0) return nearest.front();
  const auto near = viscous_modes_near(forms, target, settings);
  return *std::max_element(near.begin(), near.end(), [](const auto& a, const auto& b) {
    return std::abs(a.residue) < std::abs(b.residue);
  });
}

// A refinement round's mesh too large for the machine (thrown before its assembly): a round is allowed 60 % of the
// machine's memory (all ranks together), and the table is then written without it, with a note.
struct BeyondMemory : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What solve_targets does with a mesh beyond memory: the mesh the user asked for is refused in one line against the
// memory free now (viscous_memory.hpp), a refinement round throws BeyondMemory, and a mesh coarser than one that was
// solved is not checked.
enum class MemoryLimit { refuse, round, unchecked };

// Shares out the targets' rows solved on their own ranks (split: rank r solved every ranks-th target from r): the
// scalars summed over the ranks, and with keep_block each row's block vector broadcast from its rank, so that every
// rank holds every row on its own forms (PETSC_COMM_SELF) as the serial solve would.
void share_split_rows(std::vector<ViscousMode>& rows, bool blocks) {
  const int ranks = world_ranks();
  constexpr int kScalars = 7;
  std::vector<double> mine(kScalars * rows.size(), 0.0), all(mine.size(), 0.0);
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  for (std::size_t i = static_cast<std::size_t>(rank); i < rows.size(); i += static_cast<std::size_t>(ranks)) {
    const ViscousMode& m = rows[i];
    const double v[kScalars] = {m.lambda.real(), m.lambda.imag(), m.residue.real(), m.residue.imag(),
                                m.offset.real(),  m.offset.imag(), m.residual};
    std::copy(v, v + kScalars, mine.begin() + kScalars * static_cast<long>(i));
  }
  MPI_Allreduce(mine.data(), all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double* v = all.data() + kScalars * i;
    rows[i].lambda = {v[0], v[1]};
    rows[i].residue = {v[2], v[3]};
    rows[i].offset = {v[4], v[5]};
    rows[i].residual = v[6];
  }
  if (!blocks) return;
  PetscInt n = 0;
  for (const auto& r : rows)
    if (r.block) petsc_check(VecGetSize(*r.block, &n), "VecGetSize");
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPIU_INT, MPI_MAX, PETSC_COMM_WORLD);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const int owner = static_cast<int>(i % static_cast<std::size_t>(ranks));
    if (owner != rank) {
      rows[i].block = std::make_shared<PVec>();
      petsc_check(VecCreateSeq(PETSC_COMM_SELF, n, rows[i].block->out()), "VecCreateSeq");
    }
    PetscScalar* a = nullptr;
    petsc_check(VecGetArray(*rows[i].block, &a), "VecGetArray");
    MPI_Bcast(a, static_cast<int>(n), MPIU_SCALAR, owner, PETSC_COMM_WORLD);
    petsc_check(VecRestoreArray(*rows[i].block, &a), "VecRestoreArray");
  }
}

// One damped mode per target (continue_mode). Under mpirun with several targets and no fields the targets, not the
// matrices, are shared out: each rank assembles the forms on its own (PETSC_COMM_SELF) and solves every ranks-th
// target (measured: MUMPS's factorisation of one matrix does not scale on this machine's two ranks, docs/benchmarks.md
// "Complex factorisation"). `limit` says what a mesh beyond memory (each rank's unknowns times the ranks that hold a
// copy) meets before anything is assembled (MemoryLimit).
Solved solve_targets(const geometry::ShapeSpec& shape, geometry::MeshOptions& mesh, double centroid_z,
                     const ViscousTableSettings& s, const std::vector<double>& targets,
                     const std::vector<double>& energies,
                     const std::function<void(std::size_t, std::size_t)>& progress, MemoryLimit limit) {
  const int ranks = world_ranks();
  const bool split = ranks > 1 && targets.size() > 1 && !s.solve.keep_vector;
  TaylorHoodSpace space(mesh_on_root([&] { return viscous_mesh(shape, mesh); }, PETSC_COMM_WORLD));
  const long copies = split ? ranks : 1;
  if (limit == MemoryLimit::refuse) refuse_viscous_beyond_memory(2L * space.size(), copies, mesh_text(mesh));
  const long most = most_viscous_unknowns(0.6);
  if (limit == MemoryLimit::round && most > 0 && 2L * space.size() * copies > most)
    throw BeyondMemory(fmt::format("{} real unknowns{}, about {:.1f} GB", 2L * space.size(),
                                   split ? fmt::format(" on each of {} ranks", ranks) : std::string(),
                                   2.0 * space.size() * copies * kBytesPerViscousUnknown / 1e9));
  const ViscousForms forms =
      assemble_viscous_forms(space, centroid_z, s.ekman, split ? PETSC_COMM_SELF : PETSC_COMM_WORLD);
  Solved out;
  out.unknowns = 2L * forms.complex_size;
  const bool fields = s.solve.keep_vector && is_root_rank();
  if (fields) out.fields = viscous_fields_mesh(space);
  out.fields.damped = true;
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  out.rows.resize(targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i) {
    if (split && static_cast<int>(i % static_cast<std::size_t>(ranks)) != rank) continue;
    out.rows[i] = continue_mode(forms, targets[i], energies[i], s.ekman, s.solve);
    if (fields) out.fields.modes.push_back(viscous_mode_field(space, out.rows[i]));
    out.rows[i].vector = {};  // the field holds what is needed
    progress(i + 1, targets.size());
  }
  if (split) share_split_rows(out.rows, s.solve.keep_block);
  if (s.solve.keep_block) {
    std::vector<Vec> blocks;
    for (const auto& r : out.rows) blocks.push_back(*r.block);
    out.galerkin = project_on_modes(forms, blocks);
    for (auto& r : out.rows) r.block.reset();
  }
  return out;
}

// The table's /galerkin block in the rows' order (sort_by_energy permutes it with them).
void set_galerkin(ModeTable& t, const Solved& solved) {
  const auto& g = solved.galerkin;
  const Eigen::Index n = g.gram.rows();
  if (n == 0) return;
  std::vector<std::complex<double>> lambda;
  for (const auto& m : solved.rows) lambda.push_back(m.lambda);
  for (Eigen::Index l = 0; l < n; ++l)
    for (Eigen::Index k = 0; k < n; ++k) {
      t.galerkin.gram_re.push_back(g.gram(l, k).real());
      t.galerkin.gram_im.push_back(g.gram(l, k).imag());
      t.galerkin.viscous_re.push_back(g.viscous(l, k).real());
      t.galerkin.viscous_im.push_back(g.viscous(l, k).imag());
    }
  t.galerkin.dissipation_mismatch = dissipation_mismatch(g, lambda);
}

double relative(std::complex<double> a, std::complex<double> b) { return std::abs(a - b) / std::abs(b); }

}  // namespace

// The default interior element size of a filled sphere or cylinder at low Ekman numbers. The forced flow's internal
// shear layers (beams from the corners and the critical latitudes, about Ek^{1/3} R wide away from their sources:
// Kerswell 1995, "On the internal shear layers spawned by the critical regions in oscillatory Ekman boundary layers")
// need interior elements a few times their width at order 6; d/8 stops resolving them below an Ekman number that
// depends on the shape. Measured at the spacecraft's nutation (s = −0.2437; docs/viscous.md, "Interior size at low
// Ekman numbers"): Im R of the full cylinder (2h/a = 2) at Ek = 1e-6 3.3 % off at h = 1/8, 0.9 % at 0.088, 0.01 % from
// the mesh with every size halved at 1/16; the full sphere at Ek = 1e-7 2.5 %, 0.14 %, 7.5e-6 from the spectral
// method's at the same sizes. So h = C Ek^{1/3} R, C = 6.25 (cylinder) and 13.5 (sphere): 1/16 at those Ekman numbers,
// d/8 above 8e-6 and 7.9e-7. Partially filled tanks and rings keep their fraction of d (measured converged there:
// docs/trust.md).
namespace {
double shear_layer_interior_size(const geometry::ShapeSpec& shape, double ekman) {
  const bool filled = !shape.dims.count("free_radius") && !shape.dims.count("inner_radius");
  const double C = !filled ? 0.0 : shape.kind == "cylinder" ? 6.25 : shape.kind == "sphere" ? 13.5 : 0.0;
  return C > 0 ? C * std::cbrt(ekman) * shape.dims.at("radius") : std::numeric_limits<double>::infinity();
}

// The default interior of a liquid whose smallest dimension is d. A partially filled cylinder's liquid (an annulus
// between straight walls and a coaxial free surface, with or without a rod) converges its forced response on d/4:
// measured on the spacecraft's nutation decay (docs/viscous.md, "Interior size of a partially filled cylinder"; the
// tables' at Ek = 1e-5 and 1e-6, fills 0.3 to 0.8, forced solves on the table's mesh at 1e-7), within 0.08 % of the
// mesh-converged references, in a third of d/8's time. Below Ek = 1e-7, where nothing is measured, it shrinks with the shear layers' width Ek^{1/3}
// (54 Ek^{1/3} d is d/4 at 1e-7). Every other liquid keeps d/8.
double default_interior(const geometry::ShapeSpec& shape, double ekman, double d) {
  if (shape.kind == "cylinder" && shape.dims.count("free_radius")) return std::min(0.25, 54 * std::cbrt(ekman)) * d;
  return d / 8;
}
}  // namespace

geometry::MeshOptions viscous_mesh_defaults(const geometry::ShapeSpec& shape, double ekman,
                                            geometry::MeshOptions mesh) {
  if (!(ekman >= kMinEkman && ekman <= kMaxEkman))
    throw std::runtime_error(fmt::format("--ekman {} is outside [{:g}, {:g}] (below 1e-8 the Ekman layers need more "
                                         "than this machine: docs/viscous.md, \"Limits\")", ekman, kMinEkman,
                                         kMaxEkman));
  geometry::check_shape(shape);
  const double layer = std::sqrt(ekman), d = smallest_dimension(shape);
  if (mesh.order == 0) mesh.order = 6;
  if (mesh.order < 2) throw std::runtime_error("--ekman needs --order >= 2 (Taylor-Hood P_k/P_(k-1) elements)");
  if (mesh.radial_size > 0) throw std::runtime_error("--radial-size (structured meshes) does not apply with --ekman");
  if (mesh.size == 0 && d > 0)
    mesh.size = std::min(default_interior(shape, ekman, d), shear_layer_interior_size(shape, ekman));
  if (mesh.wall_size == 0) mesh.wall_size = layer;
  if (mesh.size > 0) mesh.wall_size = std::min(mesh.wall_size, mesh.size);
  // Layers at most half as thick as the interior elements (gmsh's layers invert otherwise); beyond them the
  // interior elements carry the rest of a thick Ekman layer. gmsh's BoundaryLayer field along the wall (sphere,
  // spheroid, cylinder and user sections); the cone builds its layers into the CAD model (gmsh 4.8's field crashed or
  // inverted at its apex; geometry/shapes.cpp). Where the field inverts an element, viscous_mesh falls back to the
  // isotropic grading. (Sections had only the grading until 2026-11-26: Kore's shell at Ek = 1e-3 took 171 400
  // unknowns and 14 s, with layers 38 236 and 3 s: docs/benchmarks.md, "Kore".)
  const double interior = mesh.size > 0 ? mesh.size : 0.125 * d;
  mesh.wall_layer = std::min(kLayersThickness * layer, interior / 2);
  if (mesh.wall_layer <= mesh.wall_size) mesh.wall_layer = 0;
  if (mesh.wall_size > kMaxWallSizePerLayer * layer)
    throw std::runtime_error(fmt::format("--wall-size {:g} does not resolve the Ekman layer at Ek = {:g} (thickness "
                                         "{:.3g}): use --wall-size {:.3g} or less", mesh.wall_size, ekman, layer,
                                         kMaxWallSizePerLayer * layer));
  return mesh;
}

double default_near_wall_size(const geometry::ShapeSpec& shape, double ekman) {
  const bool zoned = shape.kind == "cylinder" || shape.kind == "spheroid";
  return zoned && ekman <= kNearWallZoneFrom ? std::cbrt(ekman * smallest_dimension(shape)) : 0.0;
}

geometry::MeshOptions refined_viscous_mesh(const geometry::ShapeSpec& shape, double ekman,
                                           const geometry::MeshOptions& mesh) {
  geometry::MeshOptions finer = mesh;
  // The Ek^{1/3} layers' thickness, (ν/Ω)^{1/3} d^{1/3} with lengths in the table's unit: Stewartson's E_d^{1/3} d
  // (Stewartson 1957, "On almost rigid rotations"; docs/viscous.md, "Near-wall zone").
  const double zone = std::cbrt(ekman * smallest_dimension(shape));
  if (mesh.wall_layer > 0 && mesh.near_wall_size == 0 && 2 * zone < mesh.size / 2) {
    finer.near_wall_size = 2 * zone;
    return finer;
  }
  if (mesh.wall_layer > 0 && mesh.near_wall_size > 0.51 * zone) {
    finer.near_wall_size = mesh.near_wall_size / 2;
    return finer;
  }
  return halved_viscous_mesh(ekman, mesh);
}

geometry::MeshOptions halved_viscous_mesh(double ekman, const geometry::MeshOptions& mesh) {
  geometry::MeshOptions finer = mesh;
  finer.size /= 2;
  finer.wall_size /= 2;
  finer.band_size /= 2;
  finer.near_wall_size /= 2;
  if (finer.wall_layer > 0) finer.wall_layer = std::min(kLayersThickness * std::sqrt(ekman), finer.size / 2);
  if (finer.wall_layer <= finer.wall_size) finer.wall_layer = 0;
  return finer;
}

namespace {

// The ideal table's frozen-fluid data with the damped modes as its rows (residues as complex couplings).
ModeTable viscous_rows(const ModeTable& ideal, const Solved& fine, double ekman, const geometry::MeshOptions& mesh) {
  ModeTable t = ideal;
  t.ekman = ekman;
  t.fe_order = mesh.order;
  t.mesh_h = mesh.size;
  t.mesh_h_radial = 0;
  t.mesh_h_wall = mesh.wall_size;
  t.mesh_h_near_wall = mesh.near_wall_size;
  t.ndof = fine.unknowns;
  t.bands = {};
  t.kappa.clear(); t.lambda.clear(); t.E.clear(); t.a.clear(); t.N2.clear(); t.residual.clear();
  t.spread.clear(); t.members.clear(); t.dlambda.clear(); t.dE.clear(); t.converged.clear();
  t.free_surface.t.clear();
  t.free_surface.t_imag.clear();
  double kept = 0;
  for (const auto& m : fine.rows) {
    const std::complex<double> a = std::sqrt(m.residue / 2.0);
    t.lambda.push_back(m.lambda.real());
    t.kappa.push_back(2 / m.lambda.real());
    t.decay.push_back(m.lambda.imag());
    t.E.push_back(m.residue.real());
    t.E_imag.push_back(m.residue.imag());
    t.a.push_back(a.real());
    t.a_imag.push_back(a.imag());
    t.N2.push_back(1.0);
    t.residual.push_back(std::max(m.residual, std::numeric_limits<double>::epsilon()));  // as add_modes
    if (t.free_surface.present()) {  // a + c t about a joint c below the centroid: t with a's branch (Re a ≥ 0)
      t.free_surface.t.push_back(m.offset.real());
      t.free_surface.t_imag.push_back(m.offset.imag());
    }
    kept += m.residue.real();
  }
  t.coverage = t.sum_rule > 0 ? kept / t.sum_rule : 1.0;
  set_galerkin(t, fine);
  t.normalisation = "rho = 1, omega0 = 1; each mode x is normalised to x^T M x = 1 (complex symmetric, unconjugated), "
                    "a + i a_imag = (e1 x r, V) / (i sqrt(2 pi)) and E + i E_imag = 2 (a + i a_imag)^2: the residue of "
                    "the fluid's response at lambda + i decay (docs/viscous.md)";
  return t;
}

std::string viscous_solver_text(const geometry::MeshOptions& mesh, const std::string& ideal_solver) {
  const std::string near = mesh.near_wall_size > 0 ? fmt::format(", then {:.3g} growing by {:g} per unit distance",
                                                                  mesh.near_wall_size, mesh.near_wall_growth)
                                                    : std::string();
  const std::string wall = mesh.wall_layer > 0
                               ? fmt::format("anisotropic wall layers (first {:.3g}, ratio {:g}, {:.3g} thick{})",
                                             mesh.wall_size, 1 + mesh.wall_growth, mesh.wall_layer, near)
                               : fmt::format("isotropic wall grading (wall {:.3g}, growth {:g})", mesh.wall_size,
                                             mesh.wall_growth);
  return fmt::format("Taylor-Hood P{}/P{}, interior size {:.3g}, {}; real 2x2 block form, SLEPc Krylov-Schur "
                     "shift-and-invert (MUMPS complex LU) at each ideal mode's lambda; ideal targets: {}",
                     mesh.order, mesh.order - 1, mesh.size, wall, ideal_solver);
}

// Each row against the same target's mode on the reference mesh (described by `reference`).
void add_viscous_convergence(ModeTable& t, const Solved& fine, const Solved& ref, const std::string& reference,
                             double tolerance) {
  t.convergence_reference = reference;
  t.convergence_tolerance = tolerance;
  t.dlambda.clear(); t.dE.clear(); t.converged.clear();
  for (std::size_t i = 0; i < fine.rows.size(); ++i) {
    const double dl = relative(ref.rows[i].lambda, fine.rows[i].lambda);
    const double dE = relative(ref.rows[i].residue, fine.rows[i].residue);
    t.dlambda.push_back(dl);
    t.dE.push_back(dE);
    t.converged.push_back(dl <= tolerance && dE <= tolerance ? 1 : 0);
  }
}

// The solved modes' fields in the rows' order after sort_by_energy (a stable sort by E descending).
void fields_in_row_order(Solved& fine, ModeFields& fields) {
  std::vector<std::size_t> order(fine.rows.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return fine.rows[i].residue.real() > fine.rows[j].residue.real(); });
  std::vector<ModeFields::Mode> modes = std::move(fine.fields.modes);
  fields = std::move(fine.fields);
  fields.modes.clear();
  for (std::size_t k = 0; k < order.size(); ++k) {
    fields.modes.push_back(std::move(modes[order[k]]));
    fields.modes.back().row = k;
  }
}

bool every_row_converged(const ModeTable& t) {
  return std::all_of(t.converged.begin(), t.converged.end(), [](int c) { return c == 1; });
}

bool has_repeats(const Solved& solved) {
  for (std::size_t i = 0; i < solved.rows.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (same_mode(solved.rows[j], solved.rows[i])) return true;
  return false;
}

// The refinement rounds of one table (ViscousTableSettings::refinements) and their progress lines.
struct Rounds {
  const geometry::ShapeSpec& shape;
  const ModeTable& ideal;
  const ViscousTableSettings& s;
  Progress& lines;

  std::function<void(std::size_t, std::size_t)> progress(std::string what) const {
    return [this, what](std::size_t done, std::size_t total) {
      lines.step(fmt::format("{} mode {}/{}", what, done, total), done, total);
    };
  }

  // While a row is not converged: the table made again on the refined mesh, flagged against the round before
  // (`fine`, `mesh` and `t` become the last round's). A round beyond the machine's memory, or one where two targets
  // reach the same damped mode, ends them, reported. Returns the rounds made.
  int refine_until_converged(const std::vector<double>& targets, const std::vector<double>& energies,
                             geometry::MeshOptions& mesh, Solved& fine, ModeTable& t) const {
    int done = 0;
    for (; done < s.refinements && !every_row_converged(t); ++done) {
      geometry::MeshOptions finer = refined_viscous_mesh(shape, s.ekman, mesh);
      const std::string label = fmt::format("refinement round {}", done + 1);
      lines.step(fmt::format("{} ({})", label, mesh_text(finer)));
      Solved next;
      try {
        next = solve_targets(shape, finer, ideal.centroid_z, s, targets, energies, progress(label),
                             MemoryLimit::round);
      } catch (const BeyondMemory& e) {
        lines.note(fmt::format("{} not made: its mesh ({}) has {}, more than 60 % of this machine's memory", label,
                           mesh_text(finer), e.what()));
        break;
      }
      if (has_repeats(next)) {
        lines.note(fmt::format("{} dropped: two targets reached the same damped mode on its mesh", label));
        break;
      }
      const std::string before = done == 0 ? "the first mesh" : fmt::format("refinement round {}", done);
      t = viscous_rows(ideal, next, s.ekman, finer);
      add_viscous_convergence(t, next, fine, fmt::format("{} ({})", before, mesh_text(mesh)), s.convergence_tolerance);
      fine = std::move(next);
      mesh = finer;
      const auto ok = std::count(t.converged.begin(), t.converged.end(), 1);
      lines.note(fmt::format("{}: {}, {} real unknowns: {} of {} rows converged against {}", label, mesh_text(mesh),
                         fine.unknowns, ok, t.converged.size(), before));
    }
    return done;
  }
};

}  // namespace

ModeTable compute_viscous_table(const geometry::ShapeSpec& shape, const ViscousTableSettings& settings,
                                const ModeTable& ideal, const std::function<void(const std::string&)>& report,
                                ModeFields* fields) {
  ViscousTableSettings s = settings;
  s.solve.keep_vector = fields != nullptr;
  s.solve.keep_block = true;  // the table's /galerkin matrices
  const auto start = std::chrono::steady_clock::now();
  geometry::MeshOptions mesh = viscous_mesh_defaults(shape, s.ekman, s.mesh);
  std::vector<double> targets = ideal.lambda, energies = ideal.E;
  if (targets.empty()) throw std::runtime_error("the ideal table has no mode to continue");
  if (s.shear_layers_ekman > 0) add_shear_layer_bands(shape, s.shear_layers_ekman, targets, mesh);

  Progress lines(report);  // at least every 5 s, with the time left (progress.hpp)
  const Rounds rounds{shape, ideal, s, lines};
  Solved fine = solve_targets(shape, mesh, ideal.centroid_z, s, targets, energies, rounds.progress("viscous"),
                              MemoryLimit::refuse);
  drop_repeats(fine, targets, energies, report);

  ModeTable t = viscous_rows(ideal, fine, s.ekman, mesh);
  int refined = 0;
  if (s.check_convergence) {
    geometry::MeshOptions coarse = mesh;
    coarse.size *= 2;
    coarse.wall_size *= 2;
    coarse.band_size *= 2;
    coarse.near_wall_size *= 2;
    ViscousTableSettings check = s;
    check.solve.keep_vector = false;
    check.solve.keep_block = false;
    const Solved ref = solve_targets(shape, coarse, ideal.centroid_z, check, targets, energies,
                                     rounds.progress("convergence check"), MemoryLimit::unchecked);
    add_viscous_convergence(t, fine, ref,
                            fmt::format("order {} with the interior and wall sizes doubled (h = {:.3g}, wall {:.3g})",
                                        coarse.order, coarse.size, coarse.wall_size),
                            s.convergence_tolerance);
    refined = rounds.refine_until_converged(targets, energies, mesh, fine, t);
  }
  t.solver = viscous_solver_text(mesh, ideal.solver);
  if (refined > 0)
    t.solver += fmt::format("; {} refinement round{} while a row was not converged (docs/viscous.md, \"Refinement "
                            "rounds\")", refined, refined > 1 ? "s" : "");
  t.tolerance = s.solve.tolerance;
  if (fields && is_root_rank()) fields_in_row_order(fine, *fields);
  t.sort_by_energy();
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

}  // namespace rc::modes
