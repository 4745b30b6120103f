// The LU factorisation of a complex matrix that PETSc (built for real scalars) holds in its real block form: complex
// unknown j's real and imaginary parts in slots 2j and 2j + 1 (rows 2i and 2i + 1 the real and imaginary parts of
// equation i), the layout of the viscous forms (viscous_forms.hpp). MUMPS factors it in complex arithmetic (ZMUMPS)
// rather than as a real matrix of twice the order: a complex multiply-add is 8 flops where the same 2 × 2 real block
// costs 16, the factors take half the memory, and the ordering works on a graph of half the size — measured in
// docs/benchmarks.md, "Complex factorisation".
//
// A block vector is read as the complex vector it holds (its interleaved pairs are std::complex<double>'s layout).
// Under MPI the matrix goes to MUMPS distributed (each rank its own rows, ICNTL(18) = 3) and the right-hand side is
// gathered on rank 0 and the solution scattered back (MUMPS's centralised dense right-hand side).
//
// Options: -<prefix>mat_mumps_icntl_<k> V and -<prefix>mat_mumps_cntl_<k> V set MUMPS's ICNTL(k) and CNTL(k), as
// PETSc's own MUMPS interface reads them, so the prefixes documented for the viscous solvers keep their meaning
// (all but ICNTL 18, 20 and 21, this interface's data layout).
#pragma once

#include "petsc_handles.hpp"

#include <complex>
#include <memory>
#include <string>
#include <vector>

namespace rc::modes {

class ComplexLu {
 public:
  // `prefix` is the options prefix ("viscous_st_", "response_"); comm the matrices' communicator. A complex symmetric
  // matrix (Sᵀ = S, not Hermitian) is factored as LDLᵀ from its lower triangle (MUMPS SYM = 2, with 2 × 2 pivots for
  // the zero pressure block): 20 % less time than LU on the viscous forms (docs/viscous.md, "Krylov response table").
  ComplexLu(MPI_Comm comm, std::string prefix, bool complex_symmetric = false);
  ~ComplexLu();
  ComplexLu(const ComplexLu&) = delete;
  ComplexLu& operator=(const ComplexLu&) = delete;

  // Factors the complex matrix held by `block`. The ordering and symbolic analysis are kept and reused while the
  // pattern stays the same (a new σ on the same forms costs the numerical factorisation only). Throws
  // std::runtime_error naming MUMPS's cause (singular, out of memory) when it fails.
  void factor(Mat block);

  // The complex entries of `block` at the pattern of the last factor(Mat), in its order (zero where `block` has none;
  // its pattern must lie within that one's). With them a pencil's matrices are read once and each new shift combined
  // entry by entry (shifted_solver.hpp).
  std::vector<std::complex<double>> entries(Mat block) const;

  // Factors the matrix with these entries (entries()' order) on the pattern of the last factor(Mat), reusing its
  // ordering and analysis: no sparse matrix is copied or read.
  void factor(std::vector<std::complex<double>> values);

  // x = S⁻¹ b on block vectors (x and b may not alias); with `transposed`, x = S⁻ᵀ b (the plain transpose, not the
  // conjugate: a non-symmetric pencil's left eigenvectors, viscous_eigensolver.hpp). Throws std::runtime_error when
  // MUMPS's solve fails.
  void solve(Vec b, Vec x, bool transposed = false);
  // x[k] = S⁻¹ b[k] for every k in one MUMPS solve (one pass over the factors for all columns).
  void solve(const std::vector<Vec>& b, const std::vector<Vec>& x, bool transposed = false);

  // MUMPS's INFOG(k) of the last phase (for reports: INFOG(28) the null pivots, INFOG(3) the factors' entries).
  int infog(int k) const;

 private:
  struct Mumps;
  // This rank's complex entries of a block matrix, rows in order and columns sorted within each, 1-based.
  struct Entries {
    std::vector<int> rows, cols;
    std::vector<std::complex<double>> values;
  };
  Entries read(Mat block) const;
  void factor_numerically(PetscInt block_size);
  void run(int job, const char* phase);
  std::unique_ptr<Mumps> mumps_;
  std::string prefix_;
  MPI_Comm comm_;
  std::vector<int> rows_, cols_;  // this rank's entries, 1-based, as MUMPS analysed them
  std::vector<std::complex<double>> values_;
  PetscInt block_size_ = 0;  // the block matrix's order (twice the complex one)
  bool analysed_ = false, factored_ = false;
  PetscHandle<VecScatter, VecScatterDestroy> gather_;  // block vector → rank 0, made at the first solve
  PVec gathered_;
};

}  // namespace rc::modes
