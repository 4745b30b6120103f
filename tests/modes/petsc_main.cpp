// GoogleTest main for tests that need PETSc/SLEPc: one SLEPc session around all tests.
#include "petsc_handles.hpp"

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  int petsc_argc = 1;
  char** petsc_argv = argv;
  rc::modes::PetscSession session(&petsc_argc, &petsc_argv);
  return RUN_ALL_TESTS();
}
