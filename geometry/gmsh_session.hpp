// Internal to rc_geometry: scoped, quiet, exception-safe use of the gmsh API.
#pragma once

#include <cstddef>
#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace rc::geometry::detail {

// Holds gmsh for the lifetime of the object. gmsh is one global, non-thread-safe state, so the
// session takes a process-wide lock; the outermost session initializes gmsh (quiet, no config
// files, errors logged instead of thrown) and finalizes it, which also clears every model and
// gmsh's own "busy" flags. gmsh 4.8 has no isInitialized(), so rc_geometry owns gmsh: other code
// must not initialize or finalize it while a session is open.
class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  // Throws std::runtime_error("<context>: <first gmsh error>") if gmsh logged an error since the
  // session started (or since the last call).
  void throw_if_error(const std::string& context);

  // Forgets what gmsh logged so far: for a step whose errors the caller judges by its result instead (the high-order
  // optimiser's "failed to reach" leaves a mesh that check_jacobians accepts or refuses).
  void forgive_logged();

 private:
  std::unique_lock<std::recursive_mutex> lock_;
  bool outermost_ = false;
  std::size_t log_seen_ = 0;  // gmsh log lines already checked for errors
};

// Runs f() inside a session; anything gmsh throws (it may throw non-std types) and any error it
// logs becomes a one-line std::runtime_error prefixed with `context`.
template <class F>
auto with_gmsh(const std::string& context, F&& f) {
  GmshSession session;
  try {
    if constexpr (std::is_void_v<decltype(f(session))>) {
      f(session);
      session.throw_if_error(context);
    } else {
      auto result = f(session);
      session.throw_if_error(context);
      return result;
    }
  } catch (const std::runtime_error&) {
    throw;
  } catch (const std::exception& e) {
    session.throw_if_error(context);
    throw std::runtime_error(context + ": " + e.what());
  } catch (...) {
    session.throw_if_error(context);
    throw std::runtime_error(context + ": gmsh failed without a message");
  }
}

}  // namespace rc::geometry::detail
