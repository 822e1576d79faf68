// Elastodynamics residual and Jacobian on a DMPlex, element by element (see plex_elasticity.hpp).
#include "fem/plex_elasticity.hpp"

#include <petscds.h>
#include <petscfe.h>

#include <cmath>

namespace suite::fem {

namespace {

// One P1 tetrahedron from its vertex coordinates x[12] (closure order): volume and the gradients g[3a + j] of
// its barycentric coordinates. False when degenerate.
struct Tet {
  double V, g[12];
};

bool tetGeometry(const PetscScalar* x, Tet* t) {
  Mat3 J;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) J(i, k) = PetscRealPart(x[3 * (k + 1) + i] - x[i]);
  const double det = J.determinant();
  if (!(std::abs(det) > 0.0)) return false;
  const Mat3 Ji = J.inverse();
  t->V = std::abs(det) / 6.0;
  for (int j = 0; j < 3; ++j) {
    t->g[j] = 0.0;
    for (int a = 1; a < 4; ++a) t->g[3 * a + j] = Ji(a - 1, j), t->g[j] -= Ji(a - 1, j);
  }
  return true;
}

// F = I + sum_a u_a g_a^T.
Mat3 deformationGradient(const PetscScalar* u, const Tet& t) {
  Mat3 F = Mat3::Identity();
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) F(i, j) += PetscRealPart(u[3 * a + i]) * t.g[3 * a + j];
  return F;
}

// Consistent P1 mass: rho V (1 + d_ab) / 20.
inline double massEntry(double rho, double V, int a, int b) {
  return rho * V * (a == b ? 2.0 : 1.0) / 20.0;
}

PetscErrorCode zeroDisplacement(PetscInt, PetscReal, const PetscReal[], PetscInt nc, PetscScalar* u, void*) {
  for (PetscInt i = 0; i < nc; ++i) u[i] = 0.0;
  return 0;
}

PetscErrorCode rigidBodyModes(DM dm, PetscInt field, PetscInt, MatNullSpace* sp) {
  return DMPlexCreateRigidBody(dm, field, sp);
}

// RAII closure of a local vector on one cell.
struct Closure {
  DM dm;
  Vec v;
  PetscInt cell, n = 0;
  PetscScalar* x = nullptr;
  PetscErrorCode get() { return DMPlexVecGetClosure(dm, nullptr, v, cell, &n, &x); }
  ~Closure() {
    if (x) DMPlexVecRestoreClosure(dm, nullptr, v, cell, &n, &x);
  }
};

} // namespace

PetscErrorCode PlexElasticity::setup(DM dm, const PlexElasticParams& p) {
  PetscFE fe;
  DMLabel clamped;
  const PetscInt one = 1;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscFunctionBeginUser;
  dm_ = dm, p_ = p;
  PetscCall(createMaterial(comm, p.law, p.lame, &material_));
  PetscCall(PetscFECreateLagrange(comm, 3, 3, PETSC_TRUE, 1, PETSC_DETERMINE, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, "displacement"));
  PetscCall(DMSetField(dm, 0, nullptr, (PetscObject)fe));
  PetscCall(DMCreateDS(dm));
  PetscCall(PetscFEDestroy(&fe));
  PetscCall(DMGetLabel(dm, "clamped", &clamped));
  PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, "clamped", clamped, 1, &one, 0, 0, nullptr,
                          (void (*)(void))zeroDisplacement, nullptr, nullptr, nullptr));
  PetscCall(DMSetNearNullSpaceConstructor(dm, 0, rigidBodyModes));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::attach(SNES snes) {
  Mat J;
  MatNullSpace rbm;
  PetscFunctionBeginUser;
  snes_ = snes;
  PetscCall(DMSNESSetFunctionLocal(dm_, residualLocal, this));
  PetscCall(DMSNESSetJacobianLocal(dm_, jacobianLocal, this));
  PetscCall(DMCreateMatrix(dm_, &J));
  PetscCall(DMPlexCreateRigidBody(dm_, 0, &rbm));
  PetscCall(MatSetNearNullSpace(J, rbm));
  PetscCall(MatNullSpaceDestroy(&rbm));
  PetscCall(SNESSetJacobian(snes, J, J, nullptr, nullptr));
  PetscCall(MatDestroy(&J));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::residualLocal(DM dm, Vec x, Vec f, void* ctx) {
  return static_cast<PlexElasticity*>(ctx)->residual(dm, x, f);
}

PetscErrorCode PlexElasticity::jacobianLocal(DM dm, Vec x, Mat J, Mat, void* ctx) {
  return static_cast<PlexElasticity*>(ctx)->jacobian(dm, x, J);
}

// Element by element: M (c u - b) + k V P g_a - rho g V / 4 into f (local; summed into the global residual).
PetscErrorCode PlexElasticity::residual(DM dm, Vec x, Vec f) {
  Vec coords;
  PetscInt c0, c1;
  bool admissible = true;
  PetscFunctionBeginUser;
  PetscCall(DMPlexInsertBoundaryValues(dm, PETSC_TRUE, x, 0.0, nullptr, nullptr, nullptr));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c0, &c1));
  const double c = w_.mass, k = w_.stiffness, rho = p_.rho;
  energy_ = 0.0;
  for (PetscInt cell = c0; cell < c1; ++cell) {
    Closure xc{dm, coords, cell}, uc{dm, x, cell}, bc{dm, b_, cell};
    PetscCall(xc.get());
    PetscCall(uc.get());
    PetscCall(bc.get());
    Tet t;
    PetscCheck(tetGeometry(xc.x, &t), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "degenerate tetrahedron %d",
               (int)cell);
    PetscScalar fe[12] = {};
    if (k != 0.0) {
      const Mat3 F = deformationGradient(uc.x, t);
      admissible = admissible && (material_->isLinear() || F.determinant() > 0.0);
      double W = 0.0;
      Mat3 P;
      material_->evaluate(F, &W, &P, nullptr);
      energy_ += k * W * t.V;
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) fe[3 * a + i] += k * t.V * P(i, j) * t.g[3 * a + j];
    }
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) {
        for (int b = 0; b < 4; ++b)
          fe[3 * a + i] += massEntry(rho, t.V, a, b) * (c * uc.x[3 * b + i] - bc.x[3 * b + i]);
        fe[3 * a + i] -= rho * p_.gravity[i] * t.V / 4.0;
      }
    PetscCall(DMPlexVecSetClosure(dm, nullptr, f, cell, fe, ADD_VALUES));
  }
  if (!admissible && snes_) PetscCall(SNESSetFunctionDomainError(snes_)); // an inverted element: Newton fails
  PetscFunctionReturn(0);
}

// Element by element: c M + k K_T (the material's closed-form tangent, upper triangle, then mirrored).
PetscErrorCode PlexElasticity::jacobian(DM dm, Vec x, Mat J) {
  Vec coords;
  PetscInt c0, c1;
  PetscFunctionBeginUser;
  PetscCall(DMPlexInsertBoundaryValues(dm, PETSC_TRUE, x, 0.0, nullptr, nullptr, nullptr));
  PetscCall(MatZeroEntries(J));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c0, &c1));
  const double c = w_.mass, k = w_.stiffness, rho = p_.rho;
  for (PetscInt cell = c0; cell < c1; ++cell) {
    Closure xc{dm, coords, cell}, uc{dm, x, cell};
    PetscCall(xc.get());
    PetscCall(uc.get());
    Tet t;
    PetscCheck(tetGeometry(xc.x, &t), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "degenerate tetrahedron %d",
               (int)cell);
    double ke[144] = {};
    if (k != 0.0) material_->addElementTangent(deformationGradient(uc.x, t), t.g, 4, k * t.V, ke);
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b)
        for (int i = 0; i < 3; ++i) ke[(3 * a + i) * 12 + 3 * b + i] += c * massEntry(rho, t.V, a, b);
    for (int p = 0; p < 12; ++p)
      for (int q = 0; q < p; ++q) ke[p * 12 + q] = ke[q * 12 + p];
    PetscCall(DMPlexMatSetClosure(dm, nullptr, nullptr, J, cell, ke, ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::strainEnergy(double* e) const {
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&energy_, e, 1, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  PetscFunctionReturn(0);
}

} // namespace suite::fem
