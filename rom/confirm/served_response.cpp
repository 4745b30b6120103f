#include "served_response.hpp"

#include "recorded_command.hpp"

#include <array>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <regex>
#include <sstream>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace rc::rom {
namespace fs = std::filesystem;
namespace {

// cavity-modes' options that take no value (main.cpp): skipped with nothing after them.
bool is_flag(const std::string& name) {
  for (const char* f : {"--fields", "--fill-gaps", "--no-convergence-check", "--galerkin", "--krylov", "--fit", "--serve", "--json", "-h",
                        "--help"})
    if (name == f) return true;
  return false;
}

// What the served forced solves need: the shape's dimensions and the viscous mesh.
bool is_kept(const std::string& name) {
  for (const char* k : {"--radius", "--height", "--inner-radius", "--a", "--c", "--order", "--mesh-size", "--radial-size", "--wall-size",
                        "--near-wall-size", "--mesh-ekman", "--fill"})
    if (name == k) return true;
  return false;
}

// A number as the command line takes it, to full precision.
}  // namespace

std::vector<std::string> serve_arguments(const rc::ModeTable& t, const fs::path& scratch, double ekman,
                                         double mesh_ekman) {
  return serve_arguments(t, scratch, ekman, mesh_ekman, ServedMesh{});
}

namespace {

// The shape and the kept options of the table's recorded command line (the section's file written from the table),
// less those that `mesh_ekman` and `mesh` replace. Sets `near_wall` when the line gives --near-wall-size.
std::vector<std::string> recorded_arguments(const rc::ModeTable& t, const fs::path& scratch, double mesh_ekman,
                                            const ServedMesh& mesh, bool& near_wall) {
  const std::vector<std::string> w = shell_words(t.command_line);
  std::size_t i = 1;
  if (i < w.size() && w[i] == "response") ++i;
  if (i >= w.size() || !is_shape(w[i]))
    throw std::runtime_error("its recorded command line names no shape: " + t.command_line);
  std::vector<std::string> args{"response", w[i]};
  const bool section = w[i] == "section";
  bool have_file = false;
  for (++i; i < w.size(); ++i) {
    std::string name = w[i], value;
    if (!(name.size() > 1 && name[0] == '-')) {  // a positional word: the section's file
      if (section && !have_file) args.push_back(section_file(t, name, scratch).string());
      have_file = have_file || section;
      continue;
    }
    const auto eq = name.find('=');
    const bool inline_value = eq != std::string::npos;
    if (inline_value) value = name.substr(eq + 1), name = name.substr(0, eq);
    if (is_flag(name)) continue;
    if (!inline_value && i + 1 < w.size()) value = w[++i];
    const bool replaced = (name == "--mesh-ekman" && mesh_ekman > 0) || (name == "--mesh-size" && mesh.mesh_size > 0) ||
                          (name == "--order" && (mesh.order > 0 || mesh.order_raise > 0));
    if (!is_kept(name) || replaced) continue;
    args.insert(args.end(), {name, value});
    near_wall = near_wall || name == "--near-wall-size";
  }
  if (section && !have_file) throw std::runtime_error("its recorded command line names no section file");
  return args;
}

// A mesh study's options (ServedMesh): the size and order in place of the table's, and the level.
void add_study_mesh(std::vector<std::string>& args, const rc::ModeTable& t, const ServedMesh& mesh) {
  if (mesh.mesh_size > 0) args.insert(args.end(), {"--mesh-size", number_text(mesh.mesh_size)});
  if (mesh.order > 0 || mesh.order_raise > 0) {
    const int order = (mesh.order > 0 ? mesh.order : t.fe_order) + mesh.order_raise;
    if (order > 6 || order < 2)
      throw std::runtime_error("a study in the order reaches order " + std::to_string(order) + ": Taylor-Hood orders are "
                               "2..6 (start from a lower --order, or refine by size)");
    args.insert(args.end(), {"--order", std::to_string(order)});
  }
  if (mesh.level > 0) args.insert(args.end(), {"--mesh-level", std::to_string(mesh.level)});
}

// A spectral table's (`cavity-modes shell ... --sigma ... -o FILE.h5`, docs/spherical.md): the shell's radius and
// truncation options as recorded (`--name value` or `--name=value`), so that the served solves are the table's own
// discretisation; a study's level raises the truncation 1.5 times a level on top of the table's own --mesh-level, and
// there is no mesh size or element order to replace.
std::vector<std::string> spectral_serve_arguments(const std::vector<std::string>& w, const rc::ModeTable& t,
                                                  double ekman, double mesh_ekman, const ServedMesh& mesh) {
  if (mesh.mesh_size > 0 || mesh.order > 0 || mesh.order_raise > 0)
    throw std::runtime_error("a spectral table (cavity-modes shell) has no mesh size or element order: its study "
                             "raises the truncation (--refine N, by size)");
  std::vector<std::string> args{"shell"};
  int level = mesh.level;
  for (std::size_t i = 2; i < w.size(); ++i) {
    std::string name = w[i], value;
    if (const auto eq = name.find('='); eq != std::string::npos) value = name.substr(eq + 1), name = name.substr(0, eq);
    else if (i + 1 < w.size()) value = w[i + 1];
    if (name == "--mesh-level") level += std::stoi(value);
    const bool kept = name == "--inner-radius" || name == "--resolution" || name == "--radial" || name == "--lmax" ||
                      (name == "--mesh-ekman" && !(mesh_ekman > 0));
    if (kept) args.insert(args.end(), {name, value});
  }
  args.insert(args.end(), {"--ekman", number_text(ekman > 0 ? ekman : t.ekman)});
  if (mesh_ekman > 0) args.insert(args.end(), {"--mesh-ekman", number_text(mesh_ekman)});
  if (level > 0) args.insert(args.end(), {"--mesh-level", std::to_string(level)});
  args.push_back("--serve");
  return args;
}

}  // namespace

std::vector<std::string> serve_arguments(const rc::ModeTable& t, const fs::path& scratch, double ekman,
                                         double mesh_ekman, const ServedMesh& mesh) {
  if (!t.viscous()) throw std::runtime_error("it is an ideal-fluid table (its roots need no confirmation)");
  if (t.command_line.empty()) throw std::runtime_error("it records no command line (made before provenance)");
  if (const std::vector<std::string> w = shell_words(t.command_line); w.size() > 1 && w[1] == "shell")
    return spectral_serve_arguments(w, t, ekman, mesh_ekman, mesh);
  bool near_wall = false;
  std::vector<std::string> args = recorded_arguments(t, scratch, mesh_ekman, mesh, near_wall);
  args.insert(args.end(), {"--ekman", number_text(ekman > 0 ? ekman : t.ekman)});
  if (mesh_ekman > 0) args.insert(args.end(), {"--mesh-ekman", number_text(mesh_ekman)});
  // A table's default near-wall zone (a whole cylinder or spheroid at Ek <= 1e-5) is not on its command line: the
  // table records the size it used.
  if (!near_wall && t.mesh_h_near_wall > 0 && !(mesh_ekman > 0))
    args.insert(args.end(), {"--near-wall-size", number_text(t.mesh_h_near_wall)});
  add_study_mesh(args, t, mesh);
  args.push_back("--serve");
  return args;
}

std::string cavity_modes_binary(const std::string& given) {
  if (!given.empty()) return given;
  if (const char* env = std::getenv("CAVITY_MODES"); env && *env) return env;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path sibling = self.parent_path().parent_path() / "modes" / "cavity-modes";
    if (fs::exists(sibling)) return sibling.string();
  }
  return "cavity-modes";
}

ServedResponse::ServedResponse(const std::string& binary, const std::vector<std::string>& args) {
  std::signal(SIGPIPE, SIG_IGN);  // a child that died is reported by the failed write, not by a signal
  std::array<int, 2> in{}, out{};  // in: chain-rom -> child's stdin; out: child's stdout -> chain-rom
  // Close-on-exec: a second child (one per tank) must not inherit this child's pipe ends, or closing ours would
  // never give this one its end of input (a scene with three tanks waited for ever).
  if (pipe2(in.data(), O_CLOEXEC) != 0 || pipe2(out.data(), O_CLOEXEC) != 0)
    throw std::runtime_error("cannot create a pipe");
  char tmpl[] = "/tmp/chain-rom-served-XXXXXX";
  const int err = mkostemp(tmpl, O_CLOEXEC);
  if (err < 0) throw std::runtime_error("cannot create a temporary file for cavity-modes' messages");
  stderr_file_ = tmpl;
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, in[0], 0);
  posix_spawn_file_actions_adddup2(&fa, out[1], 1);
  posix_spawn_file_actions_adddup2(&fa, err, 2);
  for (int fd : {in[0], in[1], out[0], out[1], err}) posix_spawn_file_actions_addclose(&fa, fd);
  std::vector<std::string> all{binary};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int rc = posix_spawnp(&pid_, binary.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  close(in[0]);
  close(out[1]);
  close(err);
  if (rc != 0) {
    close(in[1]);
    close(out[0]);
    pid_ = -1;
    throw std::runtime_error("cannot start " + binary + ": " + std::strerror(rc) +
                             " (give its path with --cavity-modes, or build it: scripts/build.sh)");
  }
  to_child_ = fdopen(in[1], "w");
  from_child_ = fdopen(out[0], "r");
  std::string first = read_line();
  while (!first.empty() && first.rfind("ready: ", 0) != 0) first = read_line();  // anything printed before it
  if (first.rfind("ready: ", 0) != 0) {
    const std::string why = child_error();
    shut();
    throw std::runtime_error("cavity-modes did not start: " + why);
  }
  ready_ = first.substr(7);
}

ServedResponse::~ServedResponse() { shut(); }

void ServedResponse::shut() {
  if (to_child_) std::fclose(to_child_);  // end of input: the child leaves its loop and exits
  if (from_child_) std::fclose(from_child_);
  to_child_ = from_child_ = nullptr;
  if (pid_ > 0) {
    int status = 0;
    waitpid(pid_, &status, 0);
  }
  pid_ = -1;
  std::error_code ec;
  if (!stderr_file_.empty()) fs::remove(stderr_file_, ec);
  stderr_file_.clear();
}

std::string ServedResponse::read_line() {
  std::string line;
  char buf[512];
  while (from_child_ && std::fgets(buf, sizeof buf, from_child_)) {
    line += buf;
    if (!line.empty() && line.back() == '\n') {
      line.pop_back();
      return line;
    }
  }
  return line;  // end of output: the child has exited
}

std::string ServedResponse::child_error() const {
  std::ifstream in(stderr_file_);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last.empty() ? "it exited without a message" : last;
}

long ServedResponse::unknowns() const {
  std::smatch m;
  static const std::regex re("\\((\\d+) real unknowns\\)");
  return std::regex_search(ready_, m, re) ? std::stol(m[1]) : 0;
}

std::vector<double> ServedResponse::ask(std::complex<double> s, int count) {
  if (std::fprintf(to_child_, "%.17g%+.17gi\n", s.real(), s.imag()) < 0 || std::fflush(to_child_) != 0)
    throw std::runtime_error("cavity-modes stopped answering: " + child_error());
  const std::string line = read_line();
  if (line.rfind("error: ", 0) == 0) throw std::runtime_error("cavity-modes: " + line.substr(7));
  std::istringstream in(line);
  std::vector<double> v(static_cast<std::size_t>(count));
  for (double& x : v)
    if (!(in >> x)) throw std::runtime_error("cavity-modes stopped answering: " + child_error());
  ++solves_;
  return v;
}

std::complex<double> ServedResponse::operator()(std::complex<double> s) {
  const std::vector<double> v = ask(s, 2);
  return {v[0], v[1]};
}

std::array<std::complex<double>, 3> ServedResponse::offset(std::complex<double> s) {
  const std::vector<double> v = ask(s, 6);
  return {std::complex<double>(v[0], v[1]), {v[2], v[3]}, {v[4], v[5]}};
}

}  // namespace rc::rom
