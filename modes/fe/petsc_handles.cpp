#include "petsc_handles.hpp"

#include <slepcsys.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace rc::modes {

void petsc_check(PetscErrorCode ierr, const char* what) {
  if (ierr == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(ierr, &text, nullptr);
  throw std::runtime_error(std::string(what) + ": PETSc error " + std::to_string(static_cast<int>(ierr)) +
                           (text ? std::string(" (") + text + ")" : std::string()));
}

namespace {

// Serial runs (no mpirun; the default) start MPI as a singleton. Started outside mpirun, OpenMPI's start-up probes network
// transports and a runtime daemon, which costs ~0.3 s per process — measured: MPI_Init 0.31 s by default,
// 0.03 s with these settings. Values the user has set are kept; under mpirun nothing is changed.
// Each singleton also gets its own session directory: OpenMPI 4 puts every singleton's under one shared
// <tmp>/ompi.<host>.<uid>/jf.0, and a process finishing while another starts can remove it under the starter
// ("A call to mkdir was unable to create the desired directory", orte_init failed) — seen once with two test
// processes and a long run side by side. Returns the directory to remove at the end ("" if none was made).
std::string fast_serial_mpi_startup() {
  if (std::getenv("OMPI_COMM_WORLD_SIZE")) return "";
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_pml", "ob1", 0);
  setenv("OMPI_MCA_btl", "self", 0);
  if (std::getenv("OMPI_MCA_orte_tmpdir_base")) return "";
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/rc-ompi-XXXXXX";
  if (!mkdtemp(pattern.data())) return "";  // OpenMPI's default then
  setenv("OMPI_MCA_orte_tmpdir_base", pattern.c_str(), 1);
  return pattern;
}

}  // namespace

PetscSession::PetscSession(int* argc, char*** argv) {
  session_dir_ = fast_serial_mpi_startup();
  // PETSc prints a multi-line traceback for every error by default; we report one line ourselves.
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  petsc_check(SlepcInitialize(argc, argv, nullptr, nullptr), "SlepcInitialize");
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
}

PetscSession::~PetscSession() {
  SlepcFinalize();
  if (!session_dir_.empty()) {
    std::error_code ec;
    std::filesystem::remove_all(session_dir_, ec);
  }
}

}  // namespace rc::modes

namespace rc::modes {

ST pep_shift_invert_mumps(PEP pep, PCType pc_type) {
  ST st;
  KSP ksp;
  PC pc;
  petsc_check(PEPGetST(pep, &st), "PEPGetST");
  petsc_check(STSetType(st, STSINVERT), "STSetType");
  petsc_check(STGetKSP(st, &ksp), "STGetKSP");
  petsc_check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
  petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, pc_type), "PCSetType");
  petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  return st;
}

bool is_root_rank() {
  PetscBool initialised = PETSC_FALSE;
  PetscInitialized(&initialised);
  if (!initialised) {
    // Before PetscInitialize or after PetscFinalize (a command-line error, an error caught in main): the rank the
    // launcher gave this process, so that under mpirun one process prints the error line, not each.
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
      if (const char* value = std::getenv(name)) return std::string(value) == "0";
    return true;
  }
  PetscMPIInt rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  return rank == 0;
}

int world_ranks() {
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  return ranks;
}

}  // namespace rc::modes
