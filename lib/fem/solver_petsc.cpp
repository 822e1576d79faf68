// The distributed PETSc path (-solver petsc): the mesh nodes are partitioned with METIS (METIS_PartGraphKway,
// Karypis & Kumar, SIAM J. Sci. Comput. 20 (1998) 359) into one part per rank; the free DOFs are renumbered
// part by part (within a part in the order of -ordering) so that each rank owns the contiguous block of rows
// of its nodes in an MPIAIJ matrix; the linear systems are solved with KSP: by default MUMPS Cholesky
// (KSPPREONLY + PCCHOLESKY, Amestoy et al., SIAM J. Matrix Anal. Appl. 23 (2001) 15) when PETSc has MUMPS,
// else CG + GAMG; -ksp_type, -pc_type, -ksp_rtol, ... override (KSPSetFromOptions, no prefix).
// At several ranks the element assembly is distributed too: each rank assembles the elements whose first corner
// node it owns (ElasticModel::setOwnedElements) and passes partial sums, which factor() adds into the MPIAIJ
// matrix (ADD_VALUES; MatAssembly moves the entries of other ranks' rows); the time integrator sums the
// residual over the ranks. The solution is gathered to every rank (VecScatterCreateToAll): the time-stepping
// state (u, v, a) stays replicated.
#include "fem/linear_solver.hpp"

#include <metis.h>
#include <petscksp.h>

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace suite::fem {
namespace {

class PetscSolver final : public LinearSolver {
public:
  ~PetscSolver() override {
    KSPDestroy(&ksp_);
    MatDestroy(&A_);
    VecDestroy(&b_);
    VecDestroy(&x_);
    VecDestroy(&xall_);
    VecScatterDestroy(&toall_);
  }
  const char* name() const override { return "petsc"; }

  PetscErrorCode setFromOptions(MPI_Comm comm) override {
    PetscFunctionBeginUser;
    comm_ = comm;
    PetscCall(KSPCreate(comm, &ksp_));
    PC pc;
    PetscCall(KSPGetPC(ksp_, &pc));
    PetscBool mumps = PETSC_FALSE;
    PetscCall(PetscHasExternalPackage("mumps", &mumps));
    if (mumps) {
      PetscCall(KSPSetType(ksp_, KSPPREONLY));
      PetscCall(PCSetType(pc, PCCHOLESKY));
      PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    } else {
      PetscCall(KSPSetType(ksp_, KSPCG));
      PetscCall(PCSetType(pc, PCGAMG));
    }
    PetscCall(KSPSetFromOptions(ksp_));
    PetscFunctionReturn(0);
  }

  void setNodeGraph(const Graph& nodes, const std::vector<int>& eq) override {
    nodes_ = nodes;
    eq_ = eq;
  }

  PetscErrorCode analyze(MPI_Comm comm, const SymCsc& A, const std::vector<int>& perm) override {
    PetscFunctionBeginUser;
    PetscCheck(ksp_, comm, PETSC_ERR_ORDER, "petsc solver: setFromOptions() must precede analyze()");
    PetscCheck(isPermutation(perm, A.n), comm, PETSC_ERR_ARG_WRONG,
               "petsc: ordering is not a permutation of %d", A.n);
    comm_ = comm;
    n_ = A.n;
    PetscMPIInt size, rank;
    PetscCallMPI(MPI_Comm_size(comm, &size));
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    // Part of each free DOF: METIS on the node graph (rank 0, broadcast), or on the DOF graph without one.
    const bool by_nodes = nodes_.n > 0 && static_cast<int>(eq_.size()) == 3 * nodes_.n;
    std::vector<idx_t> part;
    PetscCall(partition(comm, by_nodes ? nodes_ : graphOfMatrix(A), size, rank, &part));
    distributed_ = size > 1 && by_nodes;
    numberByParts(dofParts(part, by_nodes), perm, size, rank);
    std::vector<PetscInt> dnz, onz;
    const long long nnz = localRows(A, &dnz, &onz);
    PetscCall(createOperator(comm, dnz, onz, nnz));
    PetscCall(fixPattern());
    PetscCall(describeLayout(size, by_nodes));
    PetscFunctionReturn(0);
  }

  PetscErrorCode factor(const SymCsc& A, bool* ok) override {
    PetscFunctionBeginUser;
    if (distributed_) {
      // Partial sums of this rank's elements: add every nonzero (both triangles); MatAssembly sends the
      // entries of rows owned by other ranks to them.
      PetscCall(MatZeroEntries(A_));
      for (int c = 0; c < n_; ++c)
        for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k) {
          const double v = A.val[k];
          if (v == 0.0) continue;
          const int r = A.rowind[k];
          PetscCall(MatSetValue(A_, map_[r], map_[c], v, ADD_VALUES));
          if (r != c) PetscCall(MatSetValue(A_, map_[c], map_[r], v, ADD_VALUES));
        }
    } else {
      for (size_t j = 0; j < vidx_.size(); ++j) vals_[j] = A.val[vidx_[j]];
      PetscCall(insertLocalRows());
    }
    PetscCall(MatAssemblyBegin(A_, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A_, MAT_FINAL_ASSEMBLY));
    if (!operators_set_) {
      PetscCall(KSPSetOperators(ksp_, A_, A_));
      operators_set_ = true;
    }
    PetscCall(KSPSetUp(ksp_));
    PC pc;
    PetscCall(KSPGetPC(ksp_, &pc));
    PCFailedReason why = PC_NOERROR;
    PetscCall(PCGetFailedReason(pc, &why));
    int bad = why != PC_NOERROR, any = 0;
    PetscCallMPI(MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, comm_));
    *ok = any == 0;
    PetscFunctionReturn(0);
  }

  PetscErrorCode solve(const double* b, double* x) override {
    PetscFunctionBeginUser;
    PetscScalar* bl;
    PetscCall(VecGetArray(b_, &bl));
    for (PetscInt i = 0; i < nlocal_; ++i) bl[i] = b[inv_[rstart_ + i]];
    PetscCall(VecRestoreArray(b_, &bl));
    PetscCall(KSPSolve(ksp_, b_, x_));
    KSPConvergedReason reason;
    PetscCall(KSPGetConvergedReason(ksp_, &reason));
    PetscCheck(reason > 0, comm_, PETSC_ERR_NOT_CONVERGED,
               "-solver petsc: KSP did not converge (%s); try -ksp_type preonly -pc_type cholmod or a larger "
               "-ksp_max_it",
               KSPConvergedReasons[reason]);
    PetscCall(VecScatterBegin(toall_, x_, xall_, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(toall_, x_, xall_, INSERT_VALUES, SCATTER_FORWARD));
    const PetscScalar* xa;
    PetscCall(VecGetArrayRead(xall_, &xa));
    for (int i = 0; i < n_; ++i) x[i] = xa[map_[i]];
    PetscCall(VecRestoreArrayRead(xall_, &xa));
    PetscFunctionReturn(0);
  }

  FactorStats stats() const override { return stats_; }
  std::string describe() const override { return desc_; }
  bool distributedAssembly() const override { return distributed_; }
  const std::vector<int>& nodePartition() const override { return node_part_; }

private:
  // One part per rank of the graph g: METIS_PartGraphKway on rank 0 (contiguous blocks for a graph without
  // edges or with fewer vertices than ranks), broadcast; all zeros at one rank.
  static PetscErrorCode partition(MPI_Comm comm, const Graph& g, int size, int rank,
                                  std::vector<idx_t>* part) {
    PetscFunctionBeginUser;
    part->assign(g.n, 0);
    if (size <= 1 || g.n <= 0) PetscFunctionReturn(0);
    int status = METIS_OK;
    if (rank == 0) {
      idx_t nv = g.n, ncon = 1, nparts = size, cut = 0;
      std::vector<idx_t> xadj(g.xadj.begin(), g.xadj.end()), adj(g.adj.begin(), g.adj.end());
      idx_t options[METIS_NOPTIONS];
      METIS_SetDefaultOptions(options);
      if (g.adj.empty() || g.n < size) {
        for (int v = 0; v < g.n; ++v) (*part)[v] = static_cast<idx_t>((long long)v * size / g.n);
      } else {
        status = METIS_PartGraphKway(&nv, &ncon, xadj.data(), adj.data(), nullptr, nullptr, nullptr, &nparts,
                                     nullptr, nullptr, options, &cut, part->data());
      }
    }
    PetscCallMPI(MPI_Bcast(&status, 1, MPI_INT, 0, comm));
    PetscCheck(status == METIS_OK, comm, PETSC_ERR_LIB, "METIS_PartGraphKway failed (status %d)", status);
    static_assert(sizeof(idx_t) == 4 || sizeof(idx_t) == 8, "idx_t");
    PetscCallMPI(MPI_Bcast(part->data(), g.n, sizeof(idx_t) == 8 ? MPI_INT64_T : MPI_INT32_T, 0, comm));
    PetscFunctionReturn(0);
  }

  // The part of each free DOF: that of its node (by_nodes; kept as node_part_) or of the DOF itself.
  std::vector<int> dofParts(const std::vector<idx_t>& part, bool by_nodes) {
    std::vector<int> dof_part(n_, 0);
    node_part_.assign(part.begin(), part.end());
    if (!by_nodes) node_part_.clear();
    if (by_nodes) {
      for (int v = 0; v < nodes_.n; ++v)
        for (int c = 0; c < 3; ++c)
          if (eq_[3 * v + c] >= 0) dof_part[eq_[3 * v + c]] = static_cast<int>(part[v]);
    } else {
      for (int i = 0; i < n_; ++i) dof_part[i] = static_cast<int>(part[i]);
    }
    return dof_part;
  }

  // Global numbering: part by part, in the order of perm within a part; this rank's block of rows.
  void numberByParts(const std::vector<int>& dof_part, const std::vector<int>& perm, int size, int rank) {
    std::vector<PetscInt> count(size + 1, 0);
    for (int i = 0; i < n_; ++i) ++count[dof_part[i] + 1];
    std::partial_sum(count.begin(), count.end(), count.begin());
    range_.assign(count.begin(), count.end());
    std::vector<PetscInt> next(count.begin(), count.end() - 1);
    map_.assign(n_, 0);
    inv_.assign(n_, 0);
    for (int k = 0; k < n_; ++k) {
      const int old = perm[k];
      const PetscInt idx = next[dof_part[old]]++;
      map_[old] = idx;
      inv_[idx] = old;
    }
    rstart_ = range_[rank];
    nlocal_ = range_[rank + 1] - range_[rank];
  }

  // Local rows of the symmetric matrix (both triangles) with the index of each value in A.val, and the
  // nonzeros per row in and outside the diagonal block; returns this rank's number of entries.
  long long localRows(const SymCsc& A, std::vector<PetscInt>* dnz, std::vector<PetscInt>* onz) {
    struct Entry {
      PetscInt row, col;
      int k;
    };
    std::vector<Entry> ent;
    for (int c = 0; c < n_; ++c)
      for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k) {
        const int r = A.rowind[k];
        const PetscInt pr = map_[r], pc = map_[c];
        if (pr >= rstart_ && pr < rstart_ + nlocal_) ent.push_back({pr, pc, k});
        if (r != c && pc >= rstart_ && pc < rstart_ + nlocal_) ent.push_back({pc, pr, k});
      }
    std::sort(ent.begin(), ent.end(),
              [](const Entry& a, const Entry& b) { return a.row != b.row ? a.row < b.row : a.col < b.col; });
    rowptr_.assign(nlocal_ + 1, 0);
    cols_.resize(ent.size());
    vidx_.resize(ent.size());
    vals_.resize(ent.size());
    dnz->assign(nlocal_, 0), onz->assign(nlocal_, 0);
    for (size_t j = 0; j < ent.size(); ++j) {
      const PetscInt lr = ent[j].row - rstart_;
      ++rowptr_[lr + 1];
      cols_[j] = ent[j].col;
      vidx_[j] = ent[j].k;
      const bool diag = ent[j].col >= rstart_ && ent[j].col < rstart_ + nlocal_;
      ++(diag ? *dnz : *onz)[lr];
    }
    std::partial_sum(rowptr_.begin(), rowptr_.end(), rowptr_.begin());
    return static_cast<long long>(ent.size());
  }

  // The MPIAIJ matrix preallocated with dnz, onz, its vectors and the scatter of the solution to all ranks.
  PetscErrorCode createOperator(MPI_Comm comm, const std::vector<PetscInt>& dnz,
                                const std::vector<PetscInt>& onz, long long nnz) {
    PetscFunctionBeginUser;
    MatDestroy(&A_);
    PetscCall(MatCreateAIJ(comm, nlocal_, nlocal_, n_, n_, 0, dnz.data(), 0, onz.data(), &A_));
    PetscCall(MatSetOption(A_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
    PetscCall(MatSetOption(A_, MAT_SYMMETRIC, PETSC_TRUE));
    PetscCall(MatSetOption(A_, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
    VecDestroy(&b_);
    VecDestroy(&x_);
    VecDestroy(&xall_);
    VecScatterDestroy(&toall_);
    PetscCall(MatCreateVecs(A_, &x_, &b_));
    PetscCall(VecScatterCreateToAll(x_, &toall_, &xall_));
    long long total = 0;
    PetscCallMPI(MPI_Allreduce(&nnz, &total, 1, MPI_LONG_LONG, MPI_SUM, comm));
    stats_.nnz_L = (total + n_) / 2; // stored upper triangle of the matrix (the factor is PETSc's business)
    stats_.flops = 0;
    operators_set_ = false;
    PetscFunctionReturn(0);
  }

  // vals_ into the owned rows of A_ (INSERT_VALUES).
  PetscErrorCode insertLocalRows() {
    PetscFunctionBeginUser;
    for (PetscInt r = 0; r < nlocal_; ++r) {
      const PetscInt row = rstart_ + r, nc = rowptr_[r + 1] - rowptr_[r];
      PetscCall(
          MatSetValues(A_, 1, &row, nc, cols_.data() + rowptr_[r], vals_.data() + rowptr_[r], INSERT_VALUES));
    }
    PetscFunctionReturn(0);
  }

  // Fix the nonzero structure once (zeros on the whole pattern of the owned rows): partial sums skip exact
  // zeros, and the first matrix (e.g. the mass) may have structural zeros.
  PetscErrorCode fixPattern() {
    PetscFunctionBeginUser;
    std::fill(vals_.begin(), vals_.end(), 0.0);
    PetscCall(insertLocalRows());
    PetscCall(MatAssemblyBegin(A_, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A_, MAT_FINAL_ASSEMBLY));
    PetscCall(KSPSetOperators(ksp_, A_, A_));
    operators_set_ = true;
    PetscFunctionReturn(0);
  }

  // The one-line description: rows, ranks, partition, KSP and PC types, assembly.
  PetscErrorCode describeLayout(int size, bool by_nodes) {
    PetscFunctionBeginUser;
    KSPType kt;
    PCType pt;
    PC pc;
    PetscCall(KSPGetType(ksp_, &kt));
    PetscCall(KSPGetPC(ksp_, &pc));
    PetscCall(PCGetType(pc, &pt));
    PetscInt lmin = n_, lmax = 0;
    for (int p = 0; p < size; ++p)
      lmin = std::min(lmin, range_[p + 1] - range_[p]), lmax = std::max(lmax, range_[p + 1] - range_[p]);
    char d[256];
    snprintf(
        d, sizeof d,
        "petsc: %d rows on %d ranks (METIS %s partition, %d..%d rows per rank), KSP %s, PC %s, %s assembly",
        n_, size, by_nodes ? "node" : "DOF", (int)lmin, (int)lmax, kt ? kt : "?", pt ? pt : "?",
        distributed_ ? "distributed" : "replicated");
    desc_ = d;
    PetscFunctionReturn(0);
  }
  std::string desc_ = "petsc";
  MPI_Comm comm_ = MPI_COMM_SELF;
  KSP ksp_ = nullptr;
  Mat A_ = nullptr;
  Vec b_ = nullptr, x_ = nullptr, xall_ = nullptr;
  VecScatter toall_ = nullptr;
  bool operators_set_ = false, distributed_ = false;
  std::vector<int> node_part_;
  Graph nodes_;
  std::vector<int> eq_;
  int n_ = 0;
  PetscInt rstart_ = 0, nlocal_ = 0;
  std::vector<PetscInt> range_, map_, inv_, rowptr_, cols_;
  std::vector<int> vidx_;
  std::vector<PetscScalar> vals_;
  FactorStats stats_;
};

} // namespace

std::unique_ptr<LinearSolver> makePetscSolver() {
  return std::make_unique<PetscSolver>();
}

} // namespace suite::fem
