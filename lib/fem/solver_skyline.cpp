// Envelope (skyline) Cholesky factorisation A = L L^T in row-oriented envelope storage: row i holds columns
// f_i..i; L_ij = (a_ij - sum_{k=max(f_i,f_j)}^{j-1} L_ik L_jk) / L_jj. Fill stays inside the envelope, so its
// cost is what a bandwidth/profile reducing ordering (RCM) buys. George & Liu 1981, ch. 4 (envelope methods).
#include "fem/linear_solver.hpp"

#include <algorithm>
#include <cmath>

namespace suite::fem {
namespace {

class SkylineSolver final : public LinearSolver {
public:
  static constexpr long long kMaxEnvelope = 400000000LL; // 3.2 GB of doubles

  const char* name() const override { return "skyline"; }

  PetscErrorCode analyze(MPI_Comm comm, const SymCsc& A, const std::vector<int>& perm) override {
    PetscFunctionBeginUser;
    PetscCheck(isPermutation(perm, A.n), comm, PETSC_ERR_ARG_WRONG,
               "skyline: ordering is not a permutation of %d", A.n);
    n_ = A.n;
    perm_ = perm;
    const auto inv = inversePermutation(perm);
    first_.assign(n_, 0);
    for (int i = 0; i < n_; ++i) first_[i] = i;
    for (int c = 0; c < n_; ++c)
      for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k) {
        const int a = inv[A.rowind[k]], b = inv[c];
        const int row = std::max(a, b), col = std::min(a, b);
        first_[row] = std::min(first_[row], col);
      }
    start_.assign(n_ + 1, 0);
    for (int i = 0; i < n_; ++i) start_[i + 1] = start_[i] + (i - first_[i] + 1);
    PetscCheck(start_[n_] <= kMaxEnvelope, comm, PETSC_ERR_MEM,
               "skyline: the envelope of this ordering has %lld entries (limit %lld); use -ordering rcm or "
               "-solver cholmod",
               start_[n_], kMaxEnvelope);
    scatter_.resize(A.nnzUpper());
    for (int c = 0; c < n_; ++c)
      for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k) {
        const int a = inv[A.rowind[k]], b = inv[c];
        const int row = std::max(a, b), col = std::min(a, b);
        scatter_[k] = start_[row] + (col - first_[row]);
      }
    L_.assign(start_[n_], 0.0);
    work_.resize(n_);
    stats_.nnz_L = start_[n_];
    stats_.flops = 0;
    for (int i = 0; i < n_; ++i) {
      const double r = i - first_[i];
      stats_.flops += r * (r + 1); // dot products of average length ~ r/2, 2 flops each
    }
    PetscFunctionReturn(0);
  }

  PetscErrorCode factor(const SymCsc& A, bool* ok) override {
    PetscFunctionBeginUser;
    std::fill(L_.begin(), L_.end(), 0.0);
    for (size_t k = 0; k < scatter_.size(); ++k) L_[scatter_[k]] += A.val[k];
    *ok = true;
    for (int i = 0; i < n_; ++i) {
      const int fi = first_[i];
      double* Li = L_.data() + start_[i] - fi; // Li[j] = L(i, j) for j in [fi, i]
      for (int j = fi; j < i; ++j) {
        const int fj = first_[j];
        const double* Lj = L_.data() + start_[j] - fj;
        const int k0 = std::max(fi, fj);
        double s = Li[j];
        for (int k = k0; k < j; ++k) s -= Li[k] * Lj[k];
        Li[j] = s / Lj[j];
      }
      double d = Li[i];
      for (int k = fi; k < i; ++k) d -= Li[k] * Li[k];
      if (!(d > 0)) {
        *ok = false;
        PetscFunctionReturn(0);
      }
      Li[i] = std::sqrt(d);
    }
    PetscFunctionReturn(0);
  }

  PetscErrorCode solve(const double* b, double* x) override {
    PetscFunctionBeginUser;
    for (int i = 0; i < n_; ++i) work_[i] = b[perm_[i]];
    for (int i = 0; i < n_; ++i) { // L y = b
      const int fi = first_[i];
      const double* Li = L_.data() + start_[i] - fi;
      double s = work_[i];
      for (int k = fi; k < i; ++k) s -= Li[k] * work_[k];
      work_[i] = s / Li[i];
    }
    for (int i = n_ - 1; i >= 0; --i) { // L^T x = y, column sweep
      const int fi = first_[i];
      const double* Li = L_.data() + start_[i] - fi;
      work_[i] /= Li[i];
      const double xi = work_[i];
      for (int k = fi; k < i; ++k) work_[k] -= Li[k] * xi;
    }
    for (int i = 0; i < n_; ++i) x[perm_[i]] = work_[i];
    PetscFunctionReturn(0);
  }

  FactorStats stats() const override { return stats_; }

private:
  int n_ = 0;
  std::vector<int> perm_, first_;
  std::vector<long long> start_, scatter_;
  std::vector<double> L_, work_;
  FactorStats stats_;
};

} // namespace

std::unique_ptr<LinearSolver> makeSkylineSolver() {
  return std::make_unique<SkylineSolver>();
}

} // namespace suite::fem
