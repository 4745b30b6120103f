// rc-mesher: one meridian mesh per run, for mesh_meridian_isolated (geometry/isolated_mesh.hpp), which starts it with
// no environment and the address-space randomisation off so that its heap, and so gmsh's mesh, is the same on every
// run. Reads the request on standard input, writes the mesh on standard output; not a command for users.
#include "isolated_mesh.hpp"

#include <unistd.h>

int main() { return rc::geometry::run_mesher(STDIN_FILENO, STDOUT_FILENO); }
