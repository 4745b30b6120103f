// Opens libgmsh when a command first needs it, so that commands which mesh nothing start fast.
#pragma once

namespace rc::geometry {

// Makes the gmsh API callable. In the test programs, which list libgmsh among their NEEDED libraries, it is
// already loaded and this does nothing. cavity-modes' link step drops libgmsh from that list (modes/CMakeLists.txt):
// the dynamic loader spends most of a bare start binding libgmsh's and OpenCASCADE's symbols (docs/benchmarks.md,
// "cavity-modes' start"), which `--help`, `info`, `compare` and every refused command line never use. Here libgmsh
// is opened with RTLD_GLOBAL, and the executable's lazily bound calls into gmsh resolve there.
// Idempotent and cheap after the first call. Throws std::runtime_error naming the library when it cannot be opened.
void load_gmsh();

}  // namespace rc::geometry
