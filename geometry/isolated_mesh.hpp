// gmsh run in a child process: a crash or a hang inside gmsh becomes a one-line error instead of the end of the
// program. gmsh 4.8's BoundaryLayer field crashes (a segmentation fault in its Delaunay, DocRecord) or hangs on some
// user sections at some sizes, and a signal cannot be caught in the process that raised it (measured 2026-12-02:
// data/sections/cone.geo filled to 0.8 at Ek = 1e-3, interior sizes 0.1 and 0.08; docs/geometry.md, "Wall-refined
// meshes"). Its callers then try another mesh (modes/viscous/viscous_mesh.hpp).
#pragma once

#include "meridian_mesh.hpp"

namespace rc::geometry {

// mesh_meridian(shape, options) in a child process (POSIX fork, then the mesher program, rc-mesher, with no
// environment and the address-space randomisation off; the child calls no MPI), its mesh sent back through a pipe.
// The same request then gives the same mesh in every run, whatever the asking process's environment: gmsh's
// BoundaryLayer field does not otherwise (docs/viscous.md, "Reproducible tables"). Throws std::runtime_error with
// mesh_meridian's own message, or saying that gmsh crashed (the signal) or took longer than `seconds`.
MeridianMesh mesh_meridian_isolated(const ShapeSpec& shape, const MeshOptions& options, double seconds);

// The mesher program's work (geometry/mesher_main.cpp): reads one request from `request_fd` to its end, meshes it and
// writes the mesh (or the error's message) to `result_fd`. Returns the program's exit code.
int run_mesher(int request_fd, int result_fd);

}  // namespace rc::geometry
