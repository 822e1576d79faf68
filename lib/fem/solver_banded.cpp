// Banded Cholesky on the band of half-width kd = bandwidth of P A P^T (what a bandwidth reducing ordering
// such as RCM buys: cost <= n kd^2). Storage: the lower band column by column with leading dimension
// ld = kd + nb + 1, A(i, j) at ab[j ld + i - j]; with the leading dimension ld - 1 the same array is a dense
// column-major matrix (the view LAPACK's dpbtrf uses, Anderson et al., LAPACK Users' Guide 1999, sec. 2.4.2),
// and the nb extra zero subdiagonals make every block below a diagonal block addressable in it.
// Factorisation: right-looking, blocked by nb columns (Golub & Van Loan 2013, alg. 4.3.5 by blocks): per block
// J = [j, j + nb): L_JJ = chol(A_JJ) (dpotrf), L_RJ = A_RJ L_JJ^-T as A_RJ * inv(L_JJ)^T (inverse + dtrmm: 3x
// faster than dtrsm in single-thread OpenBLAS at these sizes), A_RR -= L_RJ L_RJ^T (dsyrk). The rows R of the
// block end at the envelope (last row i with first nonzero f_i <= j + nb - 1), not at the band edge, so an
// ordering with a varying front (RCM) pays about its envelope flops, not n kd^2. Narrow bands (kd <= 96) use the
// unblocked column algorithm (small BLAS calls would dominate) and dpbtrs for the solve; the blocked factor is
// solved by the same blocks (dtrsv + dgemv on the envelope rows).
#include "fem/linear_solver.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

extern "C" {
void dpbtrs_(const char* uplo, const int* n, const int* kd, const int* nrhs, const double* ab,
             const int* ldab, double* b, const int* ldb, int* info);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dtrmm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m,
            const int* n, const double* alpha, const double* a, const int* lda, double* b, const int* ldb);
void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a,
            const int* lda, double* x, const int* incx);
void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a,
            const int* lda, const double* x, const int* incx, const double* beta, double* y, const int* incy);
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* beta, double* c, const int* ldc);
}

namespace suite::fem {
namespace {

class BandedSolver final : public LinearSolver {
public:
  static constexpr long long kMaxBand = 400000000LL; // entries of the band storage (3.2 GB; int offsets)
  const char* name() const override { return "banded"; }

  PetscErrorCode analyze(MPI_Comm comm, const SymCsc& A, const std::vector<int>& perm) override {
    PetscFunctionBeginUser;
    PetscCheck(isPermutation(perm, A.n), comm, PETSC_ERR_ARG_WRONG,
               "banded: ordering is not a permutation of %d", A.n);
    n_ = A.n;
    perm_ = perm;
    const auto inv = inversePermutation(perm);
    // first[i] = first nonzero column of row i of the lower triangle of P A P^T.
    std::vector<int> first(n_);
    for (int i = 0; i < n_; ++i) first[i] = i;
    kd_ = 0;
    for (int c = 0; c < n_; ++c)
      for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k) {
        const int a = inv[A.rowind[k]], b = inv[c];
        const int row = std::max(a, b), col = std::min(a, b);
        kd_ = std::max(kd_, row - col);
        first[row] = std::min(first[row], col);
      }
    nb_ = kd_ <= kNarrowBand ? 0 : kBlock;
    ld_ = kd_ + nb_ + 1;
    PetscCheck((long long)ld_ * n_ <= kMaxBand, comm, PETSC_ERR_MEM,
               "banded: band of half-width %d for n = %d is too large; use -ordering rcm or -solver cholmod",
               kd_, n_);
    // last_[c] = last row of the envelope below column c: max{i : first[i] <= c} (nondecreasing in c); the
    // factor's column c has no entry below it (fill stays inside the envelope).
    last_.assign(n_, 0);
    for (int i = 0; i < n_; ++i) last_[first[i]] = std::max(last_[first[i]], i);
    for (int c = 0; c < n_; ++c) last_[c] = std::max(last_[c], c > 0 ? last_[c - 1] : c);
    // Scatter of A's values into the band grouped by band column (col_start_), so that the blocked
    // factorisation can load each column just before its first update (cache-warm).
    scatter_.resize(A.nnzUpper());
    col_start_.assign(n_ + 1, 0);
    for (int c = 0; c < n_; ++c)
      for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k)
        ++col_start_[std::min(inv[A.rowind[k]], inv[c]) + 1];
    for (int c = 0; c < n_; ++c) col_start_[c + 1] += col_start_[c];
    std::vector<long long> fill(col_start_.begin(), col_start_.end() - 1);
    for (int c = 0; c < n_; ++c)
      for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k) {
        const int a = inv[A.rowind[k]], b = inv[c];
        const int row = std::max(a, b), col = std::min(a, b);
        scatter_[fill[col]++] = {k, col * ld_ + (row - col)};
      }
    ab_.assign((size_t)ld_ * n_, 0.0);
    work_.resize(n_);
    winv_.resize((size_t)kBlock * kBlock);
    // nnz_L: the whole stored band (zeros in it included); flops: those of the envelope-limited algorithm: column c updates the rows
    // c+1..last(c) (eta_c entries) of the later columns, sum eta_c (eta_c + 3) as in computeMetrics.
    stats_.nnz_L = (long long)n_ * (kd_ + 1) - (long long)kd_ * (kd_ + 1) / 2;
    double fl = 0;
    for (int c = 0; c < n_; ++c) {
      const double eta = nb_ ? blockLast(c) - c : std::min(kd_, n_ - 1 - c);
      fl += eta * (eta + 3);
    }
    stats_.flops = fl;
    PetscFunctionReturn(0);
  }

  PetscErrorCode factor(const SymCsc& A, bool* ok) override {
    PetscFunctionBeginUser;
    if (nb_ == 0) {
      loadColumns(A.val.data(), 0, n_);
      *ok = narrowBandCholesky();
    } else {
      *ok = blockedCholesky(A.val.data());
    }
    PetscFunctionReturn(0);
  }

  PetscErrorCode solve(const double* b, double* x) override {
    PetscFunctionBeginUser;
    for (int i = 0; i < n_; ++i) work_[i] = b[perm_[i]];
    if (nb_ > 0) {
      blockedSolve(work_.data());
    } else {
      int info = 0, one = 1;
      dpbtrs_("L", &n_, &kd_, &one, ab_.data(), &ld_, work_.data(), &n_, &info);
      PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "dpbtrs: info %d", info);
    }
    for (int i = 0; i < n_; ++i) x[perm_[i]] = work_[i];
    PetscFunctionReturn(0);
  }

  FactorStats stats() const override { return stats_; }

private:
  // Below this half-width the blocked algorithm spends its time in small BLAS calls; the unblocked
  // right-looking band Cholesky with contiguous column updates (the dpbtf2 algorithm with the dsyr written out
  // as axpys, Golub & Van Loan 2013, alg. 4.3.5) is faster (5k-DOF beam, kd = 53: 3.9 ms against 5.1 ms blocked).
  static constexpr int kNarrowBand = 96;
  // Block width: dsyrk with k = 24..32 is near its best rate for m ~ 250 while the wasted zeros stay small.
  static constexpr int kBlock = 32;

  // Last row that the blocked algorithm touches in column c: the envelope end of c's block.
  int blockLast(int c) const {
    const int j = c - c % kBlock;
    return std::min(n_ - 1, last_[std::min(n_ - 1, j + kBlock - 1)]);
  }

  bool narrowBandCholesky() {
    double* ab = ab_.data();
    const int ld = ld_;
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

  // Columns [c0, c1) of the band := A (zero, then add A's entries): only the rows the factorisation reads,
  // c..blockLast(c) (the rows below stay zero from analyze).
  void loadColumns(const double* val, int c0, int c1) {
    for (int c = c0; c < c1; ++c) {
      std::fill_n(ab_.data() + (size_t)c * ld_, (nb_ ? blockLast(c) : std::min(n_ - 1, c + kd_)) - c + 1,
                  0.0);
      for (long long k = col_start_[c]; k < col_start_[c + 1]; ++k)
        ab_[scatter_[k].second] += val[scatter_[k].first];
    }
  }

  // inv(L) of the jb x jb lower triangle at d (leading dimension lda) into winv_ (leading dimension jb),
  // column by column (forward substitution on the unit vectors); false on a zero diagonal.
  bool invertLower(const double* d, int lda, int jb) {
    double* w = winv_.data();
    for (int c = 0; c < jb; ++c) {
      double* wc = w + (size_t)c * jb;
      std::fill_n(wc, jb, 0.0);
      wc[c] = 1.0;
      for (int k = c; k < jb; ++k) { // solve L x = e_c: x_k = wc[k] / L_kk, then wc[r] -= L_rk x_k
        const double* lk = d + (size_t)k * lda;
        if (!(lk[k] != 0)) return false;
        const double xk = wc[k] / lk[k];
        wc[k] = xk;
        for (int r = k + 1; r < jb; ++r) wc[r] -= lk[r] * xk;
      }
    }
    return true;
  }

  bool blockedCholesky(const double* val) {
    const int lda = ld_ - 1;
    const double one = 1, minus_one = -1;
    int loaded = 0; // columns [0, loaded) hold A (plus updates)
    for (int j = 0; j < n_; j += nb_) {
      const int jb = std::min(nb_, n_ - j);
      const int last = blockLast(j);
      if (loaded <= last) loadColumns(val, loaded, last + 1), loaded = last + 1;
      double* d = ab_.data() + (size_t)j * ld_; // A(j, j) in the dense view
      int info = 0;
      dpotrf_("L", &jb, d, &lda, &info);
      if (info != 0) return false;
      const int m = last - (j + jb) + 1; // rows of the block below the diagonal block
      if (m <= 0) continue;
      if (!invertLower(d, lda, jb)) return false;
      double* p = d + jb; // A(j + jb, j)
      dtrmm_("R", "L", "T", "N", &m, &jb, &one, winv_.data(), &jb, p, &lda);
      dsyrk_("L", "N", &m, &jb, &minus_one, p, &lda, &one, ab_.data() + (size_t)(j + jb) * ld_, &lda);
    }
    return true;
  }

  // L L^T x = b by blocks of the factorisation: triangular solves with L_JJ, matrix-vector products with the
  // block below it (only its envelope rows), so the band outside the envelope is never read.
  void blockedSolve(double* x) const {
    const int lda = ld_ - 1, inc = 1;
    const double one = 1, minus_one = -1;
    for (int j = 0; j < n_; j += nb_) {
      const int jb = std::min(nb_, n_ - j), m = blockLast(j) - (j + jb) + 1;
      const double* d = ab_.data() + (size_t)j * ld_;
      dtrsv_("L", "N", "N", &jb, d, &lda, x + j, &inc);
      if (m > 0) dgemv_("N", &m, &jb, &minus_one, d + jb, &lda, x + j, &inc, &one, x + j + jb, &inc);
    }
    for (int j = (n_ - 1) / nb_ * nb_; j >= 0; j -= nb_) {
      const int jb = std::min(nb_, n_ - j), m = blockLast(j) - (j + jb) + 1;
      const double* d = ab_.data() + (size_t)j * ld_;
      if (m > 0) dgemv_("T", &m, &jb, &minus_one, d + jb, &lda, x + j + jb, &inc, &one, x + j, &inc);
      dtrsv_("L", "T", "N", &jb, d, &lda, x + j, &inc);
    }
  }

  int n_ = 0, kd_ = 0, nb_ = 0, ld_ = 1;
  std::vector<int> perm_, last_;
  std::vector<long long> col_start_;
  std::vector<std::pair<int, int>> scatter_; // (index into A's values, band offset < kMaxBand)
  std::vector<double> ab_, work_, winv_;
  FactorStats stats_;
};

} // namespace

std::unique_ptr<LinearSolver> makeBandedSolver() {
  return std::make_unique<BandedSolver>();
}

} // namespace suite::fem
