// Banded Cholesky through LAPACK dpbtrf/dpbtrs (blocked, BLAS-3 inside the band; Anderson et al., LAPACK
// Users' Guide 1999, sec. 2.4.2): the whole band of half-width kd = bandwidth of P A P^T is stored and
// factored, so its cost n kd^2 is exactly what a bandwidth reducing ordering (RCM) buys.
#include "fem/linear_solver.hpp"

#include <algorithm>
#include <cmath>

extern "C" {
void dpbtrf_(const char* uplo, const int* n, const int* kd, double* ab, const int* ldab, int* info);
void dpbtrs_(const char* uplo, const int* n, const int* kd, const int* nrhs, const double* ab,
             const int* ldab, double* b, const int* ldb, int* info);
}

namespace suite::fem {
namespace {

class BandedSolver final : public LinearSolver {
public:
  static constexpr long long kMaxBand = 400000000LL; // entries of the band storage (3.2 GB)
  const char* name() const override { return "banded"; }

  PetscErrorCode analyze(MPI_Comm comm, const SymCsc& A, const std::vector<int>& perm) override {
    PetscFunctionBeginUser;
    PetscCheck(isPermutation(perm, A.n), comm, PETSC_ERR_ARG_WRONG,
               "banded: ordering is not a permutation of %d", A.n);
    n_ = A.n;
    perm_ = perm;
    const auto inv = inversePermutation(perm);
    kd_ = 0;
    for (int c = 0; c < n_; ++c)
      for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k)
        kd_ = std::max(kd_, std::abs(inv[A.rowind[k]] - inv[c]));
    ldab_ = kd_ + 1;
    PetscCheck((long long)ldab_ * n_ <= kMaxBand, comm, PETSC_ERR_MEM,
               "banded: band of half-width %d for n = %d is too large; use -ordering rcm or -solver cholmod",
               kd_, n_);
    scatter_.resize(A.nnzUpper());
    for (int c = 0; c < n_; ++c)
      for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k) {
        const int a = inv[A.rowind[k]], b = inv[c];
        const int row = std::max(a, b), col = std::min(a, b);
        scatter_[k] = (long long)col * ldab_ + (row - col);
      }
    ab_.assign((size_t)ldab_ * n_, 0.0);
    work_.resize(n_);
    stats_.nnz_L = (long long)n_ * (kd_ + 1) - (long long)kd_ * (kd_ + 1) / 2;
    stats_.flops = (double)n_ * kd_ * (kd_ + 3);
    PetscFunctionReturn(0);
  }

  PetscErrorCode factor(const SymCsc& A, bool* ok) override {
    PetscFunctionBeginUser;
    std::fill(ab_.begin(), ab_.end(), 0.0);
    for (size_t k = 0; k < scatter_.size(); ++k) ab_[scatter_[k]] += A.val[k];
    if (kd_ <= kNarrowBand) {
      *ok = narrowBandCholesky();
      PetscFunctionReturn(0);
    }
    int info = 0;
    dpbtrf_("L", &n_, &kd_, ab_.data(), &ldab_, &info);
    PetscCheck(info >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "dpbtrf: illegal argument %d", -info);
    *ok = info == 0;
    PetscFunctionReturn(0);
  }

  PetscErrorCode solve(const double* b, double* x) override {
    PetscFunctionBeginUser;
    for (int i = 0; i < n_; ++i) work_[i] = b[perm_[i]];
    int info = 0, one = 1;
    dpbtrs_("L", &n_, &kd_, &one, ab_.data(), &ldab_, work_.data(), &n_, &info);
    PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "dpbtrs: info %d", info);
    for (int i = 0; i < n_; ++i) x[perm_[i]] = work_[i];
    PetscFunctionReturn(0);
  }

  FactorStats stats() const override { return stats_; }

private:
  // Below this half-width the blocked dpbtrf (block size 32) spends its time in small BLAS calls; the
  // unblocked right-looking band Cholesky with contiguous column updates (the dpbtf2 algorithm with the dsyr
  // written out as axpys, Golub & Van Loan 2013, alg. 4.3.5) is faster (5k-DOF beam, kd = 53: 5.1 -> 3.9 ms).
  static constexpr int kNarrowBand = 96;
  bool narrowBandCholesky() {
    double* ab = ab_.data();
    const int ld = ldab_;
    for (int j = 0; j < n_; ++j) {
      double* cj = ab + (size_t)j * ld; // cj[m] = A(j + m, j), m = 0..kd
      const double d = cj[0];
      if (!(d > 0)) return false;
      const double r = std::sqrt(d);
      cj[0] = r;
      const int len = std::min(kd_, n_ - 1 - j);
      const double inv = 1.0 / r;
      for (int m = 1; m <= len; ++m) cj[m] *= inv;
      for (int k = 1; k <= len; ++k) { // column j + k: A(j+k+m, j+k) -= l(j+k, j) l(j+k+m, j)
        double* ck = ab + (size_t)(j + k) * ld;
        const double lk = cj[k];
        const double* lj = cj + k;
        const int cnt = len - k + 1;
        for (int m = 0; m < cnt; ++m) ck[m] -= lk * lj[m];
      }
    }
    return true;
  }

  int n_ = 0, kd_ = 0, ldab_ = 1;
  std::vector<int> perm_;
  std::vector<long long> scatter_;
  std::vector<double> ab_, work_;
  FactorStats stats_;
};

} // namespace

std::unique_ptr<LinearSolver> makeBandedSolver() {
  return std::make_unique<BandedSolver>();
}

} // namespace suite::fem
