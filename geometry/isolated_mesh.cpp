#include "isolated_mesh.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/personality.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
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

// The request as bytes, every field of ShapeSpec and MeshOptions in a fixed order (a field added to either must be
// added here).
std::string serialise(const ShapeSpec& shape, const MeshOptions& o) {
  std::string out(1, '\0');
  const auto put_text = [&out](const std::string& t) { put_vector(out, std::vector<char>(t.begin(), t.end())); };
  put_text(shape.kind);
  const std::size_t dims = shape.dims.size();
  put(out, &dims, sizeof dims);
  for (const auto& [name, value] : shape.dims) put_text(name), put(out, &value, sizeof value);
  put_text(shape.file.string());  // as given: the mesher runs in this process's working directory
  put(out, &o.order, sizeof o.order);
  for (const double* v : {&o.size, &o.radial_size, &o.wall_size, &o.wall_growth, &o.wall_layer, &o.near_wall_size,
                          &o.near_wall_growth, &o.band_size, &o.band_width, &o.band_growth})
    put(out, v, sizeof *v);
  put_vector(out, o.bands);
  return out;
}

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

void deserialise(const std::string& in, ShapeSpec& shape, MeshOptions& o) {
  Reader r{in};
  const auto get_text = [&r] {
    std::vector<char> t;
    r.get_vector(t);
    return std::string(t.begin(), t.end());
  };
  shape.kind = get_text();
  std::size_t dims = 0;
  r.get(&dims, sizeof dims);
  if (dims > 64) throw std::runtime_error("a shape with " + std::to_string(dims) + " dimensions");
  for (std::size_t i = 0; i < dims; ++i) {
    const std::string name = get_text();
    r.get(&shape.dims[name], sizeof(double));
  }
  shape.file = get_text();
  r.get(&o.order, sizeof o.order);
  for (double* v : {&o.size, &o.radial_size, &o.wall_size, &o.wall_growth, &o.wall_layer, &o.near_wall_size,
                    &o.near_wall_growth, &o.band_size, &o.band_width, &o.band_growth})
    r.get(v, sizeof *v);
  r.get_vector(o.bands);
}

void write_all(int fd, const std::string& out) {
  for (std::size_t sent = 0; sent < out.size();) {
    const ssize_t n = write(fd, out.data() + sent, out.size() - sent);
    if (n <= 0) _exit(3);
    sent += static_cast<std::size_t>(n);
  }
}

// Meshes in this process and writes the result (a mesh, or a status byte 1 and the error's message) to `fd`.
void mesh_and_send(int fd, const ShapeSpec& shape, const MeshOptions& options) {
  std::string out;
  try {
    out = serialise(mesh_meridian(shape, options));
  } catch (const std::exception& e) {
    out = std::string(1, '\1') + e.what();
  }
  write_all(fd, out);
}

// The forked child becomes the mesher program, with no environment and the address-space randomisation off: gmsh's
// BoundaryLayer field orders its layers by heap addresses, and a fresh process with a fixed environment has the same
// heap on every run, so the same request gives the same mesh whichever process asks, serially or under mpirun
// (docs/viscous.md, "Reproducible tables").
[[noreturn]] void run_child(int request_fd, int result_fd) {
  if (dup2(request_fd, STDIN_FILENO) < 0 || dup2(result_fd, STDOUT_FILENO) < 0) _exit(4);
  personality(ADDR_NO_RANDOMIZE);
  char* const argv[] = {const_cast<char*>(RC_MESHER_PATH), nullptr};
  char* const envp[] = {nullptr};
  execve(RC_MESHER_PATH, argv, envp);
  // Not started: the reason as the child's error message, written without allocating (a forked child of a threaded
  // process may not).
  const char* parts[] = {"\1cannot run the mesher " RC_MESHER_PATH ": ", std::strerror(errno),
                         " (build it: cmake --build build --target rc-mesher)"};
  for (const char* part : parts)
    if (write(result_fd, part, std::strlen(part)) < 0) break;
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
  int result[2], request[2];
  if (pipe(result) != 0) throw std::runtime_error("could not open a pipe to mesh in a child process");
  if (pipe(request) != 0) {
    close(result[0]), close(result[1]);
    throw std::runtime_error("could not open a pipe to mesh in a child process");
  }
  const std::string asked = serialise(shape, options);  // before the fork: the child may not allocate
  const pid_t child = fork();
  if (child < 0) {
    for (int fd : {result[0], result[1], request[0], request[1]}) close(fd);
    throw std::runtime_error("could not fork a child process to mesh in");
  }
  if (child == 0) {
    close(result[0]);
    close(request[1]);
    run_child(request[0], result[1]);
  }
  close(result[1]);
  close(request[0]);
  // A mesher that ended before reading its request must not end this process by SIGPIPE: its status says why below.
  void (*previous)(int) = signal(SIGPIPE, SIG_IGN);
  for (std::size_t sent = 0; sent < asked.size();) {
    const ssize_t n = write(request[1], asked.data() + sent, asked.size() - sent);
    if (n <= 0) break;
    sent += static_cast<std::size_t>(n);
  }
  close(request[1]);
  signal(SIGPIPE, previous);
  std::string in;
  const bool finished = read_all(result[0], seconds, in);
  close(result[0]);
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

int run_mesher(int request_fd, int result_fd) {
  std::string in;
  char buffer[1 << 12];
  for (ssize_t n; (n = read(request_fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      return 1;
    }
    in.append(buffer, static_cast<std::size_t>(n));
  }
  ShapeSpec shape;
  MeshOptions options;
  try {
    deserialise(in, shape, options);
  } catch (const std::exception& e) {
    write_all(result_fd, std::string(1, '\1') + "the mesher's request: " + e.what());
    return 0;
  }
  mesh_and_send(result_fd, shape, options);
  return 0;
}

}  // namespace rc::geometry
