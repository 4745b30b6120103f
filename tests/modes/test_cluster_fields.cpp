// cavity-modes --fields: the cluster field of modes/ideal/cluster_fields.hpp, checked independently of the way it
// was formed. Every comparison prints its error.
#include "cluster_fields.hpp"
#include "fe_space.hpp"
#include "poincare_forms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace rc;
using namespace rc::modes;

namespace {

constexpr double kPi = std::numbers::pi;

struct Problem {
  FESpace space;
  FluidIntegrals fluid;
  PoincareForms forms;
  Problem(const geometry::ShapeSpec& shape, int order, double size)
      : space(geometry::mesh_meridian(shape, {order, size})), fluid(integrate_fluid(space)),
        forms(assemble_poincare_forms(space, fluid.centroid_z)) {}
};

// A table with just the rows' λ (all cluster_fields reads).
ModeTable rows(std::vector<double> lambdas) {
  ModeTable t;
  t.lambda = lambdas;
  t.E.assign(lambdas.size(), 1.0);
  return t;
}

// N² = 2π ∫∫ |V_h|² r dr dz and a = π ∫∫ [z'(v_r − v_φ) − r v_z] r dr dz of the nodal field interpolated with
// the FE basis (V_h = Σ_a V(node a) N_a), by the FE quadrature: independent of the forms that normalised it.
std::pair<double, double> nodal_norm_and_a(const Problem& P, const ModeFields::Mode& m) {
  const auto& mesh = P.space.mesh();
  const int npe = mesh.nodes_per_element;
  ElementQuadrature q;
  double n2 = 0, a = 0;
  for (std::size_t e = 0; e < mesh.num_triangles(); ++e) {
    P.space.quadrature(e, q);
    for (std::size_t k = 0; k < q.w.size(); ++k) {
      double v[3] = {0, 0, 0};
      for (int b = 0; b < npe; ++b)
        for (int c = 0; c < 3; ++c) v[c] += q.N[k * npe + b] * m.V[3 * mesh.triangles[e * npe + b] + c];
      const double r = q.r[k], z = q.z[k] - P.fluid.centroid_z;
      n2 += 2 * kPi * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * r * q.w[k];
      a += kPi * (z * (v[0] - v[1]) - r * v[2]) * r * q.w[k];
    }
  }
  return {n2, a};
}

}  // namespace

// Sphere (docs/physics.md §2): the one mode is p = −z r, V = s (z, −z, −r) with s = sqrt(15 / (16π R⁵)) for N² = 1, a ≥ 0.
TEST(ClusterFields, SphereModeIsTheClosedForm) {
  const Problem P({"sphere", {{"radius", 1.0}}, {}}, 6, 0.25);
  const auto f = cluster_fields(P.space, P.forms, rows({1.0}), {});
  ASSERT_EQ(f.modes.size(), 1u);
  const auto& m = f.modes[0];
  const double s = std::sqrt(15 / (16 * kPi));
  double err_v = 0, err_p = 0;
  for (std::size_t i = 0; i < f.num_points(); ++i) {
    const double r = f.points[3 * i], z = f.points[3 * i + 2] - P.fluid.centroid_z;
    const double exact[3] = {s * z, -s * z, -s * r};
    for (int c = 0; c < 3; ++c) err_v = std::max(err_v, std::abs(m.V[3 * i + c] - exact[c]));
    err_p = std::max(err_p, std::abs(m.p[i] + s * z * r));
  }
  const auto [n2, a] = nodal_norm_and_a(P, m);
  const double a_exact = std::sqrt(4 * kPi / 15);  // E = 2a² = 8π/15
  std::printf("sphere P6 h=0.25: %d member(s), max |V - exact| / s %.2e, max |p - exact| / s %.2e, "
              "N2 of the nodal field - 1 = %.2e, a: FE %.2e nodal %.2e (rel err)\n",
              m.members, err_v / s, err_p / s, n2 - 1, std::abs(m.a - a_exact) / a_exact,
              std::abs(a - a_exact) / a_exact);
  EXPECT_EQ(m.members, 1);
  EXPECT_LE(err_v / s, 1e-4);
  EXPECT_LE(err_p / s, 1e-5);
  EXPECT_LE(std::abs(n2 - 1), 1e-6);
  EXPECT_LE(std::abs(m.a - a_exact) / a_exact, 1e-9);
  EXPECT_LE(std::abs(a - a_exact) / a_exact, 1e-6);
  EXPECT_NEAR(m.E_members, 8 * kPi / 15, 1e-9);
}

// A cluster of several eigenpairs (a wide window on a coarse P2 cylinder): W = Σ (a_l / N_l²) V_l carries
// a(W)² = Σ a_l² / N_l² = E/2 only if the members' fields are orthogonal in the kinetic-energy inner product
// (the operator is self-adjoint) and the Gram matrix of cluster_fields.cpp is right.
TEST(ClusterFields, SeveralMembersCarryTheirCouplingFlow) {
  const Problem P({"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}}, 2, 0.25);
  FieldSettings wide;
  wide.cluster_width = 0.03;
  const auto f = cluster_fields(P.space, P.forms, rows({0.9956, 0.51}), wide);
  for (const auto& m : f.modes) {
    const auto [n2, a] = nodal_norm_and_a(P, m);
    const double err = std::abs(2 * m.a * m.a - m.E_members) / m.E_members;
    std::printf("cylinder P2 lambda %.4f: %d members, |2 a(W)^2 - sum E| / sum E = %.2e; nodal field: N2 - 1 = "
                "%.2e, a rel err %.2e\n",
                m.lambda, m.members, err, n2 - 1, std::abs(a - m.a) / m.a);
    EXPECT_GE(m.members, 2);
    EXPECT_LE(err, 1e-9);
    EXPECT_LE(std::abs(n2 - 1), 0.02);  // nodal averaging of P2 gradients on a coarse mesh (measured 7e-3)
  }
}

TEST(ClusterFields, EmptySliceIsAnError) {
  const Problem P({"sphere", {{"radius", 1.0}}, {}}, 2, 0.5);
  EXPECT_THROW(cluster_fields(P.space, P.forms, rows({1.9999}), {}), std::runtime_error);
}
