#include "mesh_broadcast.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace rc::modes {
namespace {

template <class T>
void broadcast_vector(std::vector<T>& v, MPI_Datatype type, MPI_Comm comm) {
  long n = static_cast<long>(v.size());
  MPI_Bcast(&n, 1, MPI_LONG, 0, comm);
  v.resize(n);
  if (n > 0) MPI_Bcast(v.data(), static_cast<int>(n), type, 0, comm);
}

// make() on rank 0; its error, if any, re-thrown on every rank.
template <class Mesh>
Mesh made_on_root(const std::function<Mesh()>& make, int rank, MPI_Comm comm) {
  Mesh m;
  std::string error;
  if (rank == 0) {
    try {
      m = make();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  std::vector<char> message(error.begin(), error.end());
  broadcast_vector(message, MPI_CHAR, comm);
  if (!message.empty()) throw std::runtime_error(std::string(message.begin(), message.end()));
  return m;
}

}  // namespace

geometry::MeridianMesh mesh_on_root(const std::function<geometry::MeridianMesh()>& make, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  if (ranks == 1) return make();
  geometry::MeridianMesh m = made_on_root(make, rank, comm);
  int header[2] = {m.order, m.nodes_per_element};
  MPI_Bcast(header, 2, MPI_INT, 0, comm);
  m.order = header[0];
  m.nodes_per_element = header[1];
  MPI_Bcast(&m.size, 1, MPI_DOUBLE, 0, comm);
  MPI_Bcast(&m.free_radius, 1, MPI_DOUBLE, 0, comm);
  std::vector<double> xy;
  for (const auto& p : m.nodes) xy.insert(xy.end(), {p[0], p[1]});
  broadcast_vector(xy, MPI_DOUBLE, comm);
  m.nodes.resize(xy.size() / 2);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) m.nodes[i] = {xy[2 * i], xy[2 * i + 1]};
  broadcast_vector(m.triangles, MPI_INT, comm);
  broadcast_vector(m.axis_nodes, MPI_INT, comm);
  broadcast_vector(m.wall_edges, MPI_INT, comm);
  broadcast_vector(m.free_edges, MPI_INT, comm);
  return m;
}

geometry::VolumeMesh volume_mesh_on_root(const std::function<geometry::VolumeMesh()>& make, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  if (ranks == 1) return make();
  geometry::VolumeMesh m = made_on_root(make, rank, comm);
  int header[2] = {m.order, m.nodes_per_element};
  MPI_Bcast(header, 2, MPI_INT, 0, comm);
  m.order = header[0];
  m.nodes_per_element = header[1];
  MPI_Bcast(&m.size, 1, MPI_DOUBLE, 0, comm);
  std::vector<double> xyz;
  for (const auto& p : m.nodes) xyz.insert(xyz.end(), {p[0], p[1], p[2]});
  broadcast_vector(xyz, MPI_DOUBLE, comm);
  m.nodes.resize(xyz.size() / 3);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) m.nodes[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  broadcast_vector(m.tetrahedra, MPI_INT, comm);
  return m;
}

}  // namespace rc::modes
