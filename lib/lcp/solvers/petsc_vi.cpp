// PETSc's variational-inequality Newton solvers as reference methods: SNESVINEWTONSSLS (semismooth, Fischer-
// Burmeister based; Munson, Facchinei, Ferris, Fischer & Kanzow 2001, INFORMS J. Comput. 13) and
// SNESVINEWTONRSLS (reduced-space active set; Benson & Munson 2006, Optim. Methods Softw. 21) on
// F(z) = M z + q with bounds l <= z <= u (PETSC_NINFINITY / PETSC_INFINITY for infinite bounds), dense
// sequential matrices on PETSC_COMM_SELF (one problem per rank). Warm start: the initial z.
#include "lcp/solver.hpp"

#include <petscsnes.h>

#include <cmath>

namespace suite::lcp {
namespace {

struct Ctx {
  const Problem* p;
};

PetscErrorCode formF(SNES, ::Vec X, ::Vec F, void* ptr) {
  const Problem& p = *static_cast<Ctx*>(ptr)->p;
  const PetscScalar* x;
  PetscScalar* f;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(X, &x));
  PetscCall(VecGetArray(F, &f));
  Eigen::Map<const Vec> xv(x, p.size());
  Eigen::Map<Vec> fv(f, p.size());
  fv = p.M * xv + p.q;
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCall(VecRestoreArray(F, &f));
  PetscFunctionReturn(0);
}

// Jacobian M, copied every call: SNESVINEWTONSSLS scales the matrix in place to build the semismooth
// Jacobian.
PetscErrorCode formJ(SNES, ::Vec, ::Mat J, ::Mat, void* ptr) {
  const Problem& p = *static_cast<Ctx*>(ptr)->p;
  PetscScalar* a;
  PetscFunctionBeginUser;
  PetscCall(MatDenseGetArray(J, &a)); // column-major, like Eigen
  Eigen::Map<Eigen::MatrixXd>(a, p.size(), p.size()) = p.M;
  PetscCall(MatDenseRestoreArray(J, &a));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

class PetscVi : public Solver {
public:
  PetscVi(const char* name, SNESType type) : name_(name), type_(type) {}
  std::string name() const override { return name_; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    Result r;
    if (runPetsc(p, opt, &r)) {
      r.status = Status::NumericalError;
      r.message = "PETSc error in " + name_;
      if (r.z.size() != p.size()) r.z = Vec::Zero(p.size());
    }
    return r;
  }

private:
  PetscErrorCode runPetsc(const Problem& p, const SolverOptions& opt, Result* r) const {
    const PetscInt n = p.size();
    SNES snes;
    ::Mat J;
    ::Vec x, f, xl, xu;
    Ctx ctx{&p};
    PetscFunctionBeginUser;
    PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, n, n, nullptr, &J));
    PetscCall(formJ(nullptr, nullptr, J, J, &ctx));
    PetscCall(VecCreateSeq(PETSC_COMM_SELF, n, &x));
    PetscCall(VecDuplicate(x, &f));
    PetscCall(VecDuplicate(x, &xl));
    PetscCall(VecDuplicate(x, &xu));
    {
      PetscScalar *pl, *pu, *px;
      PetscCall(VecGetArray(xl, &pl));
      PetscCall(VecGetArray(xu, &pu));
      PetscCall(VecGetArray(x, &px));
      for (PetscInt i = 0; i < n; ++i) {
        pl[i] = std::isfinite(p.l[i]) ? p.l[i] : PETSC_NINFINITY;
        pu[i] = std::isfinite(p.u[i]) ? p.u[i] : PETSC_INFINITY;
        double z0 = (opt.warm_start && opt.warm_start->size() == n) ? (*opt.warm_start)[i] : 0.0;
        px[i] = std::min(p.u[i], std::max(p.l[i], z0));
      }
      PetscCall(VecRestoreArray(xl, &pl));
      PetscCall(VecRestoreArray(xu, &pu));
      PetscCall(VecRestoreArray(x, &px));
    }
    PetscCall(SNESCreate(PETSC_COMM_SELF, &snes));
    PetscCall(SNESSetType(snes, type_));
    PetscCall(SNESSetFunction(snes, f, formF, &ctx));
    PetscCall(SNESSetJacobian(snes, J, J, formJ, &ctx));
    PetscCall(SNESVISetVariableBounds(snes, xl, xu));
    const double tol = acceptanceTolerance(p, opt.rel_tol);
    const PetscInt maxit = opt.max_iterations > 0 ? opt.max_iterations : 200;
    PetscCall(SNESSetTolerances(snes, 0.1 * tol, 0.0, 0.0, maxit, 100000));
    KSP ksp;
    PC pc;
    PetscCall(SNESGetKSP(snes, &ksp));
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCLU));
    PetscCall(SNESSetOptionsPrefix(snes, "lcp_vi_")); // tunable as -lcp_vi_snes_*, never picks up app options
    PetscCall(SNESSolve(snes, nullptr, x));
    SNESConvergedReason reason;
    PetscInt its;
    PetscCall(SNESGetConvergedReason(snes, &reason));
    PetscCall(SNESGetIterationNumber(snes, &its));
    const PetscScalar* px;
    PetscCall(VecGetArrayRead(x, &px));
    r->z = Eigen::Map<const Vec>(px, n);
    PetscCall(VecRestoreArrayRead(x, &px));
    r->iterations = static_cast<int>(its);
    if (reason > 0)
      r->status = Status::Solved;
    else if (reason == SNES_DIVERGED_MAX_IT)
      r->status = Status::MaxIterations;
    else
      r->status = Status::Breakdown;
    if (reason <= 0) r->message = std::string("SNES ") + SNESConvergedReasons[reason];
    // A converged SNES is still checked against the natural residual in solve().
    PetscCall(SNESDestroy(&snes));
    PetscCall(VecDestroy(&x));
    PetscCall(VecDestroy(&f));
    PetscCall(VecDestroy(&xl));
    PetscCall(VecDestroy(&xu));
    PetscCall(MatDestroy(&J));
    PetscFunctionReturn(0);
  }
  std::string name_;
  SNESType type_;
};

} // namespace

std::unique_ptr<Solver> makePetscSsls() {
  return std::make_unique<PetscVi>("petsc_ssls", SNESVINEWTONSSLS);
}
std::unique_ptr<Solver> makePetscRsls() {
  return std::make_unique<PetscVi>("petsc_rsls", SNESVINEWTONRSLS);
}

} // namespace suite::lcp
