// Small RAII owners for PETSc/SLEPc objects and an error check that turns a PETSc error code into a
// one-line C++ exception (PETSc's own tracebacks are switched off by PetscSession).
#pragma once

#include <petscksp.h>
#include <slepcpep.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace rc::modes {

// Throws std::runtime_error("<what>: PETSc error <code>: <message>") when ierr != 0.
void petsc_check(PetscErrorCode ierr, const char* what);

template <class T, PetscErrorCode (*Destroy)(T*)>
class PetscHandle {
 public:
  PetscHandle() = default;
  explicit PetscHandle(T obj) : obj_(obj) {}
  PetscHandle(const PetscHandle&) = delete;
  PetscHandle& operator=(const PetscHandle&) = delete;
  PetscHandle(PetscHandle&& o) noexcept : obj_(std::exchange(o.obj_, nullptr)) {}
  PetscHandle& operator=(PetscHandle&& o) noexcept {
    if (this != &o) { reset(); obj_ = std::exchange(o.obj_, nullptr); }
    return *this;
  }
  ~PetscHandle() { reset(); }
  void reset() { if (obj_) Destroy(&obj_); obj_ = nullptr; }
  T get() const { return obj_; }
  T* out() { reset(); return &obj_; }   // for PETSc "create" calls that fill a T*
  operator T() const { return obj_; }   // NOLINT: handles read like the raw objects in PETSc calls
 private:
  T obj_ = nullptr;
};

using PMat = PetscHandle<Mat, MatDestroy>;
using PVec = PetscHandle<Vec, VecDestroy>;
using PKSP = PetscHandle<KSP, KSPDestroy>;
using PPEP = PetscHandle<PEP, PEPDestroy>;
using PVecScatter = PetscHandle<VecScatter, VecScatterDestroy>;

// A polynomial eigensolver's spectral transformation: shift-and-invert, each shift's matrix factorised once by MUMPS
// (pc_type PCLU or PCCHOLESKY), no Krylov iterations around the factorisation. Returns the ST for further settings.
ST pep_shift_invert_mumps(PEP pep, PCType pc_type);

// True on rank 0 of PETSC_COMM_WORLD: the rank that prints and writes. When PETSc is not initialised, the rank an
// MPI launcher gave the process (OMPI_COMM_WORLD_RANK, PMIX_RANK, PMI_RANK) is 0, or there is none.
bool is_root_rank();

// The number of ranks of PETSC_COMM_WORLD (PETSc initialised).
int world_ranks();

// Initialises SLEPc (and PETSc, MPI) for the lifetime of the object, passing command-line options
// such as -pep_type or -log_view through to PETSc's options database.
class PetscSession {
 public:
  PetscSession(int* argc, char*** argv);
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;

 private:
  std::string session_dir_;  // this process's own OpenMPI session directory (serial runs), removed at the end
};

}  // namespace rc::modes
