#include "volume_table.hpp"

#include "machine_memory.hpp"
#include "mesh_broadcast.hpp"

#include "convergence.hpp"
#include "progress.hpp"
#include "table_assembly.hpp"
#include "volume_fields.hpp"
#include "volume_forms.hpp"
#include "volume_velocity.hpp"
#include "volume_zhukovsky.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace rc::modes {
namespace {

std::vector<double> flat(const Tensor3& t) {
  std::vector<double> v;
  for (const auto& row : t) v.insert(v.end(), row.begin(), row.end());
  return v;
}

std::vector<double> flat(const Eigen::Matrix3d& t) {
  std::vector<double> v;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) v.push_back(t(j, k));
  return v;
}

void add_rows(ModeTable& t, const VolumeSurvey& survey) {
  for (const auto& m : survey.modes) {
    push_ideal_volume_row(t, m.lambda, (m.H(0, 0) + m.H(1, 1)).real(), m.residual, m.spread, m.members);
    const Hermitian3 H = 0.5 * (m.H + m.H.adjoint());  // Hermitian to rounding; exactly so in the file
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        t.volume_cavity.coupling_re.push_back(H(j, k).real());
        t.volume_cavity.coupling_im.push_back(H(j, k).imag());
      }
  }
}

// The coupling's weight in λ-bands (docs/volume.md §5) from the plain Gauss rule, which sees a dense cluster as a
// whole (its light modes too, which the rows leave below the floor). /bands: each node with λ > lambda_floor by its
// transverse weight E = H_xx + H_yy, and half the λ = 0 weight's (its conjugate half is the λ < 0 side), so that the
// bands sum to A_f − J_zh as the rows' E would with every mode kept. /volume/band_*: the same nodes' H summed per band
// (the λ = 0 weight apart, as in the table's geostrophic tensor) and their trace-weighted mean λ.
void add_volume_bands(ModeTable& t, const VolumeSurvey& survey, double lambda_floor) {
  std::vector<GaussNode> nodes{{0.0, 0.5 * (survey.geostrophic(0, 0) + survey.geostrophic(1, 1)).real(), 0.0}};
  for (const auto& m : survey.rule)
    if (m.lambda > lambda_floor) nodes.push_back({m.lambda, (m.H(0, 0) + m.H(1, 1)).real(), m.residual});
  add_bands(t, band_weights(nodes));
  auto& v = t.volume_cavity;
  for (std::size_t b = 0; b < t.bands.size(); ++b) {
    Hermitian3 H = Hermitian3::Zero();
    double weighted = 0;
    for (const auto& m : survey.rule)
      if (m.lambda > lambda_floor && m.lambda >= t.bands.lo[b] &&
          (m.lambda < t.bands.hi[b] || (b + 1 == t.bands.size() && m.lambda <= t.bands.hi[b]))) {  // as band_weights
        H += m.H;
        weighted += m.H.trace().real() * m.lambda;
      }
    H = 0.5 * (H + H.adjoint()).eval();
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        v.band_coupling_re.push_back(H(j, k).real());
        v.band_coupling_im.push_back(H(j, k).imag());
      }
    v.band_lambda.push_back(H.trace().real() > 0 ? weighted / H.trace().real() : 0.0);
  }
}

// The survey keeps up to 360 velocity-space vectors (six reals per quadrature point) besides the factorisations:
// measured 2026-11-27, 120 kB per unknown at P6 (61 801 unknowns, 7.4 GB) and 80 kB at P4. A mesh that cannot fit is
// refused at once rather than killed by the system half-way.
// Under mpirun on one machine each further rank adds about 60 % of it (each holds the mesh and its own share; measured
// 2026-11-28 at P6: 7.45 GB on one rank, 5.79 GB on each of two).
// Called twice: on the linear mesh's counts (VolumeSpace's unknowns: every node but one; before gmsh spends most of a
// large mesh's time on the high-order nodes) and on the mesh itself (a read .msh file, wall layers).
void refuse_beyond_memory(std::size_t unknowns) {
  constexpr double kBytesPerUnknown = 1.3e5;
  const double need = kBytesPerUnknown * static_cast<double>(unknowns) * (1 + 0.6 * (world_ranks() - 1));
  const double have = machine_memory_bytes();
  if (have > 0 && need > have)
    throw std::runtime_error(fmt::format("the 3-D mesh has {} unknowns, about {:.0f} GB for the survey on {} rank(s), "
                                         "more than this machine's {:.0f} GB: use a larger --mesh-size, a --wall-size or "
                                         "a lower --order", unknowns, need / 1e9, world_ranks(), have / 1e9));
}

std::string solver_text(const VolumeSurvey& s) {
  return "block Lanczos Gauss rule of the coupling measure (P_H S, " + std::to_string(s.columns) +
         " basis vectors, plain; docs/volume.md §2)";
}

// /volume's tensors about the centroid (docs/volume.md §5): the frozen fluid's inertia, Zhukovsky's, their difference
// (the tensor sum rule) and the λ = 0 weight. Returns how far the survey's weights miss the sum rule: max |Σ H −
// (I_f − J_zh)| over trace(I_f − J_zh).
double set_volume_tensors(ModeTable& t, const VolumeIntegrals& fluid, const Tensor3& J, const VolumeSurvey& survey) {
  auto& v = t.volume_cavity;
  v.centroid.assign(fluid.centroid.begin(), fluid.centroid.end());
  v.inertia = flat(fluid.inertia);
  v.zhukovsky = flat(J);
  Tensor3 P{};
  double scale = 0, worst = 0;
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 3; ++k) P[j][k] = fluid.inertia[j][k] - J[j][k];
    scale += P[j][j];
  }
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(survey.total(j, k) - P[j][k]));
  v.sum_rule = flat(P);
  v.geostrophic_re = flat(Eigen::Matrix3d(survey.geostrophic.real()));
  v.geostrophic_im = flat(Eigen::Matrix3d(survey.geostrophic.imag()));
  return worst / scale;
}

}  // namespace

void push_ideal_volume_row(ModeTable& t, double lambda, double E, double residual, double spread, int members) {
  t.lambda.push_back(lambda);
  t.kappa.push_back(2 / lambda);
  t.E.push_back(E);
  t.a.push_back(std::sqrt(E / 2));
  t.N2.push_back(1.0);
  t.residual.push_back(residual);
  t.spread.push_back(spread);
  t.members.push_back(members);
}

VolumeTableResult make_volume_table(const VolumeTableRequest& request,
                                    const std::function<void(const std::string&)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  Progress lines(progress);
  lines.step("meshing the 3-D cavity");
  // Under mpirun rank 0 meshes and sends the mesh (gmsh may mesh differently on two ranks); every rank holds it
  // whole, the matrices and the velocity space are split between the ranks (volume_forms.hpp, volume_velocity.hpp).
  const int order = request.mesh.order;
  const auto check = [order](const geometry::LinearTetCounts& c) { refuse_beyond_memory(c.nodes(order) - 1); };
  VolumeSpace space(volume_mesh_on_root([&] { return geometry::mesh_volume(request.shape, request.mesh, check); },
                                        PETSC_COMM_WORLD));
  refuse_beyond_memory(space.ndof());
  lines.step(fmt::format("forms and the stiffness factorisation: {} unknowns", space.ndof()));

  const VolumeIntegrals fluid = integrate_volume(space);
  const VolumeForms forms = assemble_volume_forms(space, PETSC_COMM_WORLD);
  const StiffnessSolver M(forms.M, "stiff_", "the 3-D stiffness matrix");
  const VolumeVelocity V(space, fluid.centroid, PETSC_COMM_WORLD);
  const Tensor3 J = zhukovsky_tensor(V, M);
  VolumeTableResult out;
  lines.step("block Lanczos survey of the coupling measure");
  out.survey = survey_volume_modes(V, M, forms, request.survey);

  ModeTable& t = out.table;
  t.shape = request.shape.kind;
  t.dimensions = request.shape.dims;
  t.fe_order = space.order();
  t.mesh_h = space.mesh().size;
  t.ndof = space.ndof();
  t.volume = fluid.volume;
  t.centroid_z = fluid.centroid[2];
  t.A_f = 0.5 * (fluid.inertia[0][0] + fluid.inertia[1][1]);
  t.C_f = fluid.inertia[2][2];
  t.J_zh = 0.5 * (J[0][0] + J[1][1]);
  t.sum_rule = t.A_f - t.J_zh;
  t.solver = solver_text(out.survey);
  t.tolerance = request.survey.lambda_tolerance;
  t.normalisation = "3-D: H = c c^H with c_k = int (e_k x r).V, |V| = 1 (docs/volume.md); a = sqrt(E/2), N2 = 1";
  out.sum_rule_mismatch = set_volume_tensors(t, fluid, J, out.survey);
  t.volume_cavity.tilt = request.shape.tilt;
  add_rows(t, out.survey);
  add_volume_bands(t, out.survey, request.survey.lambda_floor);
  double kept = 0;
  for (double E : t.E) kept += E;
  t.coverage = t.sum_rule > 0 ? kept / t.sum_rule : 0;
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  t.sort_by_energy();
  t.validate();
  // The fields re-find each row's modes in the pressure pencil, whose solver (qep_solver.hpp) is sequential: under
  // mpirun rank 0 does it alone, on sequential forms of its own (it holds the whole mesh), and writes them.
  if (request.fields && is_root_rank()) {
    lines.step("fields: each row's modes re-found in the pressure pencil");
    const bool distributed = world_ranks() > 1;
    const VolumeForms sequential = distributed ? assemble_volume_forms(space, PETSC_COMM_SELF) : VolumeForms{};
    out.fields = volume_mode_fields(space, distributed ? sequential : forms, fluid.centroid, t, progress);
  }
  return out;
}

}  // namespace rc::modes
