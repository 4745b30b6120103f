#include "isolated_mesh.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace rc::geometry {
namespace {

// The mesh as bytes: a status byte (0 mesh, 1 error message), then the fields in a fixed order.
void put(std::string& out, const void* data, std::size_t bytes) { out.append(static_cast<const char*>(data), bytes); }

template <class T>
void put_vector(std::string& out, const std::vector<T>& v) {
  const std::size_t n = v.size();
  put(out, &n, sizeof n);
  put(out, v.data(), n * sizeof(T));
}

std::string serialise(const MeridianMesh& m) {
  std::string out(1, '\0');
  put(out, &m.order, sizeof m.order);
  put(out, &m.nodes_per_element, sizeof m.nodes_per_element);
  put(out, &m.free_radius, sizeof m.free_radius);
  put(out, &m.size, sizeof m.size);
  put_vector(out, m.nodes);
  put_vector(out, m.triangles);
  put_vector(out, m.axis_nodes);
  put_vector(out, m.wall_edges);
  put_vector(out, m.free_edges);
  return out;
}

struct Reader {
  const std::string& in;
  std::size_t at = 1;
  void get(void* data, std::size_t bytes) {
    if (at + bytes > in.size()) throw std::runtime_error("gmsh's child process sent a truncated mesh");
    std::memcpy(data, in.data() + at, bytes);
    at += bytes;
  }
  template <class T>
  void get_vector(std::vector<T>& v) {
    std::size_t n = 0;
    get(&n, sizeof n);
    if (n > (in.size() - at) / sizeof(T)) throw std::runtime_error("gmsh's child process sent a truncated mesh");
    v.resize(n);
    get(v.data(), n * sizeof(T));
  }
};

MeridianMesh deserialise(const std::string& in) {
  MeridianMesh m;
  Reader r{in};
  r.get(&m.order, sizeof m.order);
  r.get(&m.nodes_per_element, sizeof m.nodes_per_element);
  r.get(&m.free_radius, sizeof m.free_radius);
  r.get(&m.size, sizeof m.size);
  r.get_vector(m.nodes);
  r.get_vector(m.triangles);
  r.get_vector(m.axis_nodes);
  r.get_vector(m.wall_edges);
  r.get_vector(m.free_edges);
  return m;
}

[[noreturn]] void run_child(int fd, const ShapeSpec& shape, const MeshOptions& options) {
  std::string out;
  try {
    out = serialise(mesh_meridian(shape, options));
  } catch (const std::exception& e) {
    out = std::string(1, '\1') + e.what();
  }
  for (std::size_t sent = 0; sent < out.size();) {
    const ssize_t n = write(fd, out.data() + sent, out.size() - sent);
    if (n <= 0) _exit(3);
    sent += static_cast<std::size_t>(n);
  }
  close(fd);
  _exit(0);
}

// Everything the child writes until it closes the pipe, or until `seconds` have passed (then false).
bool read_all(int fd, double seconds, std::string& in) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  char buffer[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(left.count()));
    if (ready == 0) return false;
    if (ready < 0) continue;  // interrupted
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n == 0) return true;
    if (n > 0) in.append(buffer, static_cast<std::size_t>(n));
  }
}

}  // namespace

MeridianMesh mesh_meridian_isolated(const ShapeSpec& shape, const MeshOptions& options, double seconds) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("could not open a pipe to mesh in a child process");
  const pid_t child = fork();
  if (child < 0) {
    close(fds[0]);
    close(fds[1]);
    throw std::runtime_error("could not fork a child process to mesh in");
  }
  if (child == 0) {
    close(fds[0]);
    run_child(fds[1], shape, options);
  }
  close(fds[1]);
  std::string in;
  const bool finished = read_all(fds[0], seconds, in);
  close(fds[0]);
  if (!finished) kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  const std::string where = shape.kind == "section" ? "section " + shape.file.string() : shape.kind;
  if (!finished)
    throw std::runtime_error(where + ": gmsh did not finish meshing in " + std::to_string(static_cast<int>(seconds)) +
                             " s");
  if (WIFSIGNALED(status))
    throw std::runtime_error(where + ": gmsh crashed meshing (signal " + std::to_string(WTERMSIG(status)) + ")");
  if (in.empty() || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(where + ": gmsh's child process ended without a mesh");
  if (in[0] == '\1') throw std::runtime_error(in.substr(1));
  return deserialise(in);
}

}  // namespace rc::geometry
