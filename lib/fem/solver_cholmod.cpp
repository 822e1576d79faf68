// CHOLMOD supernodal Cholesky (Chen, Davis, Hager & Rajamanickam, ACM TOMS 35 (2008) 22): the symbolic
// analysis with the given ordering (CHOLMOD_GIVEN, postordered) is done once per pattern; each factor() is a
// numeric refactorisation only. Debian's CHOLMOD runs a few of its loops (copies into the supernodes) in
// OpenMP regions with a fixed team of 4 threads, whatever OMP_NUM_THREADS says: on one core, or beside other
// work, those threads wait for each other and the factorisation's wall time doubles. The factorisation runs
// with OpenMP switched off (max-active-levels 0 for the call: every region has one thread) unless
// -cholmod_openmp is given.
#include "core/option_value.hpp"
#include "fem/linear_solver.hpp"

#include <cholmod.h>
#include <omp.h>

namespace suite::fem {
namespace {

class CholmodSolver final : public LinearSolver {
public:
  CholmodSolver() {
    cholmod_start(&cm_);
    cm_.print = 0;
    cm_.supernodal = CHOLMOD_SUPERNODAL;
    cm_.nmethods = 1;
    cm_.method[0].ordering = CHOLMOD_GIVEN;
    cm_.postorder = 1;
    cm_.quick_return_if_not_posdef = 1;
  }
  ~CholmodSolver() override {
    if (L_) cholmod_free_factor(&L_, &cm_);
    if (X_) cholmod_free_dense(&X_, &cm_);
    if (Y_) cholmod_free_dense(&Y_, &cm_);
    if (E_) cholmod_free_dense(&E_, &cm_);
    cholmod_finish(&cm_);
  }
  const char* name() const override { return "cholmod"; }

  PetscErrorCode setFromOptions(MPI_Comm comm) override {
    PetscBool on = openmp_ ? PETSC_TRUE : PETSC_FALSE;
    PetscFunctionBeginUser;
    PetscOptionsBegin(comm, nullptr, "CHOLMOD (-solver cholmod)", nullptr);
    PetscCall(suite::optionsBool(PetscOptionsObject, "-cholmod_openmp",
                                 "Let CHOLMOD run its OpenMP loops (a team of 4 threads in Debian's build)",
                                 "", on, &on, nullptr));
    PetscOptionsEnd();
    openmp_ = on == PETSC_TRUE;
    PetscFunctionReturn(0);
  }

  PetscErrorCode analyze(MPI_Comm comm, const SymCsc& A, const std::vector<int>& perm) override {
    PetscFunctionBeginUser;
    PetscCheck(isPermutation(perm, A.n), comm, PETSC_ERR_ARG_WRONG,
               "cholmod: ordering is not a permutation of %d", A.n);
    if (L_) cholmod_free_factor(&L_, &cm_);
    perm_ = perm;
    cholmod_sparse S = view(A);
    L_ = cholmod_analyze_p(&S, perm_.data(), nullptr, 0, &cm_);
    PetscCheck(L_ && cm_.status >= CHOLMOD_OK, comm, PETSC_ERR_LIB, "cholmod_analyze failed (status %d)",
               cm_.status);
    stats_.nnz_L = static_cast<long long>(cm_.lnz);
    stats_.flops = cm_.fl;
    n_ = A.n;
    PetscFunctionReturn(0);
  }

  PetscErrorCode factor(const SymCsc& A, bool* ok) override {
    PetscFunctionBeginUser;
    cholmod_sparse S = view(A);
    const int levels = omp_get_max_active_levels();
    if (!openmp_) omp_set_max_active_levels(0); // every OpenMP region of the call runs on this thread
    cholmod_factorize(&S, L_, &cm_);
    if (!openmp_) omp_set_max_active_levels(levels);
    *ok = cm_.status == CHOLMOD_OK && L_->minor == L_->n;
    PetscFunctionReturn(0);
  }

  PetscErrorCode solve(const double* b, double* x) override {
    PetscFunctionBeginUser;
    cholmod_dense B;
    B.nrow = n_;
    B.ncol = 1;
    B.nzmax = n_;
    B.d = n_;
    B.x = const_cast<double*>(b);
    B.z = nullptr;
    B.xtype = CHOLMOD_REAL;
    B.dtype = CHOLMOD_DOUBLE;
    PetscCheck(cholmod_solve2(CHOLMOD_A, L_, &B, nullptr, &X_, nullptr, &Y_, &E_, &cm_), PETSC_COMM_SELF,
               PETSC_ERR_LIB, "cholmod_solve2 failed (status %d)", cm_.status);
    const double* xs = static_cast<const double*>(X_->x);
    for (int i = 0; i < n_; ++i) x[i] = xs[i];
    PetscFunctionReturn(0);
  }

  FactorStats stats() const override { return stats_; }

private:
  cholmod_sparse view(const SymCsc& A) {
    cholmod_sparse S{};
    S.nrow = S.ncol = A.n;
    S.nzmax = A.nnzUpper();
    S.p = const_cast<int*>(A.colptr.data());
    S.i = const_cast<int*>(A.rowind.data());
    S.x = const_cast<double*>(A.val.data());
    S.stype = 1; // upper triangle
    S.itype = CHOLMOD_INT;
    S.xtype = CHOLMOD_REAL;
    S.dtype = CHOLMOD_DOUBLE;
    S.sorted = 1;
    S.packed = 1;
    return S;
  }

  cholmod_common cm_;
  cholmod_factor* L_ = nullptr;
  cholmod_dense *X_ = nullptr, *Y_ = nullptr, *E_ = nullptr;
  std::vector<int> perm_;
  int n_ = 0;
  bool openmp_ = false;
  FactorStats stats_;
};

} // namespace

std::unique_ptr<LinearSolver> makeCholmodSolver() {
  return std::make_unique<CholmodSolver>();
}

} // namespace suite::fem
