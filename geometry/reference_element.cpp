// Reference triangle and edge: gmsh's own Gauss rules and Lagrange bases, so that the local node
// order is by construction the one of the meshes gmsh writes.
#include "gmsh_session.hpp"
#include "meridian_mesh.hpp"
#include "volume_mesh.hpp"

#include <gmsh.h>

#include <map>
#include <mutex>
#include <utility>

namespace rc::geometry {
namespace {

constexpr int kMaxOrder = 6;
// gmsh 4.8's Gauss line rules stop at degree 31 (16 points) and crash above; the collapsed
// triangle rule needs degree + 1. 30 is far beyond any FE need.
constexpr int kMaxDegree = 30;

void check_arguments(const char* what, int order, int degree) {
  if (order < 1 || order > kMaxOrder)
    throw std::runtime_error(std::string(what) + ": order " + std::to_string(order) + " is outside 1.." +
                             std::to_string(kMaxOrder));
  if (degree < 0 || degree > kMaxDegree)
    throw std::runtime_error(std::string(what) + ": quadrature degree " + std::to_string(degree) +
                             " is outside 0.." + std::to_string(kMaxDegree));
}

struct GmshRule {
  std::vector<double> uvw, weights;  // points as (u, v, w) triplets, as gmsh takes them
};

struct Basis {
  std::vector<double> N, dN;  // dN has 3 components (u, v, w) per basis function
};

GmshRule gauss_rule(int element_type, int degree) {
  GmshRule rule;
  gmsh::model::mesh::getIntegrationPoints(element_type, "Gauss" + std::to_string(degree), rule.uvw, rule.weights);
  return rule;
}

constexpr int kMaxGmshTriangleDegree = 8;

// gmsh 4.8's tabulated triangle rules above degree 8 are only accurate to ~5e-12, and some put
// points outside the triangle (degrees 11, 15, 16, 18, 20) or are wrong (degree 20: 3e-8), which
// would put quadrature points at r < 0 near the axis. Above degree 8 we use the collapsed
// (Duffy) product of gmsh's Gauss-Legendre line rules instead: u = s (1 - t), v = t,
// du dv = (1 - t) ds dt, exact to `degree` with the t-rule one degree higher; positive weights,
// points strictly inside, machine accuracy.
GmshRule triangle_rule(int degree) {
  if (degree <= kMaxGmshTriangleDegree)
    return gauss_rule(gmsh::model::mesh::getElementType("Triangle", 1), degree);
  const int line = gmsh::model::mesh::getElementType("Line", 1);
  const GmshRule gs = gauss_rule(line, degree), gt = gauss_rule(line, degree + 1);
  GmshRule rule;
  for (std::size_t j = 0; j < gt.weights.size(); ++j) {
    const double t = 0.5 * (gt.uvw[3 * j] + 1.0), wt = 0.5 * gt.weights[j];
    for (std::size_t i = 0; i < gs.weights.size(); ++i) {
      const double s = 0.5 * (gs.uvw[3 * i] + 1.0), ws = 0.5 * gs.weights[i];
      rule.uvw.insert(rule.uvw.end(), {s * (1.0 - t), t, 0.0});
      rule.weights.push_back(ws * wt * (1.0 - t));
    }
  }
  return rule;
}

Basis lagrange_basis(int element_type, const std::vector<double>& uvw) {
  Basis b;
  int components = 0, orientations = 0;
  gmsh::model::mesh::getBasisFunctions(element_type, uvw, "Lagrange", components, b.N, orientations);
  gmsh::model::mesh::getBasisFunctions(element_type, uvw, "GradLagrange", components, b.dN, orientations);
  return b;
}

ReferenceTriangle build_triangle(int order, int degree) {
  const auto [g, b] = detail::with_gmsh("reference_triangle", [&](detail::GmshSession&) {
    GmshRule rule = triangle_rule(degree);
    Basis basis = lagrange_basis(gmsh::model::mesh::getElementType("Triangle", order), rule.uvw);
    return std::pair{rule, basis};
  });
  ReferenceTriangle t;
  t.order = order;
  t.nodes_per_element = (order + 1) * (order + 2) / 2;
  t.weights = g.weights;  // gmsh's reference triangle is ours: weights already sum to 1/2
  t.N = b.N;
  const std::size_t nq = g.weights.size(), na = t.nodes_per_element;
  for (std::size_t q = 0; q < nq; ++q) t.points.push_back({g.uvw[3 * q], g.uvw[3 * q + 1]});
  t.dN.resize(nq * na * 2);
  for (std::size_t i = 0; i < nq * na; ++i) {
    t.dN[2 * i] = b.dN[3 * i];
    t.dN[2 * i + 1] = b.dN[3 * i + 1];
  }
  return t;
}

// gmsh's reference line is xi in [-1, 1]; ours is s = (xi + 1)/2 in [0, 1]: weights halve and
// d/ds = 2 d/dxi.
ReferenceEdge build_edge(int order, int degree) {
  const auto [g, b] = detail::with_gmsh("reference_edge", [&](detail::GmshSession&) {
    const int type = gmsh::model::mesh::getElementType("Line", order);
    GmshRule rule = gauss_rule(type, degree);
    Basis basis = lagrange_basis(type, rule.uvw);
    return std::pair{rule, basis};
  });
  ReferenceEdge e;
  e.order = order;
  e.N = b.N;
  for (std::size_t q = 0; q < g.weights.size(); ++q) {
    e.points.push_back(0.5 * (g.uvw[3 * q] + 1.0));
    e.weights.push_back(0.5 * g.weights[q]);
  }
  for (std::size_t i = 0; i < b.N.size(); ++i) e.dN.push_back(2.0 * b.dN[3 * i]);
  return e;
}

// gmsh's reference tetrahedron is ours: weights sum to 1/6.
ReferenceTetrahedron build_tetrahedron(int order, int degree) {
  const auto [g, b] = detail::with_gmsh("reference_tetrahedron", [&](detail::GmshSession&) {
    GmshRule rule = gauss_rule(gmsh::model::mesh::getElementType("Tetrahedron", 1), degree);
    Basis basis = lagrange_basis(gmsh::model::mesh::getElementType("Tetrahedron", order), rule.uvw);
    return std::pair{rule, basis};
  });
  ReferenceTetrahedron t;
  t.order = order;
  t.nodes_per_element = (order + 1) * (order + 2) * (order + 3) / 6;
  t.weights = g.weights;
  t.N = b.N;
  t.dN = b.dN;
  for (std::size_t q = 0; q < g.weights.size(); ++q) t.points.push_back({g.uvw[3 * q], g.uvw[3 * q + 1], g.uvw[3 * q + 2]});
  return t;
}

// Elements are built once per (order, degree) and copied out: FE assembly asks for them often and
// each build costs a gmsh session.
template <class Element>
Element cached(int order, int degree, Element (*build)(int, int)) {
  static std::mutex mutex;
  static std::map<std::pair<int, int>, Element> cache;
  std::lock_guard lock(mutex);
  auto it = cache.find({order, degree});
  if (it == cache.end()) it = cache.emplace(std::pair{order, degree}, build(order, degree)).first;
  return it->second;
}

}  // namespace

ReferenceTriangle reference_triangle(int order, int quadrature_degree) {
  check_arguments("reference_triangle", order, quadrature_degree);
  return cached(order, quadrature_degree, build_triangle);
}

std::vector<double> triangle_basis_at(int order, const std::vector<std::array<double, 2>>& points) {
  check_arguments("triangle_basis_at", order, 1);
  std::vector<double> uvw;
  for (const auto& p : points) uvw.insert(uvw.end(), {p[0], p[1], 0.0});
  return detail::with_gmsh("triangle_basis_at", [&](detail::GmshSession&) {
    return lagrange_basis(gmsh::model::mesh::getElementType("Triangle", order), uvw).N;
  });
}

ReferenceTetrahedron reference_tetrahedron(int order, int quadrature_degree) {
  check_arguments("reference_tetrahedron", order, quadrature_degree);
  return cached(order, quadrature_degree, build_tetrahedron);
}

TetrahedronBasis tetrahedron_basis_at(int order, const std::vector<std::array<double, 3>>& points) {
  check_arguments("tetrahedron_basis_at", order, 1);
  std::vector<double> uvw;
  for (const auto& p : points) uvw.insert(uvw.end(), {p[0], p[1], p[2]});
  const Basis b = detail::with_gmsh("tetrahedron_basis_at", [&](detail::GmshSession&) {
    return lagrange_basis(gmsh::model::mesh::getElementType("Tetrahedron", order), uvw);
  });
  return {b.N, b.dN};
}

ReferenceEdge reference_edge(int order, int quadrature_degree) {
  check_arguments("reference_edge", order, quadrature_degree);
  return cached(order, quadrature_degree, build_edge);
}

}  // namespace rc::geometry
