// Exact parallel solve of many tridiagonal lines by substructuring (see substructured_lines.hpp).
#include "linalg/substructured_lines.hpp"

#include "linalg/lapack.hpp"

#include <algorithm>
#include <cmath>

namespace suite::linalg {
namespace {

constexpr int kEnds = 6;       // y, v, w at the first and at the last local row of a line
constexpr int kDenseLimit = 8; // reduced systems up to this size: dense LU (covers every wrap-around case)

// Reduced-system coefficients of rank r for one line: first row (y0, v0, w0), last row (yL, vL, wL).
struct Ends {
  double y0, v0, w0, yL, vL, wL;
};

inline Ends endsOf(const double* all, int r, int line, int nlines) {
  const double* e = all + ((size_t)r * (nlines * kEnds + 1)) + (size_t)line * kEnds;
  return {e[0], e[1], e[2], e[3], e[4], e[5]};
}

} // namespace

PetscErrorCode SubstructuredLines::localSolves(MPI_Comm comm, int nlines, int m, const double* a,
                                               const double* b, const double* c, double* d, bool first_rank,
                                               bool last_rank, bool periodic) {
  PetscFunctionBeginUser;
  dl_.resize(std::max(m - 1, 1));
  du_.resize(std::max(m - 1, 1));
  dm_.resize(m);
  rhs_.resize(3 * (size_t)m);
  v_.resize((size_t)nlines * m);
  w_.resize((size_t)nlines * m);
  ends_.assign((size_t)nlines * kEnds + 1, 0.0);
  int singular = 0;
  for (int l = 0; l < nlines; ++l) {
    const size_t o = (size_t)l * m;
    std::copy(a + o + 1, a + o + m, dl_.begin());
    std::copy(b + o, b + o + m, dm_.begin());
    std::copy(c + o, c + o + m - 1, du_.begin());
    std::fill(rhs_.begin(), rhs_.end(), 0.0);
    std::copy(d + o, d + o + m, rhs_.begin());
    rhs_[m] = (first_rank && !periodic) ? 0.0 : -a[o];
    rhs_[2 * (size_t)m + m - 1] = (last_rank && !periodic) ? 0.0 : -c[o + m - 1];
    int n = m, nrhs = 3, info = 0;
    dgtsv_(&n, &nrhs, dl_.data(), dm_.data(), du_.data(), rhs_.data(), &n, &info);
    if (info != 0) singular = 1;
    std::copy(rhs_.begin(), rhs_.begin() + m, d + o);
    std::copy(rhs_.begin() + m, rhs_.begin() + 2 * m, v_.begin() + o);
    std::copy(rhs_.begin() + 2 * m, rhs_.begin() + 3 * m, w_.begin() + o);
    double* e = &ends_[(size_t)l * kEnds];
    e[0] = d[o], e[1] = v_[o], e[2] = w_[o];
    e[3] = d[o + m - 1], e[4] = v_[o + m - 1], e[5] = w_[o + m - 1];
  }
  ends_.back() = singular;
  (void)comm;
  PetscFunctionReturn(0);
}

// Reduced system of one line: unknowns u_{2r} = x(first row of rank r), u_{2r+1} = x(last row of rank r);
//   u_{2r}   - v0_r u_{2r-1} - w0_r u_{2r+2} = y0_r,    u_{2r+1} - vL_r u_{2r-1} - wL_r u_{2r+2} = yL_r,
// indices taken modulo 2P when periodic and terms dropped at the ends otherwise.
int SubstructuredLines::reducedSolve(int P, const double* all, int line, int nlines, bool periodic,
                                     double* u) {
  const int N = 2 * P;
  auto coupling = [&](int r, int k, double* left, double* right, double* rhs) {
    Ends e = endsOf(all, r, line, nlines);
    *rhs = k == 0 ? e.y0 : e.yL;
    *left = -(k == 0 ? e.v0 : e.vL);
    *right = -(k == 0 ? e.w0 : e.wL);
  };
  int info = 0, one = 1;
  ipiv_.resize(N);
  if (N <= kDenseLimit) {
    red_.assign((size_t)N * N, 0.0); // column-major
    for (int r = 0; r < P; ++r)
      for (int k = 0; k < 2; ++k) {
        const int row = 2 * r + k;
        double left, right;
        coupling(r, k, &left, &right, &u[row]);
        red_[row + (size_t)row * N] += 1.0;
        if (r > 0 || periodic) red_[row + (size_t)((2 * r - 1 + N) % N) * N] += left;
        if (r < P - 1 || periodic) red_[row + (size_t)((2 * r + 2) % N) * N] += right;
      }
    dgesv_(&N, &one, red_.data(), &N, ipiv_.data(), u, &N, &info);
    return info;
  }
  // Banded part (kl = ku = 2) plus, when periodic, the corner entries as a rank-2 Woodbury correction.
  const int kl = 2, ku = 2, ldab = 2 * kl + ku + 1;
  ab_.assign((size_t)ldab * N, 0.0);
  auto put = [&](int i, int j, double val) { ab_[(size_t)(kl + ku + i - j) + (size_t)j * ldab] += val; };
  red_.assign(3 * (size_t)N, 0.0); // right-hand sides: [u, U1, U2]
  for (int r = 0; r < P; ++r)
    for (int k = 0; k < 2; ++k) {
      const int row = 2 * r + k;
      double left, right;
      coupling(r, k, &left, &right, &red_[row]);
      put(row, row, 1.0);
      if (r > 0)
        put(row, 2 * r - 1, left);
      else if (periodic)
        red_[N + row] = left; // column N-1 entries of rows 0, 1
      if (r < P - 1)
        put(row, 2 * r + 2, right);
      else if (periodic)
        red_[2 * (size_t)N + row] = right; // column 0 entries of rows N-2, N-1
    }
  const int nrhs = periodic ? 3 : 1;
  dgbsv_(&N, &kl, &ku, &nrhs, ab_.data(), &ldab, ipiv_.data(), red_.data(), &N, &info);
  const double* z = red_.data();
  if (periodic) {
    const double* Z1 = z + N;
    const double* Z2 = z + 2 * (size_t)N;
    // (I + V^T Z) s = V^T z with V = [e_{N-1}, e_0]
    const double s11 = 1.0 + Z1[N - 1], s12 = Z2[N - 1], s21 = Z1[0], s22 = 1.0 + Z2[0];
    const double t1 = z[N - 1], t2 = z[0], det = s11 * s22 - s12 * s21;
    const double x1 = (t1 * s22 - s12 * t2) / det, x2 = (s11 * t2 - s21 * t1) / det;
    for (int i = 0; i < N; ++i) u[i] = z[i] - Z1[i] * x1 - Z2[i] * x2;
    if (!std::isfinite(det) || det == 0.0) info = N + 1;
  } else {
    std::copy(z, z + N, u);
  }
  return info;
}

PetscErrorCode SubstructuredLines::solve(MPI_Comm comm, int nlines, int nloc, const double* a,
                                         const double* b, const double* c, double* d, bool periodic) {
  PetscFunctionBeginUser;
  int P = 1, rank = 0;
  PetscCallMPI(MPI_Comm_size(comm, &P));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCheck(nloc >= 1, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "substructured line solve: %d local rows",
             nloc);
  PetscCall(localSolves(comm, nlines, nloc, a, b, c, d, rank == 0, rank == P - 1, periodic));
  const int per_rank = nlines * kEnds + 1;
  all_ends_.resize((size_t)P * per_rank);
  PetscCallMPI(
      MPI_Allgather(ends_.data(), per_rank, MPI_DOUBLE, all_ends_.data(), per_rank, MPI_DOUBLE, comm));
  bool singular = false;
  for (int r = 0; r < P; ++r) singular = singular || all_ends_[(size_t)r * per_rank + per_rank - 1] != 0.0;
  PetscCheck(!singular, comm, PETSC_ERR_MAT_LU_ZRPVT,
             "substructured line solve: a rank's block of a tridiagonal line is exactly singular");
  if (P == 1 && !periodic) PetscFunctionReturn(0);
  std::vector<double> u(2 * (size_t)P);
  int bad = 0; // the reduced systems are identical on every rank, so this flag is too
  for (int l = 0; l < nlines && !bad; ++l) {
    bad = reducedSolve(P, all_ends_.data(), l, nlines, periodic, u.data());
    const int N = 2 * P;
    const double left = (rank > 0 || periodic) ? u[(2 * rank - 1 + N) % N] : 0.0;
    const double right = (rank < P - 1 || periodic) ? u[(2 * rank + 2) % N] : 0.0;
    const size_t o = (size_t)l * nloc;
    for (int i = 0; i < nloc; ++i) d[o + i] += left * v_[o + i] + right * w_[o + i];
  }
  PetscCheck(!bad, comm, PETSC_ERR_MAT_LU_ZRPVT,
             "substructured line solve: a tridiagonal line system is singular");
  PetscFunctionReturn(0);
}

} // namespace suite::linalg
