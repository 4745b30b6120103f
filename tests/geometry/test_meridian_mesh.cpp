// Meridian meshes: exact areas and volumes of the built-in shapes, mesh invariants the FE solver
// relies on, user sections and one-line errors on bad input.
#include "meridian_mesh.hpp"
#include "gmsh_library.hpp"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <set>

namespace {

using namespace rc::geometry;

const std::filesystem::path kSections = RC_SECTIONS_DIR;

struct Integrals {
  double area = 0, volume = 0;  // ∫∫ dr dz and 2π ∫∫ r dr dz
  double min_jacobian = INFINITY;
};

// Isoparametric integration with a rule exact for det J · r (degree 3p - 2).
Integrals integrate(const MeridianMesh& m) {
  const auto ref = reference_triangle(m.order, 3 * m.order);
  const int npe = m.nodes_per_element;
  Integrals s;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const int* v = &m.triangles[t * npe];
    for (std::size_t q = 0; q < ref.weights.size(); ++q) {
      double r = 0, j[2][2] = {{0, 0}, {0, 0}};
      for (int a = 0; a < npe; ++a) {
        const auto& x = m.nodes[v[a]];
        r += ref.N[q * npe + a] * x[0];
        for (int c = 0; c < 2; ++c)
          for (int d = 0; d < 2; ++d) j[c][d] += x[c] * ref.dN[(q * npe + a) * 2 + d];
      }
      const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
      s.min_jacobian = std::min(s.min_jacobian, det);
      s.area += ref.weights[q] * det;
      s.volume += 2 * M_PI * ref.weights[q] * det * r;
    }
  }
  return s;
}

MeridianMesh mesh(const ShapeSpec& shape, int order, double size = 0) {
  MeshOptions o;
  o.order = order;
  o.size = size;
  return mesh_meridian(shape, o);
}

struct Shape {
  const char* name;
  ShapeSpec spec;
  double area, volume;
  std::array<double, 3> bound;  // relative volume and area error allowed at orders 2, 3, 4 (default size)
};

// Bounds: the larger of the measured area and volume errors at the default size (gmsh 4.8.4),
// times ~3. Straight-sided shapes are exact up to rounding (< 1e-14). Measured relative volume
// errors, orders 2 / 3 / 4 (odd orders converge like h^(p+1), even ones like h^(p+2)):
//   sphere 6.7e-7 / 9.9e-8 / 2.4e-11; oblate spheroid 9.4e-7 / 1.4e-7 / 3.9e-10;
//   prolate spheroid 3.8e-7 / 5.2e-8 / 1.3e-9; capsule 2.7e-7 / 3.9e-8 / 9.6e-12.
const std::vector<Shape>& shapes() {
  static const std::vector<Shape> s = {
      {"sphere", {"sphere", {{"radius", 1.0}}, {}}, M_PI / 2, 4 * M_PI / 3, {2e-6, 3e-7, 8e-11}},
      {"oblate", {"spheroid", {{"a", 1.0}, {"c", 0.5}}, {}}, M_PI / 4, 2 * M_PI / 3, {3e-6, 4e-7, 1.2e-9}},
      {"prolate", {"spheroid", {{"a", 0.5}, {"c", 1.5}}, {}}, 0.375 * M_PI, 0.5 * M_PI, {1.5e-6, 2.2e-7, 4e-9}},
      {"cylinder", {"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}}, 2.0, 2 * M_PI, {1e-13, 1e-13, 1e-13}},
      {"cone", {"cone", {{"radius", 1.0}, {"height", 2.0}}, {}}, 1.0, 2 * M_PI / 3, {1e-13, 1e-13, 1e-13}},
      {"capsule", {"section", {}, kSections / "capsule.geo"}, 2 + M_PI / 2, 2 * M_PI + 4 * M_PI / 3,
       {8e-7, 1.2e-7, 3e-11}},
  };
  return s;
}

TEST(MeridianMesh, AreaAndVolumeConvergeWithOrder) {
  for (const auto& s : shapes()) {
    double previous = INFINITY;
    for (int order : {2, 3, 4}) {
      const MeridianMesh m = mesh(s.spec, order);
      const Integrals I = integrate(m);
      const double area_error = std::abs(I.area / s.area - 1), volume_error = std::abs(I.volume / s.volume - 1);
      const double bound = s.bound[order - 2];
      EXPECT_LT(volume_error, bound) << s.name << " order " << order;
      EXPECT_LT(area_error, bound) << s.name << " order " << order;
      if (bound > 1e-13) {
        EXPECT_LT(volume_error, previous / 5) << s.name << " order " << order;
      }
      previous = volume_error;
    }
  }
}

// Even orders gain one extra power of h on curved walls: h^(p+2) for p = 4.
TEST(MeridianMesh, SphereVolumeConvergesLikeHToTheSixthAtOrderFour) {
  const ShapeSpec sphere{"sphere", {{"radius", 1.0}}, {}};
  const double exact = 4 * M_PI / 3;
  const double coarse = std::abs(integrate(mesh(sphere, 4, 0.25)).volume / exact - 1);
  const double fine = std::abs(integrate(mesh(sphere, 4, 0.125)).volume / exact - 1);
  EXPECT_GT(coarse / fine, 25.0) << coarse << " -> " << fine;  // measured 9.9e-10 -> 2.4e-11: 41
}

TEST(MeridianMesh, DefaultsAreOrderThreeAndAnEighthOfTheSmallestDimension) {
  EXPECT_EQ(MeshOptions{}.order, 3);
  const MeridianMesh m = mesh_meridian({"cylinder", {{"radius", 0.5}, {"height", 3.0}}, {}}, {});
  EXPECT_EQ(m.order, 3);
  EXPECT_EQ(m.nodes_per_element, 10);
  EXPECT_DOUBLE_EQ(m.size, 0.5 / 8);
}

// The invariants the FE solver relies on, for every shape and order 1..6.
void check_invariants(const MeridianMesh& m, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_GT(m.num_triangles(), 0u);
  ASSERT_EQ(m.triangles.size() % m.nodes_per_element, 0u);
  EXPECT_GT(integrate(m).min_jacobian, 0.0);
  std::set<int> used(m.triangles.begin(), m.triangles.end());
  EXPECT_EQ(used.size(), m.nodes.size());  // compact numbering: every node is used
  EXPECT_EQ(*used.rbegin(), static_cast<int>(m.nodes.size()) - 1);
  std::set<int> axis(m.axis_nodes.begin(), m.axis_nodes.end());
  EXPECT_EQ(axis.size(), m.axis_nodes.size());
  EXPECT_TRUE(std::is_sorted(m.axis_nodes.begin(), m.axis_nodes.end()));
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    EXPECT_GE(m.nodes[i][0], 0.0);
    EXPECT_EQ(m.nodes[i][0] == 0.0, axis.count(static_cast<int>(i)) == 1) << "node " << i;
  }
  EXPECT_EQ(m.wall_edges.size() % (m.order + 1), 0u);
}

// --radial-size: a structured cylinder mesh of ⌈R / h_r⌉ × ⌈H / h⌉ rectangles, two triangles each, with the
// same invariants and the exact area and volume (straight sides).
TEST(MeridianMesh, StructuredCylinderHasTheRequestedCells) {
  const ShapeSpec cylinder{"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}};
  MeshOptions options{4, 0.5};
  options.radial_size = 0.1;
  const MeridianMesh m = mesh_meridian(cylinder, options);
  EXPECT_EQ(m.num_triangles(), 2u * 10 * 4);
  check_invariants(m, "structured cylinder");
  const auto in = integrate(m);
  EXPECT_NEAR(in.volume, 2 * M_PI, 1e-12);
  // No node is closer to the axis than the radial size allows (order 4: a quarter of it).
  double rmin = 1;
  for (const auto& n : m.nodes)
    if (n[0] > 0) rmin = std::min(rmin, n[0]);
  EXPECT_NEAR(rmin, 0.1 / 4, 1e-12);
}

// The cone with its wall layers built in (geometry/shapes.cpp, build_layered_cone): exact volume, the same
// invariants, and cells across the layer that start at the wall size and grow by the ratio asked for, on the
// slant, on the lid and at the apex (where the slant strip ends on the axis).
TEST(MeridianMesh, LayeredConeHasGeometricCellsAtTheWall) {
  const ShapeSpec cone{"cone", {{"radius", 1.0}, {"height", 1.5}}, {}};
  for (int order : {2, 6}) {
    MeshOptions o{order, 0.125};
    o.wall_size = 0.002;
    o.wall_growth = 0.25;
    o.wall_layer = 0.05;
    const MeridianMesh m = mesh_meridian(cone, o);
    check_invariants(m, "layered cone P" + std::to_string(order));
    const auto in = integrate(m);
    EXPECT_NEAR(in.volume, M_PI * 1.5 / 3, 1e-11);  // straight sides: exact up to rounding
    // Distances of the vertices from the lid (z = 1.5) and from the slant (r = z / 1.5), away from the rim where the
    // two strips meet, sorted: the layer nodes first.
    const double L = std::hypot(1.0, 1.5);
    std::set<double> from_lid, from_slant;
    for (std::size_t t = 0; t < m.num_triangles(); ++t)
      for (int i = 0; i < 3; ++i) {
        const auto& p = m.nodes[m.triangles[t * m.nodes_per_element + i]];
        if (p[0] < 0.5) from_lid.insert(std::round((1.5 - p[1]) * 1e9) / 1e9);  // away from the rim
        if (p[1] > 0.5 && p[1] < 1.0) from_slant.insert(std::round((p[1] - 1.5 * p[0]) / L * 1e9) / 1e9);
      }
    for (const auto* d : {&from_lid, &from_slant}) {
      const std::vector<double> v(d->begin(), d->end());
      ASSERT_GE(v.size(), 4u);
      EXPECT_NEAR(v[0], 0, 1e-9);
      EXPECT_LE(v[1], 0.002 + 1e-9) << "first layer thicker than the wall size";
      EXPECT_GE(v[1], 0.002 / 1.25) << "first layer much thinner than asked";
      EXPECT_NEAR((v[2] - v[1]) / v[1], 1.25, 1e-6) << "layers do not grow by the ratio";
    }
    // The apex is a mesh vertex on the axis, and so is the point where the slant strip ends on it (z = t L / R).
    bool apex = false, strip_end = false;
    for (int a : m.axis_nodes) {
      apex = apex || std::hypot(m.nodes[a][0], m.nodes[a][1]) < 1e-12;
      strip_end = strip_end || std::abs(m.nodes[a][1] - 0.05 * L) < 1e-12;
    }
    EXPECT_TRUE(apex && strip_end);
  }
  MeshOptions thick{2, 0.125};
  thick.wall_size = 0.01;
  thick.wall_layer = 0.6;  // the strips would overlap
  EXPECT_THROW(mesh_meridian(cone, thick), std::runtime_error);
}

TEST(MeridianMesh, InvariantsHoldForAllShapesAndOrders) {
  for (const auto& s : shapes())
    for (int order = 1; order <= 6; ++order) check_invariants(mesh(s.spec, order), s.name + std::to_string(order));
}

// High-order wall nodes lie on the exact ellipse, and wall edges run counter-clockwise around the
// fluid: the outward normal (dz/ds, -dr/ds) points away from the centre.
TEST(MeridianMesh, WallNodesLieOnTheCurvedWallAndEdgesRunCounterClockwise) {
  const double a = 1.0, c = 0.5;
  const MeridianMesh m = mesh({"spheroid", {{"a", a}, {"c", c}}, {}}, 5);
  const int n = m.order + 1;
  ASSERT_GT(m.wall_edges.size(), 0u);
  for (std::size_t e = 0; e < m.wall_edges.size(); e += n) {
    for (int k = 0; k < n; ++k) {
      const auto& p = m.nodes[m.wall_edges[e + k]];
      EXPECT_NEAR(p[0] * p[0] / (a * a) + p[1] * p[1] / (c * c), 1.0, 1e-14);
    }
    const auto &p0 = m.nodes[m.wall_edges[e]], &p1 = m.nodes[m.wall_edges[e + 1]];
    const double nr = p1[1] - p0[1], nz = -(p1[0] - p0[0]);
    EXPECT_GT(nr * (p0[0] + p1[0]) + nz * (p0[1] + p1[1]), 0.0);
  }
}

// Temporary section files for the tests below.
std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("rc_geometry_test_" + name);
  std::ofstream(path) << text;
  return path;
}

const char* kTriangleGeo = R"(
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
)";

// A clockwise loop gives triangles with a -z normal; they must come out counter-clockwise.
TEST(MeridianMesh, ClockwiseSectionIsReoriented) {
  const auto geo = write_file("clockwise.geo", std::string(kTriangleGeo) + R"(
Curve Loop(1) = {-3, -2, -1}; Plane Surface(1) = {1};
Physical Surface("fluid") = {1}; Physical Curve("wall") = {1, 2}; Physical Curve("axis") = {3};
)");
  for (int order = 1; order <= 4; ++order) {
    const MeridianMesh m = mesh({"section", {}, geo}, order, 0.2);
    check_invariants(m, "clockwise order " + std::to_string(order));
    EXPECT_NEAR(integrate(m).area, 0.5, 1e-14);
  }
}

// A .msh is used as it is: its own order, no remeshing.
TEST(MeridianMesh, MshSectionKeepsItsOrder) {
  const auto msh = std::filesystem::temp_directory_path() / "rc_geometry_test_capsule.msh";
  rc::geometry::load_gmsh();  // gmsh called directly, not through a GmshSession
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open((kSections / "capsule.geo").string());
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::setOrder(4);
  gmsh::write(msh.string());
  gmsh::finalize();
  const MeridianMesh m = mesh({"section", {}, msh}, 2, 0.01);  // order and size are ignored
  EXPECT_EQ(m.order, 4);
  check_invariants(m, "capsule.msh");
  EXPECT_NEAR(integrate(m).volume / (10 * M_PI / 3) - 1, 0.0, 1e-9);
}

// Bad input: std::runtime_error whose one-line message names the cause.
void expect_error(const std::function<void()>& f, const std::string& expected) {
  try {
    f();
    ADD_FAILURE() << "no exception, expected: " << expected;
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(expected), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

void expect_shape_error(const ShapeSpec& shape, const std::string& expected, MeshOptions o = {}) {
  expect_error([&] { mesh_meridian(shape, o); }, expected);
}

TEST(MeridianMeshErrors, BadShapes) {
  expect_shape_error({"torus", {{"radius", 1.0}}, {}}, "unknown shape kind 'torus'");
  expect_shape_error({"sphere", {}, {}}, "sphere: missing dimension 'radius'");
  expect_shape_error({"spheroid", {{"a", 1.0}}, {}}, "spheroid: missing dimension 'c'");
  expect_shape_error({"sphere", {{"radious", 1.0}}, {}}, "unknown dimension 'radious'");
  expect_shape_error({"sphere", {{"radius", 0.0}}, {}}, "radius = 0 must be positive");
  expect_shape_error({"cone", {{"radius", 1.0}, {"height", -2.0}}, {}}, "height = -2 must be positive");
  expect_shape_error({"cylinder", {{"radius", NAN}, {"height", 1.0}}, {}}, "radius = nan");
  expect_shape_error({"cylinder", {{"radius", 1.0}, {"height", INFINITY}}, {}}, "height = inf");
}

TEST(MeridianMeshErrors, BadOptions) {
  const ShapeSpec sphere{"sphere", {{"radius", 1.0}}, {}};
  expect_shape_error(sphere, "mesh order 0 is outside 1..6", {0, 0.0});
  expect_shape_error(sphere, "mesh order 7 is outside 1..6", {7, 0.0});
  expect_shape_error(sphere, "mesh size -0.1 must be positive", {3, -0.1});
  expect_shape_error(sphere, "mesh size nan", {3, NAN});
  expect_shape_error(sphere, "mesh size 1e-06 is too small", {3, 1e-6});
  MeshOptions radial{3, 0.5};
  radial.radial_size = 0.1;
  expect_shape_error(sphere, "only available for the cylinder", radial);
  radial.radial_size = -1;
  expect_shape_error({"cylinder", {{"radius", 1.0}, {"height", 1.0}}, {}}, "radial mesh size -1 must be positive",
                     radial);
}

TEST(MeridianMeshErrors, BadSections) {
  expect_shape_error({"section", {}, {}}, "section: no file given");
  expect_shape_error({"section", {}, "/nonexistent/cavity.geo"}, "cannot read the file");
  expect_shape_error({"section", {}, write_file("cavity.step", "")}, "expected a .geo or .msh file");
  expect_shape_error({"section", {}, write_file("syntax.geo", "Point(1) = {0, 0, 0};\nfoo bar;\n")},
                     "syntax.geo', line 2");
  const auto no_axis = write_file("no_axis.geo", std::string(kTriangleGeo) + R"(
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Physical Surface("fluid") = {1}; Physical Curve("wall") = {1, 2};
)");
  expect_shape_error({"section", {}, no_axis}, "no 1D physical group named 'axis'");
  const auto negative_r = write_file("negative_r.geo", R"(
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {-0.5, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Physical Surface("fluid") = {1}; Physical Curve("wall") = {1, 2}; Physical Curve("axis") = {3};
)");
  expect_shape_error({"section", {}, negative_r}, "has r < 0");
  const auto quads = write_file("quads.geo", R"(
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 3; Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("fluid") = {1}; Physical Curve("wall") = {1, 2, 3}; Physical Curve("axis") = {4};
)");
  expect_shape_error({"section", {}, quads}, "expected complete Lagrange triangles");
}

// After errors, gmsh is left usable: sections and reference elements still work.
TEST(MeridianMeshErrors, GmshRecoversAfterErrors) {
  expect_shape_error({"section", {}, write_file("syntax2.geo", "foo bar;\n")}, "syntax2.geo");
  const MeridianMesh m = mesh({"section", {}, kSections / "capsule.geo"}, 2);
  EXPECT_GT(m.num_triangles(), 0u);
}

}  // namespace
