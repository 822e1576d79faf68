// Elastodynamics residual and Jacobian on a DMPlex, element by element (see plex_elasticity.hpp).
#include "fem/plex_elasticity.hpp"

#include "fem/plex_beam.hpp"

#include <petscds.h>
#include <petscfe.h>

#include <algorithm>
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

} // namespace

PetscErrorCode PlexElasticity::setup(DM dm, const PlexElasticParams& p) {
  PetscFE fe;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscFunctionBeginUser;
  dm_ = dm, p_ = p;
  PetscCall(createMaterial(comm, p.law, p.lame, &material_));
  PetscCall(PetscFECreateLagrange(comm, 3, 3, PETSC_TRUE, 1, PETSC_DETERMINE, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, "displacement"));
  PetscCall(DMSetField(dm, 0, nullptr, (PetscObject)fe));
  PetscCall(DMCreateDS(dm));
  PetscCall(PetscFEDestroy(&fe));
  for (const PlexGroup& g : p.fixed) {
    DMLabel label;
    PetscCall(DMGetLabel(dm, g.name.c_str(), &label));
    PetscCall(DMPlexLabelComplete(dm, label)); // the faces' edges and vertices: their DOFs are fixed too
    PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, g.name.c_str(), label, 1, &g.value, 0, 0, nullptr,
                            (void (*)(void))zeroDisplacement, nullptr, nullptr, nullptr));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::attach(SNES snes) {
  Mat J;
  MatNullSpace rbm;
  PetscFunctionBeginUser;
  snes_ = snes;
  PetscCall(prepareCells());
  PetscCall(DMSNESSetFunctionLocal(dm_, residualLocal, this));
  PetscCall(DMSNESSetJacobianLocal(dm_, jacobianLocal, this));
  PetscCall(createJacobian(&J));
  PetscCall(rigidBodyModes(&rbm));
  PetscCall(MatSetNearNullSpace(J, rbm));
  PetscCall(MatNullSpaceDestroy(&rbm));
  PetscCall(SNESSetJacobian(snes, J, J, nullptr, nullptr));
  PetscCall(MatDestroy(&J));
  PetscFunctionReturn(0);
}

// The 4 vertices of a cell's closure, in closure order.
static PetscErrorCode cellVertices(DM dm, PetscInt cell, PetscInt v0, PetscInt v1, PetscInt vert[4]) {
  PetscInt n = 0, *pts = nullptr, nv = 0;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &n, &pts));
  for (PetscInt i = 0; i < 2 * n; i += 2)
    if (pts[i] >= v0 && pts[i] < v1 && nv < 4) vert[nv++] = pts[i];
  PetscCall(DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &n, &pts));
  PetscCheck(nv == 4, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell %d has %d vertices, not 4", (int)cell, (int)nv);
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::prepareCells() {
  PetscSection ls, gs, cs;
  Vec coords;
  const PetscScalar* cx;
  PetscInt c0, c1, v0, v1;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm_, &ls));
  PetscCall(DMGetGlobalSection(dm_, &gs));
  PetscCall(DMGetCoordinateSection(dm_, &cs));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMPlexGetHeightStratum(dm_, 0, &c0, &c1));
  PetscCall(DMPlexGetDepthStratum(dm_, 0, &v0, &v1));
  const size_t nc = (size_t)(c1 - c0);
  vol_.resize(nc), grad_.resize(12 * nc), loc_.resize(12 * nc), glob_.resize(12 * nc);
  PetscCall(VecGetArrayRead(coords, &cx));
  PetscInt degenerate = -1;
  for (PetscInt cell = c0; cell < c1; ++cell) {
    const size_t e = (size_t)(cell - c0);
    PetscInt vert[4];
    PetscScalar x[12];
    PetscCall(cellVertices(dm_, cell, v0, v1, vert));
    for (int a = 0; a < 4; ++a) {
      PetscInt off, goff, cdof;
      PetscCall(PetscSectionGetOffset(cs, vert[a], &off));
      for (int j = 0; j < 3; ++j) x[3 * a + j] = cx[off + j];
      PetscCall(PetscSectionGetOffset(ls, vert[a], &off));
      PetscCall(PetscSectionGetOffset(gs, vert[a], &goff));
      PetscCall(PetscSectionGetConstraintDof(gs, vert[a], &cdof));
      if (goff < 0) goff = -(goff + 1); // owned by another rank
      for (int i = 0; i < 3; ++i)
        loc_[12 * e + 3 * a + i] = off + i, glob_[12 * e + 3 * a + i] = cdof ? -1 : goff + i;
    }
    Tet t;
    if (!tetGeometry(x, &t)) {
      degenerate = std::max(degenerate, cell - c0);
      continue;
    }
    vol_[e] = t.V;
    std::copy(t.g, t.g + 12, &grad_[12 * e]);
  }
  PetscCall(VecRestoreArrayRead(coords, &cx));
  PetscInt worst = degenerate;
  PetscCallMPI(MPI_Allreduce(&degenerate, &worst, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)dm_)));
  PetscCheck(worst < 0, PetscObjectComm((PetscObject)dm_), PETSC_ERR_ARG_WRONG,
             "a degenerate (zero-volume) tetrahedron (local cell %d of a rank)", (int)worst);
  PetscFunctionReturn(0);
}

// The six rigid-body modes on the global vector's layout (owned, unconstrained vertices, 3 DOFs each), from
// their coordinates (MatNullSpaceCreateRigidBody; DMPlexCreateRigidBody projects them through the FE space with
// per-cell label lookups, ~10% of the setup at 40k DOFs).
PetscErrorCode PlexElasticity::rigidBodyModes(MatNullSpace* sp) const {
  Vec xyz;
  PetscScalar* a;
  PetscInt r0;
  std::vector<FreeVertex> fv;
  PetscFunctionBeginUser;
  PetscCall(ownedFreeVertices(dm_, &fv));
  PetscCall(DMCreateGlobalVector(dm_, &xyz));
  PetscCall(VecSetBlockSize(xyz, 3));
  PetscCall(VecGetOwnershipRange(xyz, &r0, nullptr));
  PetscCall(VecGetArray(xyz, &a));
  for (const FreeVertex& v : fv)
    for (int j = 0; j < 3; ++j) a[v.goff - r0 + j] = v.x[j];
  PetscCall(VecRestoreArray(xyz, &a));
  PetscCall(MatNullSpaceCreateRigidBody(xyz, sp));
  PetscCall(VecDestroy(&xyz));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::createJacobian(Mat* J) const {
  Mat pre;
  Vec g;
  PetscInt n, N;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(dm_, &g));
  PetscCall(VecGetLocalSize(g, &n));
  PetscCall(VecGetSize(g, &N));
  PetscCall(DMRestoreGlobalVector(dm_, &g));
  PetscCall(MatCreate(comm, &pre));
  PetscCall(MatSetSizes(pre, n, n, N, N));
  PetscCall(MatSetType(pre, MATPREALLOCATOR));
  PetscCall(MatSetUp(pre));
  const double zeros[144] = {};
  for (size_t e = 0; e < vol_.size(); ++e)
    PetscCall(MatSetValues(pre, 12, &glob_[12 * e], 12, &glob_[12 * e], zeros, INSERT_VALUES));
  PetscCall(MatAssemblyBegin(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreate(comm, J));
  PetscCall(MatSetSizes(*J, n, n, N, N));
  PetscCall(MatSetType(*J, MATAIJ));
  PetscCall(MatSetBlockSize(*J, 3));
  PetscCall(MatPreallocatorPreallocate(pre, PETSC_TRUE, *J));
  PetscCall(MatDestroy(&pre));
  PetscCall(MatSetOption(*J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
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
  const PetscScalar *xa, *ba;
  PetscScalar* fa;
  bool admissible = true;
  PetscFunctionBeginUser;
  PetscCall(DMPlexInsertBoundaryValues(dm, PETSC_TRUE, x, 0.0, nullptr, nullptr, nullptr));
  PetscCall(VecGetArrayRead(x, &xa));
  PetscCall(VecGetArrayRead(b_, &ba));
  PetscCall(VecGetArray(f, &fa));
  const double c = w_.mass, k = w_.stiffness, rho = p_.rho;
  energy_ = 0.0;
  for (size_t e = 0; e < vol_.size(); ++e) {
    const PetscInt* li = &loc_[12 * e];
    Tet t;
    t.V = vol_[e];
    std::copy(&grad_[12 * e], &grad_[12 * e] + 12, t.g);
    PetscScalar u[12], fe[12] = {};
    for (int m = 0; m < 12; ++m) u[m] = xa[li[m]];
    if (k != 0.0) {
      const Mat3 F = deformationGradient(u, t);
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
          fe[3 * a + i] += massEntry(rho, t.V, a, b) * (c * u[3 * b + i] - ba[li[3 * b + i]]);
        fe[3 * a + i] -= rho * p_.gravity[i] * t.V / 4.0;
      }
    for (int m = 0; m < 12; ++m) fa[li[m]] += fe[m];
  }
  PetscCall(VecRestoreArray(f, &fa));
  PetscCall(VecRestoreArrayRead(b_, &ba));
  PetscCall(VecRestoreArrayRead(x, &xa));
  if (!admissible && snes_) PetscCall(SNESSetFunctionDomainError(snes_)); // an inverted element: Newton fails
  PetscFunctionReturn(0);
}

// Element by element: c M + k K_T (the material's closed-form tangent, upper triangle, then mirrored).
PetscErrorCode PlexElasticity::jacobian(DM dm, Vec x, Mat J) {
  const PetscScalar* xa;
  PetscFunctionBeginUser;
  PetscCall(DMPlexInsertBoundaryValues(dm, PETSC_TRUE, x, 0.0, nullptr, nullptr, nullptr));
  PetscCall(MatZeroEntries(J));
  PetscCall(VecGetArrayRead(x, &xa));
  const double c = w_.mass, k = w_.stiffness, rho = p_.rho;
  for (size_t e = 0; e < vol_.size(); ++e) {
    Tet t;
    t.V = vol_[e];
    std::copy(&grad_[12 * e], &grad_[12 * e] + 12, t.g);
    PetscScalar u[12];
    for (int m = 0; m < 12; ++m) u[m] = xa[loc_[12 * e + m]];
    double ke[144] = {};
    if (k != 0.0) material_->addElementTangent(deformationGradient(u, t), t.g, 4, k * t.V, ke);
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b)
        for (int i = 0; i < 3; ++i) ke[(3 * a + i) * 12 + 3 * b + i] += c * massEntry(rho, t.V, a, b);
    for (int p = 0; p < 12; ++p)
      for (int q = 0; q < p; ++q) ke[p * 12 + q] = ke[q * 12 + p];
    PetscCall(MatSetValues(J, 12, &glob_[12 * e], 12, &glob_[12 * e], ke, ADD_VALUES));
  }
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::kineticEnergy(Vec v, double* e) const {
  Vec loc;
  const PetscScalar* va;
  double mine = 0.0;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm_, &loc));
  PetscCall(VecZeroEntries(loc)); // clamped DOFs: v = 0
  PetscCall(DMGlobalToLocal(dm_, v, INSERT_VALUES, loc));
  PetscCall(VecGetArrayRead(loc, &va));
  for (size_t c = 0; c < vol_.size(); ++c) {
    const PetscInt* li = &loc_[12 * c];
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int i = 0; i < 3; ++i)
          mine +=
              0.5 * massEntry(p_.rho, vol_[c], a, b) * PetscRealPart(va[li[3 * a + i]] * va[li[3 * b + i]]);
  }
  PetscCall(VecRestoreArrayRead(loc, &va));
  PetscCall(DMRestoreLocalVector(dm_, &loc));
  PetscCallMPI(MPI_Allreduce(&mine, e, 1, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::strainEnergy(double* e) const {
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&energy_, e, 1, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  PetscFunctionReturn(0);
}

} // namespace suite::fem
