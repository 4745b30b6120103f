#include "petsc_handles.hpp"

#include <slepcsys.h>

namespace rc::modes {

void petsc_check(PetscErrorCode ierr, const char* what) {
  if (ierr == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(ierr, &text, nullptr);
  throw std::runtime_error(std::string(what) + ": PETSc error " + std::to_string(static_cast<int>(ierr)) +
                           (text ? std::string(" (") + text + ")" : std::string()));
}

PetscSession::PetscSession(int* argc, char*** argv) {
  // PETSc prints a multi-line traceback for every error by default; we report one line ourselves.
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  petsc_check(SlepcInitialize(argc, argv, nullptr, nullptr), "SlepcInitialize");
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
}

PetscSession::~PetscSession() { SlepcFinalize(); }

}  // namespace rc::modes
