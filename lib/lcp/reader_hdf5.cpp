// Reader / writer of the suite's HDF5 LCP problem format (layout documented in readers.hpp).
#include "io/h5_input.hpp"
#include "io/h5_output.hpp"
#include "lcp/readers.hpp"

#include <cmath>

namespace suite::lcp {

PetscErrorCode readProblemH5(MPI_Comm comm, const std::string& path, Problem* p) {
  PetscFunctionBeginUser;
  H5Input in;
  PetscCall(in.open(comm, path));
  std::vector<double> q, data;
  Dims dq, dm;
  PetscCall(in.readAll("/q", &q, &dq));
  PetscCheck(dq.size() == 1 && !q.empty(), comm, PETSC_ERR_FILE_UNEXPECTED,
             "%s: /q must be a non-empty vector", path.c_str());
  const long long n = static_cast<long long>(q.size());
  Mat M = Mat::Zero(n, n);
  bool dense = false, csr = false;
  PetscCall(in.hasObject("/M", &dense));
  PetscCall(in.hasObject("/M_csr", &csr));
  PetscCheck(dense || csr, comm, PETSC_ERR_FILE_UNEXPECTED, "%s: neither /M (dense) nor /M_csr (CSR) present",
             path.c_str());
  if (dense) {
    PetscCall(in.readAll("/M", &data, &dm));
    PetscCheck(dm.size() == 2 && dm[0] == dm[1], comm, PETSC_ERR_FILE_UNEXPECTED, "%s: M is not square (%s)",
               path.c_str(),
               dm.size() == 2 ? (std::to_string(dm[0]) + " x " + std::to_string(dm[1])).c_str() : "not 2-D");
    PetscCheck((long long)dm[0] == n, comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s: M is %llu x %llu but q has %lld entries", path.c_str(), dm[0], dm[1], n);
    for (long long i = 0; i < n; ++i)
      for (long long j = 0; j < n; ++j) M(i, j) = data[i * n + j];
  } else {
    std::vector<long long> indptr, indices;
    Dims d1, d2, d3;
    PetscCall(in.readAll("/M_csr/indptr", &indptr, &d1));
    PetscCall(in.readAll("/M_csr/indices", &indices, &d2));
    PetscCall(in.readAll("/M_csr/data", &data, &d3));
    PetscCheck((long long)indptr.size() == n + 1 && indices.size() == data.size() && indptr[0] == 0 &&
                   indptr[n] == (long long)data.size(),
               comm, PETSC_ERR_FILE_UNEXPECTED, "%s: inconsistent CSR arrays /M_csr (n = %lld)", path.c_str(),
               n);
    for (long long i = 0; i < n; ++i) {
      PetscCheck(indptr[i] <= indptr[i + 1], comm, PETSC_ERR_FILE_UNEXPECTED,
                 "%s: /M_csr/indptr decreases at %lld", path.c_str(), i);
      for (long long k = indptr[i]; k < indptr[i + 1]; ++k) {
        PetscCheck(indices[k] >= 0 && indices[k] < n, comm, PETSC_ERR_FILE_UNEXPECTED,
                   "%s: /M_csr column index %lld out of range", path.c_str(), indices[k]);
        M(i, indices[k]) += data[k];
      }
    }
  }
  Vec qv = Eigen::Map<Vec>(q.data(), n);
  *p = makeLcp(std::move(M), std::move(qv), path);
  bool has_l = false, has_u = false, has_z = false, has_neq = false;
  PetscCall(in.hasObject("/l", &has_l));
  PetscCall(in.hasObject("/u", &has_u));
  PetscCall(in.hasObject("/z_known", &has_z));
  auto readVec = [&](const char* ds, Vec* v) -> PetscErrorCode {
    std::vector<double> d;
    Dims dd;
    PetscFunctionBeginUser;
    PetscCall(in.readAll(ds, &d, &dd));
    PetscCheck((long long)d.size() == n, comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s: %s has %zu entries, expected %lld", path.c_str(), ds, d.size(), n);
    *v = Eigen::Map<Vec>(d.data(), n);
    PetscFunctionReturn(0);
  };
  if (has_l) PetscCall(readVec("/l", &p->l));
  if (has_u) PetscCall(readVec("/u", &p->u));
  if (has_z) PetscCall(readVec("/z_known", &p->z_known));
  if (has_l || has_u) p->kind = Kind::Box;
  PetscCall(in.hasAttribute("/", "n_eq", &has_neq));
  if (has_neq) {
    long long neq = 0;
    PetscCall(in.readAttribute("/", "n_eq", &neq));
    PetscCheck(neq >= 0 && neq <= n, comm, PETSC_ERR_FILE_UNEXPECTED, "%s: n_eq = %lld outside [0, %lld]",
               path.c_str(), neq, n);
    p->n_eq = static_cast<int>(neq);
    if (!has_l && !has_u) // bounds given explicitly take precedence
      for (int i = 0; i < p->n_eq; ++i) p->l[i] = -kInf;
    if (neq > 0) p->kind = Kind::MLCP;
  }
  PetscCall(in.close());
  PetscFunctionReturn(0);
}

PetscErrorCode writeProblemH5(MPI_Comm comm, const std::string& path, const Problem& p) {
  PetscFunctionBeginUser;
  H5Output out;
  const unsigned long long n = p.size();
  PetscCall(out.open(comm, path));
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Mr = p.M;
  PetscCall(out.writeReplicated("/M", Mr.data(), {n, n}, ""));
  PetscCall(out.writeReplicated("/q", p.q.data(), {n}, ""));
  if (!p.isStandard() || p.kind != Kind::LCP) {
    PetscCall(out.writeReplicated("/l", p.l.data(), {n}, ""));
    PetscCall(out.writeReplicated("/u", p.u.data(), {n}, ""));
  }
  if (p.z_known.size() == (long)n) PetscCall(out.writeReplicated("/z_known", p.z_known.data(), {n}, ""));
  PetscCall(out.writeAttribute("/", "kind", kindName(p.kind)));
  PetscCall(out.writeAttribute("/", "n_eq", static_cast<long long>(p.n_eq)));
  PetscCall(out.commit(nullptr));
  PetscFunctionReturn(0);
}

} // namespace suite::lcp
