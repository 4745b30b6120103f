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
ComplexLu::Entries ComplexLu::read(Mat block) const {
  PetscInt lo = 0, hi = 0;
  petsc_check(MatGetOwnershipRange(block, &lo, &hi), "MatGetOwnershipRange");
  if (lo % 2 != 0 || hi % 2 != 0) throw std::logic_error("ComplexLu: a complex unknown straddles two ranks");
  Entries out;
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
      if (k > 0 && line[k].first == line[k - 1].first) { out.values.back() += line[k].second; continue; }
      out.rows.push_back(static_cast<int>(r / 2 + 1));
      out.cols.push_back(static_cast<int>(line[k].first + 1));
      out.values.push_back(line[k].second);
    }
  }
  return out;
}

void ComplexLu::factor(Mat block) {
  PetscInt n = 0;
  petsc_check(MatGetSize(block, &n, nullptr), "MatGetSize");
  Entries e = read(block);
  if (analysed_ && (e.rows != rows_ || e.cols != cols_)) analysed_ = false;  // a new pattern: analyse again
  rows_ = std::move(e.rows);
  cols_ = std::move(e.cols);
  values_ = std::move(e.values);
  factor_numerically(n);
}

std::vector<std::complex<double>> ComplexLu::entries(Mat block) const {
  if (!analysed_) throw std::logic_error("ComplexLu::entries before factor");
  const Entries e = read(block);
  std::vector<std::complex<double>> out(rows_.size());
  // Both lists run row by row with sorted columns: one merge walk.
  std::size_t at = 0;
  for (std::size_t k = 0; k < e.rows.size(); ++k) {
    while (at < rows_.size() && (rows_[at] < e.rows[k] || (rows_[at] == e.rows[k] && cols_[at] < e.cols[k]))) ++at;
    if (at == rows_.size() || rows_[at] != e.rows[k] || cols_[at] != e.cols[k])
      throw std::logic_error("ComplexLu::entries: the matrix has an entry outside the factored pattern");
    out[at] = e.values[k];
  }
  return out;
}

void ComplexLu::factor(std::vector<std::complex<double>> values) {
  if (!analysed_ || values.size() != rows_.size())
    throw std::logic_error("ComplexLu::factor(values): no analysed pattern of this size");
  values_ = std::move(values);
  factor_numerically(block_size_);
}

void ComplexLu::factor_numerically(PetscInt block_size) {
  block_size_ = block_size;
  ZMUMPS_STRUC_C& id = mumps_->id;
  id.n = static_cast<int>(block_size / 2);
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

void ComplexLu::solve(Vec b, Vec x, bool transposed) { solve(std::vector<Vec>{b}, std::vector<Vec>{x}, transposed); }

// Rank 0 gathers every right-hand side into one column-major array (its (Re, Im) pairs the complex entries) that MUMPS
// solves in place, all columns in one pass over the factors; the columns are then scattered back.
void ComplexLu::solve(const std::vector<Vec>& b, const std::vector<Vec>& x, bool transposed) {
  if (!factored_) throw std::logic_error("ComplexLu::solve before factor");
  if (b.size() != x.size() || b.empty()) throw std::logic_error("ComplexLu::solve: as many solutions as right-hand sides");
  if (gather_.get() == nullptr) petsc_check(VecScatterCreateToZero(b[0], gather_.out(), gathered_.out()), "VecScatterCreateToZero");
  PetscInt local = 0;
  petsc_check(VecGetLocalSize(gathered_, &local), "VecGetLocalSize");
  const std::size_t columns = b.size();
  std::vector<PetscScalar> all(static_cast<std::size_t>(local) * columns);
  const auto column = [&](std::size_t k) { return all.data() + k * static_cast<std::size_t>(local); };
  for (std::size_t k = 0; k < columns; ++k) {
    petsc_check(VecScatterBegin(gather_, b[k], gathered_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
    petsc_check(VecScatterEnd(gather_, b[k], gathered_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
    const PetscScalar* data = nullptr;
    petsc_check(VecGetArrayRead(gathered_, &data), "VecGetArrayRead");
    std::copy_n(data, local, column(k));
    petsc_check(VecRestoreArrayRead(gathered_, &data), "VecRestoreArrayRead");
  }
  ZMUMPS_STRUC_C& id = mumps_->id;
  id.rhs = reinterpret_cast<ZMUMPS_COMPLEX*>(all.data());
  id.nrhs = static_cast<int>(columns);
  id.lrhs = static_cast<int>(local / 2);
  icntl(id, 9) = transposed ? 0 : 1;  // MUMPS: 1 solves S x = b, anything else Sᵀ x = b
  run(3, "solve");
  for (std::size_t k = 0; k < columns; ++k) {
    PetscScalar* data = nullptr;
    petsc_check(VecGetArray(gathered_, &data), "VecGetArray");
    std::copy_n(column(k), local, data);
    petsc_check(VecRestoreArray(gathered_, &data), "VecRestoreArray");
    petsc_check(VecScatterBegin(gather_, gathered_, x[k], INSERT_VALUES, SCATTER_REVERSE), "VecScatterBegin");
    petsc_check(VecScatterEnd(gather_, gathered_, x[k], INSERT_VALUES, SCATTER_REVERSE), "VecScatterEnd");
  }
}

}  // namespace rc::modes
