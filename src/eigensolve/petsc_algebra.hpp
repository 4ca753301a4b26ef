// Small PETSc vector algebra that several solvers and analyses need: norms,
// x^T A y, and the inertia count (negative eigenvalues of a symmetric matrix)
// that proves a solve complete. One definition each.
#pragma once

#include "common/petsc_handle.hpp"

#include <slepcst.h>

namespace coremodal {

double vector_norm(Vec x);
// ||A||_1.
double norm_1(Mat A);

// y^T A x (real; PETSc is built with real scalars here).
double bilinear_form(Mat A, Vec y, Vec x);
// x^T A x.
inline double quadratic_form(Mat A, Vec x) { return bilinear_form(A, x, x); }

// The number of negative eigenvalues of the symmetric matrix A (Sylvester's
// law of inertia: the negative pivots of its MUMPS LDL^T factor). `what`
// names A in the error raised when the factorisation fails.
long negative_eigenvalue_count(Mat A, const char* what);
// K - sigma M, on the one sparsity pattern K and M share (the assembly
// makes them so).
PetscMatrix shifted(Mat K, Mat M, double sigma);

// MUMPS keeps its factor on disk (ICNTL(22) = 1, out of core) when the
// in-core estimate of its analysis (INFOG(17): every process's data, MB)
// exceeds this share of the memory the run may take (the machine's
// MemAvailable, its control group's limit, a user's -max_memory_mb: the
// least of them; common/free_memory.hpp): the run then
// finishes, slower, where in core it would swap or be killed. Measured on
// case 03 at 540,288 unknowns, two processes: 6.9 GB and 204 s out of core
// against 14.6 GB and 182 s in core (bench/results/log.md). A user's
// -mat_mumps_icntl_22 decides instead. The estimate is compared with the
// first process's machine: on several machines a conservative choice. The
// share: on case 03 INFOG(17) is 2,116 MB of the run's 3.27 GB peak (K, M
// and the block basis beside the factor), about two thirds; with the
// estimate at 0.6 of the free memory the whole run stays near 0.9 of it.
inline constexpr double kInCoreShare = 0.6;
// Whether a factor MUMPS estimates at estimate_mb stays in memory when the
// run may take allowed_mb (0: unknown, it stays).
bool factor_fits_in_memory(double estimate_mb, double allowed_mb);
// Whether a MUMPS factor (double or single precision, eigensolve/
// single_factor.hpp) goes out of core: its analysis's in-core estimate
// INFOG(17) does not fit (above), or the user's -mat_mumps_icntl_22 says 1.
// SolveError when even its out-of-core estimate INFOG(27) exceeds the
// machine's memory.
bool factor_goes_out_of_core(MPI_Comm comm, double estimate_mb, double out_of_core_mb);

// The factor of the symmetric A by `package` (MATSOLVERCHOLMOD: Cholesky;
// MATSOLVERMUMPS: LDL^T with pivoting, which also counts): symbolic and
// numeric steps, the package's own ordering. The numeric step's error code
// is returned (a zero pivot, PETSC_ERR_MAT_CH_ZRPVT), not thrown. MUMPS's
// factor goes out of core when too large (kInCoreShare).
PetscErrorCode factor_symmetric(Mat A, const char* package, PetscMatrix& F);
// Whether the factor F lives on disk (MUMPS out of core: chosen above, or
// by the user's -mat_mumps_icntl_22 1).
bool factor_out_of_core(Mat F);
// Its two steps: MUMPS's LDL^T factor of the symmetric A (SolveError when
// it fails), which also solves, and that factor's negative pivots.
PetscMatrix ldlt_factor(Mat A, const char* what);
long negative_pivots(Mat F);

// A direct Cholesky solver (KSP "preonly") with the shift-and-invert's
// factor package (modal_solver.hpp), its options under `prefix` (e.g.
// "static_": -static_pc_factor_mat_solver_type mumps); the caller sets the
// operators. For the static solves of a solid's prestress.
using PetscKsp = PetscHandle<KSP, KSPDestroy>;
PetscKsp direct_cholesky_solver(MPI_Comm comm, const char* prefix);

// Shift-and-invert with a direct solve (KSP "preonly") on `st`; returns the
// preconditioner whose factor type and package the caller sets.
PC direct_shift_and_invert(ST st);

}  // namespace coremodal
