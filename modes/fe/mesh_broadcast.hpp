// Under mpirun every rank needs the same mesh, and gmsh does not promise the same mesh from two concurrent runs
// (measured: two ranks meshing the same layered section got different node coordinates). Rank 0 meshes and
// sends the result to the others.
#pragma once

#include "meridian_mesh.hpp"
#include "volume_mesh.hpp"

#include <petscsys.h>  // MPI, without the C++ bindings

#include <functional>

namespace rc::modes {

// Calls make() on rank 0 of comm and broadcasts its mesh; an exception on rank 0 is re-thrown on every rank
// with the same one-line message.
geometry::MeridianMesh mesh_on_root(const std::function<geometry::MeridianMesh()>& make, MPI_Comm comm);

// The same for a 3-D cavity's mesh.
geometry::VolumeMesh volume_mesh_on_root(const std::function<geometry::VolumeMesh()>& make, MPI_Comm comm);

}  // namespace rc::modes
