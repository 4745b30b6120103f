# All dependencies come from Debian packages (scripts/install-deps.sh). PETSc links the OpenMPI
# build of HDF5, so we link that same flavour everywhere (hdf5-openmpi.pc).
find_package(PkgConfig REQUIRED)
find_package(fmt REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json REQUIRED)
pkg_check_modules(HDF5 REQUIRED IMPORTED_TARGET hdf5-openmpi)

if(RC_BUILD_MODES)
  pkg_check_modules(PETSC REQUIRED IMPORTED_TARGET PETSc)
  pkg_check_modules(SLEPC REQUIRED IMPORTED_TARGET SLEPc)
  # zgemm for the Krylov response basis (modes/fe/dense_blas.*): libblas-dev's link name; at run time Debian's
  # alternatives give the OpenBLAS that MUMPS uses too.
  find_package(BLAS REQUIRED)
  find_library(GMSH_LIBRARY NAMES gmsh REQUIRED)
  find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
  add_library(gmsh::gmsh UNKNOWN IMPORTED)
  set_target_properties(gmsh::gmsh PROPERTIES IMPORTED_LOCATION ${GMSH_LIBRARY}
                        INTERFACE_INCLUDE_DIRECTORIES ${GMSH_INCLUDE_DIR})
endif()
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
if(RC_BUILD_ROM)
  pkg_check_modules(TOMLPP REQUIRED IMPORTED_TARGET tomlplusplus)
endif()
if(RC_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
# PETSc's pkg-config file omits MPI's include path.
if(RC_BUILD_MODES)
  find_package(MPI REQUIRED COMPONENTS C)
endif()
