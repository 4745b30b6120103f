#include "gmsh_session.hpp"

#include <gmsh.h>

#include "gmsh_library.hpp"

#include <stdexcept>
#include <vector>

namespace rc::geometry::detail {
namespace {

std::recursive_mutex& gmsh_mutex() {
  static std::recursive_mutex m;
  return m;
}

int depth = 0;  // open sessions on the lock-holding thread (guarded by gmsh_mutex)

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

}  // namespace

GmshSession::GmshSession() : lock_(gmsh_mutex()) {
  load_gmsh();  // cavity-modes opens libgmsh only when a command meshes (gmsh_library.hpp)
  outermost_ = depth++ == 0;
  if (!outermost_) {
    std::vector<std::string> log;
    gmsh::logger::get(log);
    log_seen_ = log.size();  // the enclosing session reports what came before
    return;
  }
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  // 0: log errors and carry on. With the default (2) gmsh throws from inside its parser and
  // leaves it flagged busy, so every later open() in the process would be silently ignored.
  gmsh::option::setNumber("General.AbortOnError", 0);
  gmsh::logger::start();
}

GmshSession::~GmshSession() {
  if (outermost_) {
    try {
      gmsh::logger::stop();
      gmsh::finalize();
    } catch (...) {
      // finalize must not throw out of a destructor; nothing useful to do.
    }
  }
  --depth;
}

void GmshSession::throw_if_error(const std::string& context) {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  const std::string tag = "Error: ";
  for (std::size_t i = log_seen_; i < log.size(); ++i) {
    if (log[i].rfind(tag, 0) != 0) continue;
    log_seen_ = log.size();  // report each error once
    throw std::runtime_error(context + ": " + one_line(log[i].substr(tag.size())));
  }
  log_seen_ = log.size();
}

void GmshSession::forgive_logged() {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  log_seen_ = log.size();
}

}  // namespace rc::geometry::detail
