#include "gmsh_library.hpp"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

namespace rc::geometry {

void load_gmsh() {
  static std::mutex m;
  static bool loaded = false;
  const std::lock_guard<std::mutex> lock(m);
  if (loaded) return;
  // RTLD_GLOBAL: the executable's unresolved gmsh calls are looked up in the global scope. The handle is never
  // closed: gmsh stays loaded for the process, as a NEEDED library would.
  if (dlopen(RC_GMSH_SONAME, RTLD_NOW | RTLD_GLOBAL) == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(std::string("cannot open the gmsh library ") + RC_GMSH_SONAME + ": " +
                             (why ? why : "unknown reason") + " (install libgmsh-dev: scripts/install-deps.sh)");
  }
  loaded = true;
}

}  // namespace rc::geometry
