# libgmsh opened at a program's first mesh, not at its start (geometry/gmsh_library.hpp; docs/benchmarks.md,
# "cavity-modes' start"). libgmsh is linked BIND_NOW: binding its and OpenCASCADE's symbols was 0.19 s of cavity-modes'
# 0.26 s start, paid by `--help`, `info` and every refused command line, and by every process of a test program.
# The link still checks every gmsh symbol against libgmsh; patchelf then takes libgmsh off the program's NEEDED list,
# and the calls into gmsh (all through the PLT, bound lazily) resolve once geometry::load_gmsh() has opened it.

# The name the dynamic loader knows libgmsh by (libgmsh.so.4.8 on Debian 12).
execute_process(COMMAND objdump -p ${GMSH_LIBRARY} OUTPUT_VARIABLE GMSH_DYNAMIC_SECTION ERROR_QUIET)
string(REGEX MATCH "SONAME +([^\n ]+)" GMSH_SONAME_LINE "${GMSH_DYNAMIC_SECTION}")
set(GMSH_SONAME "${CMAKE_MATCH_1}")
if(NOT GMSH_SONAME)
  message(FATAL_ERROR "cannot read the SONAME of ${GMSH_LIBRARY} (objdump -p, from binutils)")
endif()
# Without patchelf (scripts/install-deps.sh installs it) a program loads gmsh at start, as before.
find_program(PATCHELF_PROGRAM patchelf)

# rc_open_gmsh_at_first_mesh(TARGET): TARGET's calls into gmsh go through rc_geometry (a GmshSession loads it) or
# call geometry::load_gmsh() first.
function(rc_open_gmsh_at_first_mesh target)
  if(PATCHELF_PROGRAM)
    target_link_options(${target} PRIVATE -Wl,-z,lazy)
    add_custom_command(TARGET ${target} POST_BUILD
                       COMMAND ${PATCHELF_PROGRAM} --remove-needed ${GMSH_SONAME} $<TARGET_FILE:${target}>
                       COMMENT "${target}: libgmsh opened at the first mesh, not at start")
  endif()
endfunction()
