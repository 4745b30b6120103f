// The ideal fluid's response R(σ) = Σ E_l/(σ − λ_l) by forced solves on the mesh (ideal/ideal_response.hpp, no
// modes) against three independent computations: the sphere's and the oblate spheroid's closed forms (one
// coupling mode each), the separable cylinder's sum over every eigenpair (separable_cylinder.hpp), and a
// separable table's kept modes plus its exact band weights, within the rigorous bound of placing each band's
// left-out weight at its centre. Every comparison prints its error.
#include "cavity_response.hpp"
#include "cavity_table.hpp"
#include "closed_forms.hpp"
#include "discretisation.hpp"
#include "ideal_response.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

using namespace rc::modes;
using C = std::complex<double>;

namespace {

// Off the real axis on both sides, near the modes, and beyond |σ| = 2 on the real axis.
const std::vector<C> kSigmas = {{0.5, 0.2}, {-1.0, 0.5}, {1.05, 0.05}, {-0.3, -0.4}, {0.1, 0.1}, {2.5, 0.0}};

std::vector<C> mesh_response(const rc::geometry::ShapeSpec& shape, double size = 0) {
  rc::geometry::MeshOptions mesh;
  mesh.order = 6;
  mesh.size = size;
  const auto t0 = std::chrono::steady_clock::now();
  const Discretisation d(shape, mesh_method_defaults(shape, mesh));
  auto R = ideal_response(d.velocity, d.forms, kSigmas);
  std::printf("%s: P6, h = %g, %d dofs, %zu forced solves in %.2f s\n", shape.kind.c_str(), d.space.mesh().size,
              d.space.ndof(), kSigmas.size(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return R;
}

double single_pole_error(const rc::geometry::ShapeSpec& shape, const exact::SpheroidValues& v) {
  const auto R = mesh_response(shape);
  double worst = 0;
  for (std::size_t k = 0; k < kSigmas.size(); ++k) {
    const C want = v.mode.E / (kSigmas[k] - v.mode.lambda);
    const double err = std::abs(R[k] - want) / std::abs(want);
    std::printf("  sigma = %+.2f%+.2fi: R = %+.12f%+.12fi, closed form %+.12f%+.12fi, rel. error %.1e\n",
                kSigmas[k].real(), kSigmas[k].imag(), R[k].real(), R[k].imag(), want.real(), want.imag(), err);
    worst = std::max(worst, err);
  }
  return worst;
}

}  // namespace

TEST(IdealResponse, SphereIsItsSpinOverPole) {
  // R = (8π/15)/(σ − 1): the sphere's only coupling mode (closed forms, docs/modes.md).
  EXPECT_LE(single_pole_error({"sphere", {{"radius", 1.0}}, {}}, exact::spheroid(1, 1)), 1e-8);
}

TEST(IdealResponse, OblateSpheroidIsItsCouplingModePole) {
  EXPECT_LE(single_pole_error({"spheroid", {{"a", 1.0}, {"c", 0.5}}, {}}, exact::spheroid(1, 0.5)), 1e-8);
}

TEST(IdealResponse, CylinderIsTheSeparableSumOverEveryEigenpair) {
  // Both sides converged (docs/viscous.md, "Ideal response"): the forced solves on P6 of size 1/16, the separable
  // sum at order 8 with 12 x 24 elements (it moves by <= 1e-11 on a grid twice as fine, 1e-9 at 0.1+0.1i). Near
  // sigma = 0, where the cylinder's short-wave modes accumulate, the unstructured mesh converges more slowly
  // (3.6e-6 at size 1/8, 2.4e-7 at 1/16), so that point has its own bound.
  const rc::geometry::ShapeSpec cyl{"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}};
  const auto R = mesh_response(cyl, 0.0625);
  ResponseRequest req;
  req.shape = cyl;
  req.separable = true;
  req.mesh.order = 8;
  req.mesh.size = 0.1;
  req.mesh.radial_size = 0.1;
  req.sigmas = kSigmas;
  const auto S = compute_cavity_response(req);
  std::printf("  against: %s\n", S.method.c_str());
  for (std::size_t k = 0; k < kSigmas.size(); ++k) {
    const double err = std::abs(R[k] - S.R[k]) / std::abs(S.R[k]);
    std::printf("  sigma = %+.2f%+.2fi: forced %+.12f%+.12fi, mode sum %+.12f%+.12fi, rel. difference %.1e\n",
                kSigmas[k].real(), kSigmas[k].imag(), R[k].real(), R[k].imag(), S.R[k].real(), S.R[k].imag(), err);
    const bool near_accumulation = std::abs(kSigmas[k]) < 0.2;
    EXPECT_LE(err, near_accumulation ? 1e-6 : 1e-8);
  }
}

TEST(IdealResponse, CylinderTableWithItsBandsBracketsTheResponse) {
  // A 20-mode separable table: Σ_kept E/(σ − λ) plus each band's left-out weight w_b placed at the band's centre
  // c_b. For λ in [lo, hi], |1/(σ − λ) − 1/(σ − c_b)| ≤ ½(hi − lo) / (dist(σ, [lo, hi]) |σ − c_b|), so the
  // estimate is off by at most Σ_b w_b ½(hi − lo) / (dist · |σ − c_b|): a bound that the forced solve must meet.
  const rc::geometry::ShapeSpec cyl{"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}};
  TableRequest treq;
  treq.method = TableMethod::separable;
  treq.shape = cyl;
  treq.selection.modes = 20;
  treq.check_convergence = false;
  const auto t = compute_mode_table(treq);
  ASSERT_GT(t.bands.size(), 0u);
  const auto R = mesh_response(cyl);
  for (std::size_t k = 0; k < kSigmas.size(); ++k) {
    const C s = kSigmas[k];
    C modes = 0;
    for (std::size_t i = 0; i < t.size(); ++i) modes += t.E[i] / (s - t.lambda[i]);
    C rest = 0;
    double bound = 0, left = 0;
    for (std::size_t b = 0; b < t.bands.size(); ++b) {
      double w = t.bands.E[b];
      for (std::size_t i = 0; i < t.size(); ++i)
        if (t.lambda[i] >= t.bands.lo[b] && t.lambda[i] < t.bands.hi[b]) w -= t.E[i];
      w = std::max(w, 0.0);
      left += w;
      const double c = 0.5 * (t.bands.lo[b] + t.bands.hi[b]);
      const double dist = s.imag() != 0 ? std::abs(s.imag())
                                        : std::max(t.bands.lo[b] - s.real(), s.real() - t.bands.hi[b]);
      rest += w / (s - c);
      bound += w * 0.5 * (t.bands.hi[b] - t.bands.lo[b]) / (dist * std::abs(s - c));
    }
    const double diff = std::abs(R[k] - (modes + rest));
    std::printf("  sigma = %+.2f%+.2fi: |forced - (20 modes + bands)| = %.2e (bound %.2e; modes alone %.2e; "
                "left-out weight %.3e)\n", s.real(), s.imag(), diff, bound, std::abs(R[k] - modes), left);
    EXPECT_LE(diff, bound + 1e-8 * std::abs(R[k]));
  }
}

TEST(IdealResponse, RealSigmaInsideTheSpectrumIsRefused) {
  const rc::geometry::ShapeSpec sph{"sphere", {{"radius", 1.0}}, {}};
  rc::geometry::MeshOptions mesh;
  mesh.order = 2;
  mesh.size = 0.5;
  const Discretisation d(sph, mesh);
  EXPECT_THROW(ideal_response(d.velocity, d.forms, {C(0.5, 0)}), std::invalid_argument);
  EXPECT_THROW(ideal_response(d.velocity, d.forms, {C(2, 0)}), std::invalid_argument);
}
