// gmsh in a child process (geometry/isolated_mesh.hpp): the mesh it sends back is the mesh made in-process, and its
// errors arrive as the same one-line messages.
#include "isolated_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace rc::geometry;

namespace {

// ∫∫ r dr dz over the straight-sided triangles (its vertices): a sum over every triangle, so a mesh sent back with
// a node or a triangle out of place shows.
double meridian_moment(const MeridianMesh& m) {
  double sum = 0;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const int* v = &m.triangles[t * m.nodes_per_element];
    const auto &a = m.nodes[v[0]], &b = m.nodes[v[1]], &c = m.nodes[v[2]];
    const double area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    sum += area * (a[0] + b[0] + c[0]) / 3;
  }
  return sum;
}

}  // namespace

TEST(IsolatedMesh, ChildsMeshIsTheInProcessMesh) {
  const ShapeSpec capsule{"section", {}, std::filesystem::path(RC_SECTIONS_DIR) / "capsule.geo"};
  MeshOptions o;
  o.order = 3;
  o.size = 0.25;
  const MeridianMesh here = mesh_meridian(capsule, o), there = mesh_meridian_isolated(capsule, o, 60);
  std::printf("capsule, P3 h 0.25: %zu and %zu nodes, %zu and %zu triangles, moment %.15f and %.15f\n",
              here.nodes.size(), there.nodes.size(), here.num_triangles(), there.num_triangles(),
              meridian_moment(here), meridian_moment(there));
  EXPECT_EQ(there.order, 3);
  EXPECT_EQ(there.nodes_per_element, here.nodes_per_element);
  EXPECT_EQ(there.nodes.size(), here.nodes.size());
  EXPECT_EQ(there.triangles.size(), here.triangles.size());
  EXPECT_EQ(there.wall_edges.size(), here.wall_edges.size());
  EXPECT_EQ(there.axis_nodes.size(), here.axis_nodes.size());
  EXPECT_DOUBLE_EQ(there.size, here.size);
  EXPECT_NEAR(meridian_moment(there), meridian_moment(here), 1e-12);
  EXPECT_NEAR(meridian_moment(there), 5.0 / 3, 0.02);  // the capsule's volume / 2π, less the straight sides' loss
}

TEST(IsolatedMesh, ChildsErrorIsTheMessage) {
  const ShapeSpec missing{"section", {}, "no_such_section.geo"};
  std::string in_process, isolated;
  try {
    mesh_meridian(missing, MeshOptions{});
  } catch (const std::runtime_error& e) {
    in_process = e.what();
  }
  try {
    mesh_meridian_isolated(missing, MeshOptions{}, 60);
  } catch (const std::runtime_error& e) {
    isolated = e.what();
  }
  std::printf("in-process: %s\nisolated:   %s\n", in_process.c_str(), isolated.c_str());
  EXPECT_FALSE(in_process.empty());
  EXPECT_EQ(isolated, in_process);
}

// gmsh's BoundaryLayer field orders its layers by heap addresses: in-process, one viscous command meshed 70 700,
// 70 434 or 69 902 unknowns with another environment (docs/viscous.md, "Reproducible tables"). The mesher program
// runs with no environment and the address-space randomisation off, so the asking process's environment and heap
// must not change the mesh: the same layered request, asked again after both changed, gives the same mesh to the bit.
// (Made in-process by mesh_meridian, the two meshes of this test differ: the same counts, other nodes; measured.)
TEST(IsolatedMesh, LayeredMeshIsTheSameWhateverTheEnvironment) {
  const ShapeSpec cylinder{"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}};
  MeshOptions o;
  o.order = 2;
  o.size = 0.125;
  o.wall_size = 0.01;
  o.wall_layer = 0.0625;
  const MeridianMesh first = mesh_meridian_isolated(cylinder, o, 60);
  setenv("RC_TEST_ENVIRONMENT_PAD", std::string(3000, 'x').c_str(), 1);
  std::vector<std::string> heap(500, std::string(200, 'y'));  // this process's heap moves on too
  const MeridianMesh second = mesh_meridian_isolated(cylinder, o, 60);
  unsetenv("RC_TEST_ENVIRONMENT_PAD");
  std::printf("layered cylinder, P2 h 0.125: %zu and %zu nodes, %zu and %zu triangles (%zu strings held between)\n",
              first.nodes.size(), second.nodes.size(), first.num_triangles(), second.num_triangles(), heap.size());
  EXPECT_EQ(first.nodes, second.nodes);
  EXPECT_EQ(first.triangles, second.triangles);
  EXPECT_EQ(first.wall_edges, second.wall_edges);
  EXPECT_EQ(first.axis_nodes, second.axis_nodes);
}
