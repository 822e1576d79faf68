// Exact distributed line solve by gathering the rows to every rank (see tridiag_distributed.hpp).
#include "linalg/tridiag_distributed.hpp"

#include <stdexcept>

namespace suite::linalg {

void DistributedTridiag::gather(MPI_Comm comm, int per_row, int nloc, const double* local,
                                std::vector<double>* global) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (size == 1) {
    global->assign(local, local + static_cast<std::size_t>(nloc) * per_row);
    return;
  }
  counts_.assign(size, 0);
  displs_.assign(size, 0);
  int mine = nloc * per_row;
  MPI_Allgather(&mine, 1, MPI_INT, counts_.data(), 1, MPI_INT, comm);
  long long total = 0;
  for (int r = 0; r < size; ++r) {
    displs_[r] = static_cast<int>(total);
    total += counts_[r];
  }
  if (total > 2147483647LL) throw std::runtime_error("DistributedTridiag: line too long for MPI_Allgatherv");
  global->resize(static_cast<std::size_t>(total));
  MPI_Allgatherv(local, mine, MPI_DOUBLE, global->data(), counts_.data(), displs_.data(), MPI_DOUBLE, comm);
}

void DistributedTridiag::solve(MPI_Comm comm, int bs, int nloc, const double* A, const double* B,
                               const double* C, const double* d, bool periodic, long long first, int count,
                               double* x) {
  const int bb = bs * bs, per_row = 3 * bb + bs;
  send_.resize(static_cast<std::size_t>(nloc) * per_row);
  for (int i = 0; i < nloc; ++i) {
    double* s = &send_[static_cast<std::size_t>(i) * per_row];
    for (int k = 0; k < bb; ++k) {
      s[k] = A[i * bb + k];
      s[bb + k] = B[i * bb + k];
      s[2 * bb + k] = C[i * bb + k];
    }
    for (int k = 0; k < bs; ++k) s[3 * bb + k] = d[i * bs + k];
  }
  gather(comm, per_row, nloc, send_.data(), &all_);
  const int nb = static_cast<int>(all_.size() / per_row);
  A_.resize(static_cast<std::size_t>(nb) * bb);
  B_.resize(A_.size());
  C_.resize(A_.size());
  d_.resize(static_cast<std::size_t>(nb) * bs);
  for (int i = 0; i < nb; ++i) {
    const double* s = &all_[static_cast<std::size_t>(i) * per_row];
    for (int k = 0; k < bb; ++k) {
      A_[i * bb + k] = s[k];
      B_[i * bb + k] = s[bb + k];
      C_[i * bb + k] = s[2 * bb + k];
    }
    for (int k = 0; k < bs; ++k) d_[i * bs + k] = s[3 * bb + k];
  }
  solver_.solve(nb, bs, A_.data(), B_.data(), C_.data(), d_.data(), periodic);
  for (int i = 0; i < count; ++i) {
    long long g = first + i;
    if (periodic) g = ((g % nb) + nb) % nb;
    if (g < 0 || g >= nb) throw std::out_of_range("DistributedTridiag: requested row outside the line");
    for (int k = 0; k < bs; ++k) x[i * bs + k] = d_[g * bs + k];
  }
}

void DistributedTridiag::solveScalar(MPI_Comm comm, int nloc, const double* abc, int ncomp, const double* d,
                                     bool periodic, long long first, int count, double* x) {
  const int per_row = 3 + ncomp;
  send_.resize(static_cast<std::size_t>(nloc) * per_row);
  for (int i = 0; i < nloc; ++i) {
    double* s = &send_[static_cast<std::size_t>(i) * per_row];
    for (int k = 0; k < 3; ++k) s[k] = abc[3 * i + k];
    for (int k = 0; k < ncomp; ++k) s[3 + k] = d[static_cast<std::size_t>(i) * ncomp + k];
  }
  gather(comm, per_row, nloc, send_.data(), &all_);
  const int nb = static_cast<int>(all_.size() / per_row);
  A_.resize(nb);
  B_.resize(nb);
  C_.resize(nb);
  d_.resize(nb);
  std::vector<double> sol(static_cast<std::size_t>(nb) * ncomp);
  for (int i = 0; i < nb; ++i) {
    A_[i] = all_[static_cast<std::size_t>(i) * per_row];
    B_[i] = all_[static_cast<std::size_t>(i) * per_row + 1];
    C_[i] = all_[static_cast<std::size_t>(i) * per_row + 2];
  }
  for (int k = 0; k < ncomp; ++k) {
    for (int i = 0; i < nb; ++i) d_[i] = all_[static_cast<std::size_t>(i) * per_row + 3 + k];
    std::vector<double> rhs(d_);
    bool ok = periodic ? cyclicThomas(nb, A_.data(), B_.data(), C_.data(), d_.data())
                       : thomas(nb, A_.data(), B_.data(), C_.data(), d_.data());
    if (ok)
      ok = blockTridiagResidual(nb, 1, A_.data(), B_.data(), C_.data(), d_.data(), rhs.data(), periodic) <=
           solver_.tolerance;
    if (!ok) {
      d_ = rhs;
      solver_.solve(nb, 1, A_.data(), B_.data(), C_.data(), d_.data(), periodic);
    }
    for (int i = 0; i < nb; ++i) sol[static_cast<std::size_t>(i) * ncomp + k] = d_[i];
  }
  for (int i = 0; i < count; ++i) {
    long long g = first + i;
    if (periodic) g = ((g % nb) + nb) % nb;
    if (g < 0 || g >= nb) throw std::out_of_range("DistributedTridiag: requested row outside the line");
    for (int k = 0; k < ncomp; ++k) x[i * ncomp + k] = sol[g * ncomp + k];
  }
}

} // namespace suite::linalg
