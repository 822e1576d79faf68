// Elastodynamics residual and Jacobian on a DMPlex, element by element (see plex_elasticity.hpp).
#include "fem/plex_elasticity.hpp"

#include "fem/plex_beam.hpp"

#include <petscds.h>
#include <petscfe.h>

#include <algorithm>
#include <utility>
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

// f += C (c_v u - b_v) of one element: alpha M + beta K_0 times its damping velocity (cv: c_v).
void addDamping(const Tet& t, const PlexElasticParams& p, const Material& linear, double cv,
                const PetscScalar* u, const PetscScalar* bva, const PetscInt* li, PetscScalar* fe) {
  PetscScalar vd[12];
  for (int m = 0; m < 12; ++m) vd[m] = cv * u[m] - bva[li[m]];
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i)
      for (int b = 0; b < 4; ++b)
        fe[3 * a + i] += p.rayleigh_mass * massEntry(p.rho, t.V, a, b) * vd[3 * b + i];
  if (p.rayleigh_stiffness == 0.0) return;
  double k0[144] = {};
  linear.addElementTangent(Mat3::Identity(), t.g, 4, p.rayleigh_stiffness * t.V, k0); // upper triangle
  for (int r = 0; r < 12; ++r)
    for (int q = 0; q < 12; ++q) fe[r] += (q >= r ? k0[r * 12 + q] : k0[q * 12 + r]) * vd[q];
}

} // namespace

PetscErrorCode PlexElasticity::setup(DM dm, const PlexElasticParams& p) {
  PetscFE fe;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscFunctionBeginUser;
  dm_ = dm, p_ = p;
  PetscCall(createMaterial(comm, p.law, p.lame, &material_));
  PetscCall(createMaterial(comm, "linear", p.lame, &linear_));
  PetscCall(PetscFECreateLagrange(comm, 3, 3, PETSC_TRUE, 1, PETSC_DETERMINE, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, "displacement"));
  PetscCall(DMSetField(dm, 0, nullptr, (PetscObject)fe));
  PetscCall(DMCreateDS(dm));
  PetscCall(PetscFEDestroy(&fe));
  PetscCall(PlexPrescribedDofs::addBoundaries(dm, p.prescribed));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::attach(SNES snes) {
  Mat J;
  MatNullSpace rbm;
  PetscFunctionBeginUser;
  snes_ = snes;
  PetscCall(held_.setup(dm_, p_.prescribed));
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
      PetscInt off, goff;
      bool held[3];
      PetscCall(PetscSectionGetOffset(cs, vert[a], &off));
      for (int j = 0; j < 3; ++j) x[3 * a + j] = cx[off + j];
      PetscCall(PetscSectionGetOffset(ls, vert[a], &off));
      PetscCall(PetscSectionGetOffset(gs, vert[a], &goff));
      PetscCall(heldComponents(ls, vert[a], held));
      if (goff < 0) goff = -(goff + 1); // owned by another rank
      // the free components are numbered in order in the global vector; the held ones are -1
      PetscInt next = goff;
      for (int i = 0; i < 3; ++i)
        loc_[12 * e + 3 * a + i] = off + i, glob_[12 * e + 3 * a + i] = held[i] ? -1 : next++;
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
  if (held_.partial()) {
    PetscCall(partialRigidBodyModes(sp));
    PetscFunctionReturn(0);
  }
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

// The six rigid-body modes (translations e_c, rotations e_k x x) on the free DOFs, orthonormalised by modified
// Gram-Schmidt as MatNullSpaceCreate requires: for meshes where some vertices have only some components held
// (rollers, symmetry planes), whose free DOFs do not come in 3 x 3 blocks.
PetscErrorCode PlexElasticity::partialRigidBodyModes(MatNullSpace* sp) const {
  PetscSection ls, gs, cs;
  Vec coords, modes[6];
  const PetscScalar* cx;
  PetscInt v0, v1, r0;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm_, &ls));
  PetscCall(DMGetGlobalSection(dm_, &gs));
  PetscCall(DMGetCoordinateSection(dm_, &cs));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMPlexGetDepthStratum(dm_, 0, &v0, &v1));
  for (Vec& m : modes) PetscCall(DMCreateGlobalVector(dm_, &m));
  PetscCall(VecGetOwnershipRange(modes[0], &r0, nullptr));
  PetscScalar* a[6];
  for (int m = 0; m < 6; ++m) PetscCall(VecGetArray(modes[m], &a[m]));
  PetscCall(VecGetArrayRead(coords, &cx));
  for (PetscInt v = v0; v < v1; ++v) {
    PetscInt goff, coff;
    bool held[3];
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    if (goff < 0) continue; // a ghost
    PetscCall(heldComponents(ls, v, held));
    PetscCall(PetscSectionGetOffset(cs, v, &coff));
    const double x = PetscRealPart(cx[coff]), y = PetscRealPart(cx[coff + 1]),
                 z = PetscRealPart(cx[coff + 2]);
    // component c of the six modes at this vertex: three translations, then e_x, e_y, e_z cross (x, y, z)
    const double row[3][6] = {{1, 0, 0, 0, z, -y}, {0, 1, 0, -z, 0, x}, {0, 0, 1, y, -x, 0}};
    PetscInt next = goff - r0;
    for (int c = 0; c < 3; ++c) {
      if (held[c]) continue;
      for (int m = 0; m < 6; ++m) a[m][next] = row[c][m];
      ++next;
    }
  }
  PetscCall(VecRestoreArrayRead(coords, &cx));
  for (int m = 0; m < 6; ++m) PetscCall(VecRestoreArray(modes[m], &a[m]));
  int kept = 0; // the modes the supports leave independent (a held component can make one vanish)
  for (int m = 0; m < 6; ++m) {
    PetscReal before, after;
    PetscCall(VecNorm(modes[m], NORM_2, &before));
    for (int k = 0; k < kept; ++k) {
      PetscScalar d;
      PetscCall(VecDot(modes[m], modes[k], &d));
      PetscCall(VecAXPY(modes[m], -d, modes[k]));
    }
    PetscCall(VecNorm(modes[m], NORM_2, &after));
    if (!(after > 1e-8 * before)) continue;
    PetscCall(VecScale(modes[m], 1.0 / after));
    std::swap(modes[kept++], modes[m]);
  }
  PetscCall(MatNullSpaceCreate(PetscObjectComm((PetscObject)dm_), PETSC_FALSE, kept, modes, sp));
  for (Vec& m : modes) PetscCall(VecDestroy(&m));
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
  if (!held_.partial()) PetscCall(MatSetBlockSize(*J, 3)); // else the free DOFs do not come in threes
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

// Element by element: M (c u - b) + C (c_v u - b_v) + k V P(F(c_k u + e)) g_a - rho g V / 4 into f (local;
// summed into the global residual).
PetscErrorCode PlexElasticity::residual(DM, Vec x, Vec f) {
  const PetscScalar *xa, *ba, *bva = nullptr, *ea = nullptr;
  PetscScalar* fa;
  bool admissible = true;
  PetscFunctionBeginUser;
  PetscCall(held_.insert(x, scale_));
  PetscCall(VecGetArrayRead(x, &xa));
  PetscCall(VecGetArrayRead(b_, &ba));
  const bool damped = bv_ && w_.damping != 0.0;
  if (damped) PetscCall(VecGetArrayRead(bv_, &bva));
  if (e_) PetscCall(VecGetArrayRead(e_, &ea));
  PetscCall(VecGetArray(f, &fa));
  const double c = w_.mass, k = w_.stiffness, rho = p_.rho, ck = w_.eval;
  energy_ = 0.0;
  for (size_t e = 0; e < vol_.size(); ++e) {
    const PetscInt* li = &loc_[12 * e];
    Tet t;
    t.V = vol_[e];
    std::copy(&grad_[12 * e], &grad_[12 * e] + 12, t.g);
    PetscScalar u[12], ue[12], fe[12] = {};
    for (int m = 0; m < 12; ++m) u[m] = xa[li[m]];
    for (int m = 0; m < 12; ++m) ue[m] = ea ? ck * u[m] + ea[li[m]] : u[m];
    if (k != 0.0) {
      const Mat3 F = deformationGradient(ue, t);
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
    if (damped) addDamping(t, p_, *linear_, w_.damping, u, bva, li, fe);
    for (int m = 0; m < 12; ++m) fa[li[m]] += fe[m];
  }
  PetscCall(VecRestoreArray(f, &fa));
  if (e_) PetscCall(VecRestoreArrayRead(e_, &ea));
  if (damped) PetscCall(VecRestoreArrayRead(bv_, &bva));
  PetscCall(VecRestoreArrayRead(b_, &ba));
  PetscCall(VecRestoreArrayRead(x, &xa));
  if (!admissible && snes_) PetscCall(SNESSetFunctionDomainError(snes_)); // an inverted element: Newton fails
  PetscFunctionReturn(0);
}

// Element by element: c M + c_v C + k c_k K_T (the material's closed-form tangent at c_k u + e; upper
// triangle, then mirrored).
PetscErrorCode PlexElasticity::jacobian(DM, Vec x, Mat J) {
  const PetscScalar *xa, *ea = nullptr;
  PetscFunctionBeginUser;
  PetscCall(held_.insert(x, scale_));
  PetscCall(MatZeroEntries(J));
  PetscCall(VecGetArrayRead(x, &xa));
  if (e_) PetscCall(VecGetArrayRead(e_, &ea));
  const double c = w_.mass, k = w_.stiffness, rho = p_.rho, ck = w_.eval;
  const double cd = bv_ ? w_.damping : 0.0, m_all = c + cd * p_.rayleigh_mass;
  for (size_t e = 0; e < vol_.size(); ++e) {
    Tet t;
    t.V = vol_[e];
    std::copy(&grad_[12 * e], &grad_[12 * e] + 12, t.g);
    PetscScalar u[12];
    for (int m = 0; m < 12; ++m) {
      const PetscInt l = loc_[12 * e + m];
      u[m] = ea ? ck * xa[l] + ea[l] : xa[l];
    }
    double ke[144] = {};
    if (k != 0.0) material_->addElementTangent(deformationGradient(u, t), t.g, 4, k * ck * t.V, ke);
    if (cd != 0.0 && p_.rayleigh_stiffness != 0.0)
      linear_->addElementTangent(Mat3::Identity(), t.g, 4, cd * p_.rayleigh_stiffness * t.V, ke);
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b)
        for (int i = 0; i < 3; ++i) ke[(3 * a + i) * 12 + 3 * b + i] += m_all * massEntry(rho, t.V, a, b);
    for (int p = 0; p < 12; ++p)
      for (int q = 0; q < p; ++q) ke[p * 12 + q] = ke[q * 12 + p];
    PetscCall(MatSetValues(J, 12, &glob_[12 * e], 12, &glob_[12 * e], ke, ADD_VALUES));
  }
  if (e_) PetscCall(VecRestoreArrayRead(e_, &ea));
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::kineticEnergy(Vec v, const std::vector<double>* v_held, double* e) const {
  Vec loc;
  const PetscScalar* va;
  double mine = 0.0;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm_, &loc));
  PetscCall(VecZeroEntries(loc)); // the prescribed DOFs: v = 0 unless v_held says otherwise
  PetscCall(DMGlobalToLocal(dm_, v, INSERT_VALUES, loc));
  if (v_held) {
    PetscScalar* w;
    PetscCall(VecGetArray(loc, &w));
    for (size_t i = 0; i < held_.size(); ++i) w[held_.offsets()[i]] = (*v_held)[i];
    PetscCall(VecRestoreArray(loc, &w));
  }
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

PetscErrorCode PlexElasticity::strainEnergyAt(Vec u, const std::vector<double>& u_held, double* e) const {
  Vec loc;
  PetscScalar* ua;
  double mine = 0.0;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm_, &loc));
  PetscCall(VecZeroEntries(loc));
  PetscCall(DMGlobalToLocal(dm_, u, INSERT_VALUES, loc));
  PetscCall(VecGetArray(loc, &ua));
  for (size_t i = 0; i < held_.size(); ++i) ua[held_.offsets()[i]] = u_held[i];
  for (size_t c = 0; c < vol_.size(); ++c) {
    Tet t;
    t.V = vol_[c];
    std::copy(&grad_[12 * c], &grad_[12 * c] + 12, t.g);
    PetscScalar uc[12];
    for (int m = 0; m < 12; ++m) uc[m] = ua[loc_[12 * c + m]];
    double W = 0.0;
    Mat3 P;
    material_->evaluate(deformationGradient(uc, t), &W, &P, nullptr);
    mine += W * t.V;
  }
  PetscCall(VecRestoreArray(loc, &ua));
  PetscCall(DMRestoreLocalVector(dm_, &loc));
  PetscCallMPI(MPI_Allreduce(&mine, e, 1, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::vonMises(Vec u, const std::vector<double>& u_held,
                                        std::vector<double>* vm) const {
  Vec loc;
  PetscScalar* ua;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm_, &loc));
  PetscCall(VecZeroEntries(loc));
  PetscCall(DMGlobalToLocal(dm_, u, INSERT_VALUES, loc));
  PetscCall(VecGetArray(loc, &ua));
  for (size_t i = 0; i < held_.size(); ++i) ua[held_.offsets()[i]] = u_held[i];
  vm->resize(vol_.size());
  for (size_t c = 0; c < vol_.size(); ++c) {
    Tet t;
    t.V = vol_[c];
    std::copy(&grad_[12 * c], &grad_[12 * c] + 12, t.g);
    PetscScalar uc[12];
    for (int m = 0; m < 12; ++m) uc[m] = ua[loc_[12 * c + m]];
    const Mat3 F = deformationGradient(uc, t);
    double W = 0.0;
    Mat3 P;
    material_->evaluate(F, &W, &P, nullptr);
    const Mat3 sigma = material_->isLinear() ? P : Mat3(P * F.transpose() / F.determinant());
    const Mat3 s = sigma - sigma.trace() / 3.0 * Mat3::Identity();
    (*vm)[c] = std::sqrt(1.5 * s.squaredNorm());
  }
  PetscCall(VecRestoreArray(loc, &ua));
  PetscCall(DMRestoreLocalVector(dm_, &loc));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexElasticity::strainEnergy(double* e) const {
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&energy_, e, 1, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  PetscFunctionReturn(0);
}

} // namespace suite::fem
