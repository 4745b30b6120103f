#include "complex_lu.hpp"

#include <zmumps_c.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rc::modes {

struct ComplexLu::Mumps {
  ZMUMPS_STRUC_C id{};
};

namespace {

int& icntl(ZMUMPS_STRUC_C& id, int k) { return id.icntl[k - 1]; }

// Why a phase failed, in words: INFOG(1) −9/−13/−17/−19/−20 are memory, −10 a singular matrix.
std::string describe(const ZMUMPS_STRUC_C& id) {
  const int info1 = id.infog[0], info2 = id.infog[1];
  const bool memory = info1 == -9 || info1 == -13 || info1 == -17 || info1 == -19 || info1 == -20;
  return "MUMPS INFOG(1) = " + std::to_string(info1) + ", INFOG(2) = " + std::to_string(info2) +
         (memory ? " (out of memory: a coarser --mesh-size/--wall-size, or mpirun over more memory)"
                 : info1 == -10 ? " (singular matrix: the shift on an eigenvalue?)"
                 : info1 == -38 ? " (a parallel ordering asked for, ICNTL(28) = 2: this MUMPS has neither PT-SCOTCH nor "
                                  "ParMETIS)"
                                : "");
}

// ICNTL(k) and CNTL(k) from the options database, as PETSc's MUMPS interface names them.
void read_options(ZMUMPS_STRUC_C& id, const std::string& prefix) {
  for (int k = 1; k <= 60; ++k) {
    PetscInt value = 0;
    PetscBool set = PETSC_FALSE;
    const std::string name = "-mat_mumps_icntl_" + std::to_string(k);
    petsc_check(PetscOptionsGetInt(nullptr, prefix.c_str(), name.c_str(), &value, &set), "PetscOptionsGetInt");
    if (set) icntl(id, k) = static_cast<int>(value);
  }
  for (int k = 1; k <= 15; ++k) {
    PetscReal value = 0;
    PetscBool set = PETSC_FALSE;
    const std::string name = "-mat_mumps_cntl_" + std::to_string(k);
    petsc_check(PetscOptionsGetReal(nullptr, prefix.c_str(), name.c_str(), &value, &set), "PetscOptionsGetReal");
    if (set) id.cntl[k - 1] = value;
  }
}

}  // namespace

ComplexLu::ComplexLu(MPI_Comm comm, std::string prefix, bool complex_symmetric)
    : mumps_(std::make_unique<Mumps>()), prefix_(std::move(prefix)), comm_(comm) {
  ZMUMPS_STRUC_C& id = mumps_->id;
  id.comm_fortran = static_cast<int>(MPI_Comm_c2f(comm));
  id.par = 1;  // rank 0 works too
  // LU unless told the matrix is complex symmetric. The eigensolvers keep LU: SYM = 2 on their shifted operator's
  // lower triangle once found a wrong mode (the cause not found); the response solves are checked against LU
  // (test ViscousFreeSurface.SymmetricFactorsSolveAsTheLu).
  id.sym = complex_symmetric ? 2 : 0;
  run(-1, "initialisation");
  icntl(id, 1) = 0;  // errors are reported through INFOG, not printed (0, not −1: with parallel analysis
                     // MUMPS 5.5 still writes to the unit and a negative one aborts the run)
  icntl(id, 2) = 0;
  icntl(id, 3) = 0;
  icntl(id, 4) = 0;
  // Null-pivot detection: a Taylor–Hood triangle with no interior vertex carries a massless spurious pressure mode.
  icntl(id, 24) = 1;
  // 100 % more workspace than estimated: the zero pressure block makes MUMPS delay many pivots (about 24 000 of
  // 200 000 on the Ek = 1e-4 sphere); the default 20 % overran (INFOG(1) = −9).
  icntl(id, 14) = 100;
  read_options(id, prefix_);
  // The layout this interface hands MUMPS, whatever the options say: the matrix distributed by rows, the dense
  // right-hand side and solution centralised on rank 0.
  icntl(id, 18) = 3;
  icntl(id, 20) = 0;
  icntl(id, 21) = 0;
}

ComplexLu::~ComplexLu() {
  ZMUMPS_STRUC_C& id = mumps_->id;
  id.job = -2;
  zmumps_c(&id);  // frees MUMPS's own memory; nothing to report from a destructor
}

int ComplexLu::infog(int k) const { return mumps_->id.infog[k - 1]; }

void ComplexLu::run(int job, const char* phase) {
  ZMUMPS_STRUC_C& id = mumps_->id;
  id.job = job;
  zmumps_c(&id);
  if (id.infog[0] < 0) throw std::runtime_error(std::string("the complex LU's ") + phase + " failed: " + describe(id));
}

// This rank's complex entries of the block matrix: equation i's row 2i holds Re S_ij at column 2j, row 2i + 1 holds
// Im S_ij there (the odd columns repeat them). The pattern is the union of the two rows' even columns.
void ComplexLu::extract(Mat block) {
  PetscInt lo = 0, hi = 0;
  petsc_check(MatGetOwnershipRange(block, &lo, &hi), "MatGetOwnershipRange");
  if (lo % 2 != 0 || hi % 2 != 0) throw std::logic_error("ComplexLu: a complex unknown straddles two ranks");
  std::vector<int> rows, cols;
  std::vector<std::complex<double>> values;
  std::vector<std::pair<PetscInt, std::complex<double>>> line;
  const bool lower_only = mumps_->id.sym == 2;
  for (PetscInt r = lo; r < hi; r += 2) {
    line.clear();
    for (int part : {0, 1}) {
      PetscInt n = 0;
      const PetscInt* c = nullptr;
      const PetscScalar* v = nullptr;
      petsc_check(MatGetRow(block, r + part, &n, &c, &v), "MatGetRow");
      for (PetscInt k = 0; k < n; ++k)
        if (c[k] % 2 == 0) line.emplace_back(c[k] / 2, part == 0 ? std::complex<double>(v[k], 0) : std::complex<double>(0, v[k]));
      petsc_check(MatRestoreRow(block, r + part, &n, &c, &v), "MatRestoreRow");
    }
    std::sort(line.begin(), line.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 0; k < line.size(); ++k) {
      if (lower_only && line[k].first > r / 2) continue;  // LDLᵀ reads the lower triangle only
      if (k > 0 && line[k].first == line[k - 1].first) { values.back() += line[k].second; continue; }
      rows.push_back(static_cast<int>(r / 2 + 1));
      cols.push_back(static_cast<int>(line[k].first + 1));
      values.push_back(line[k].second);
    }
  }
  if (analysed_ && (rows != rows_ || cols != cols_)) analysed_ = false;  // a new pattern: analyse again
  rows_ = std::move(rows);
  cols_ = std::move(cols);
  values_ = std::move(values);
}

void ComplexLu::factor(Mat block) {
  PetscInt n = 0;
  petsc_check(MatGetSize(block, &n, nullptr), "MatGetSize");
  extract(block);
  ZMUMPS_STRUC_C& id = mumps_->id;
  id.n = static_cast<int>(n / 2);
  id.nnz_loc = static_cast<MUMPS_INT8>(rows_.size());
  id.irn_loc = rows_.data();
  id.jcn_loc = cols_.data();
  id.a_loc = reinterpret_cast<ZMUMPS_COMPLEX*>(values_.data());
  factored_ = false;
  if (!analysed_) {
    run(1, "analysis");
    analysed_ = true;
  }
  run(2, "factorisation");
  factored_ = true;
}

void ComplexLu::solve(Vec b, Vec x, bool transposed) {
  if (!factored_) throw std::logic_error("ComplexLu::solve before factor");
  if (gather_.get() == nullptr) petsc_check(VecScatterCreateToZero(b, gather_.out(), gathered_.out()), "VecScatterCreateToZero");
  petsc_check(VecScatterBegin(gather_, b, gathered_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  petsc_check(VecScatterEnd(gather_, b, gathered_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  PetscInt local = 0;
  petsc_check(VecGetLocalSize(gathered_, &local), "VecGetLocalSize");
  PetscScalar* data = nullptr;
  petsc_check(VecGetArray(gathered_, &data), "VecGetArray");
  ZMUMPS_STRUC_C& id = mumps_->id;
  // Rank 0 holds the whole vector: its (Re, Im) pairs are the complex right-hand side, solved in place.
  id.rhs = reinterpret_cast<ZMUMPS_COMPLEX*>(data);
  id.nrhs = 1;
  id.lrhs = static_cast<int>(local / 2);
  icntl(id, 9) = transposed ? 0 : 1;  // MUMPS: 1 solves S x = b, anything else Sᵀ x = b
  std::string error;
  try {
    run(3, "solve");
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  petsc_check(VecRestoreArray(gathered_, &data), "VecRestoreArray");
  if (!error.empty()) throw std::runtime_error(error);
  petsc_check(VecScatterBegin(gather_, gathered_, x, INSERT_VALUES, SCATTER_REVERSE), "VecScatterBegin");
  petsc_check(VecScatterEnd(gather_, gathered_, x, INSERT_VALUES, SCATTER_REVERSE), "VecScatterEnd");
}

}  // namespace rc::modes
