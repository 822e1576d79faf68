// The Euler run's grid and initial state (see euler_run.hpp): the DMDA (1D line, or 2D/3D with a star stencil
// and the process grid from -da_processors_*), the line communicators, the direction sweep, the initial
// conserved state (euler_initial_state.cpp), the totals of the conservation report (fluid cells) and the PETSc TS.
#include "euler_run.hpp"

#include "euler/schemes.hpp"
#include "euler_state.hpp"
#include "euler_stepper.hpp"

#include <algorithm>

namespace euler_app {

using namespace suite::euler;

namespace {
PetscErrorCode rhsCallback(TS, PetscReal t, Vec U, Vec F, void* ctx) {
  return static_cast<EulerRun*>(ctx)->rhs(t, U, F);
}
} // namespace

EulerRun::~EulerRun() {
  TSDestroy(&ts_);
  VecDestroy(&U_);
  VecDestroy(&U0_);
  VecDestroy(&Ufilter_);
  DMDestroy(&da_);
  for (MPI_Comm& c : line_comm_)
    if (c != MPI_COMM_NULL) MPI_Comm_free(&c);
}

namespace {
// 2D/3D: every rank of the process grid needs at least w cells along each direction. PETSc's DMSetUp checks this
// on each rank alone and stops that rank (MPI_Abort). Where some rank could be that thin (n_d < w x ranks), the
// process grid PETSc would choose (sizes and -da_processors_* as for the run) is probed on a DMDA of stencil width
// 0 first, and a thin rank is one error for all ranks. (1D: checked with the options, naming -nx.)
PetscErrorCode checkProcessGrid(MPI_Comm comm, int dim, const DMBoundaryType bt[3], const PetscInt n[3],
                                PetscInt w) {
  PetscMPIInt size;
  DM probe;
  const PetscInt* ranges[3] = {nullptr, nullptr, nullptr};
  PetscInt procs[3] = {1, 1, 1};
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  bool may_be_thin = false;
  for (int d = 0; d < dim; ++d) may_be_thin = may_be_thin || n[d] < w * size;
  if (!may_be_thin) PetscFunctionReturn(0);
  if (dim == 2)
    PetscCall(DMDACreate2d(comm, bt[0], bt[1], DMDA_STENCIL_STAR, n[0], n[1], PETSC_DECIDE, PETSC_DECIDE, 1,
                           0, nullptr, nullptr, &probe));
  else
    PetscCall(DMDACreate3d(comm, bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, n[0], n[1], n[2], PETSC_DECIDE,
                           PETSC_DECIDE, PETSC_DECIDE, 1, 0, nullptr, nullptr, nullptr, &probe));
  PetscCall(DMSetFromOptions(probe));
  PetscCall(DMSetUp(probe));
  PetscCall(DMDAGetInfo(probe, nullptr, nullptr, nullptr, nullptr, &procs[0], &procs[1], &procs[2], nullptr,
                        nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(probe, &ranges[0], &ranges[1], dim == 3 ? &ranges[2] : nullptr));
  PetscInt thinnest[3] = {n[0], n[1], n[2]};
  for (int d = 0; d < dim; ++d)
    for (PetscInt r = 0; r < procs[d]; ++r) thinnest[d] = std::min(thinnest[d], ranges[d][r]);
  PetscCall(DMDestroy(&probe));
  for (int d = 0; d < dim; ++d) // the same ranges on every rank: the same decision
    PetscCheck(thinnest[d] >= w, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-n%c %" PetscInt_FMT " over %" PetscInt_FMT " ranks along %c (process grid %" PetscInt_FMT
               " x %" PetscInt_FMT " x %" PetscInt_FMT "): a rank would hold %" PetscInt_FMT
               " cells, below the stencil width %" PetscInt_FMT "; use more cells or fewer ranks (or set "
               "-da_processors_%c)",
               'x' + d, n[d], procs[d], 'x' + d, procs[0], procs[1], procs[2], thinnest[d], w, 'x' + d);
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode EulerRun::setupGrid() {
  MPI_Comm comm = ctx_.comm();
  DMBoundaryType bt[3];
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) {
    periodic_[d] = d >= dim() || problem_.bc[d][0] == BcN::Periodic;
    PetscCheck(d >= dim() || (problem_.bc[d][0] == BcN::Periodic) == (problem_.bc[d][1] == BcN::Periodic),
               comm, PETSC_ERR_ARG_WRONG, "Periodic boundaries must be set on both faces of direction %d", d);
    bt[d] = periodic_[d] ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_GHOSTED;
    dx_[d] = d < dim() ? (problem_.hi[d] - problem_.lo[d]) / opt_.n[d] : 1.0;
  }
  const PetscInt w = kLineGhost, *n = opt_.n;
  if (dim() > 1) PetscCall(checkProcessGrid(comm, dim(), bt, n, w));
  if (dim() == 1)
    PetscCall(DMDACreate1d(comm, bt[0], n[0], nv(), w, nullptr, &da_));
  else if (dim() == 2)
    PetscCall(DMDACreate2d(comm, bt[0], bt[1], DMDA_STENCIL_STAR, n[0], n[1], PETSC_DECIDE, PETSC_DECIDE,
                           nv(), w, nullptr, nullptr, &da_));
  else
    PetscCall(DMDACreate3d(comm, bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, n[0], n[1], n[2], PETSC_DECIDE,
                           PETSC_DECIDE, PETSC_DECIDE, nv(), w, nullptr, nullptr, nullptr, &da_));
  if (dim() > 1) PetscCall(DMSetFromOptions(da_)); // -da_processors_x ...
  PetscCall(DMSetUp(da_));
  const char* fields[4] = {"rho", "rho_u", "rho_v", "rho_w"};
  for (int c = 0; c < nv(); ++c) PetscCall(DMDASetFieldName(da_, c, c == nv() - 1 ? "E" : fields[c]));
  PetscCall(DMDAGetCorners(da_, &s_[0], &s_[1], &s_[2], &m_[0], &m_[1], &m_[2]));
  PetscCall(DMDAGetGhostCorners(da_, &gs_[0], &gs_[1], &gs_[2], &gm_[0], &gm_[1], &gm_[2]));
  PetscFunctionReturn(0);
}

// Line communicators: the ranks with the same process coordinates in the other directions, ordered along d.
// In 1D the one line spans every rank: the run's communicator.
PetscErrorCode EulerRun::setupLineComms() {
  PetscInt procs[3] = {1, 1, 1};
  const PetscInt* ranges[3] = {nullptr, nullptr, nullptr};
  PetscFunctionBeginUser;
  if (dim() == 1) PetscFunctionReturn(0);
  PetscCall(DMDAGetInfo(da_, nullptr, nullptr, nullptr, nullptr, &procs[0], &procs[1], &procs[2], nullptr,
                        nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(da_, &ranges[0], &ranges[1], dim() == 3 ? &ranges[2] : nullptr));
  int coord[3] = {0, 0, 0};
  for (int d = 0; d < dim(); ++d) {
    PetscInt start = 0;
    for (PetscInt p = 0; p < procs[d]; ++p) {
      if (start == s_[d]) coord[d] = (int)p;
      start += ranges[d][p];
    }
  }
  for (int d = 0; d < dim(); ++d) {
    const int a = (d + 1) % 3, b = (d + 2) % 3;
    const int color = coord[a] + (int)procs[a] * coord[b];
    PetscCallMPI(MPI_Comm_split(ctx_.comm(), color, coord[d], &line_comm_[d]));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::setupSweep() {
  PetscFunctionBeginUser;
  scheme_ = findScheme(opt_.scheme); // a registered name (checked when read)
  LineOptions lo;
  lo.gamma = problem_.gamma;
  lo.characteristic = opt_.characteristic;
  lo.local_lf = opt_.local_lf;
  lo.rf_char = opt_.upwinding == "rf-char";
  lo.shock_threshold = opt_.shock_threshold;
  lo.shock_ppw = opt_.shock_ppw;
  lo.positivity = opt_.positivity;
  lo.gather_lines = opt_.line_solve == "gather";
  lo.transpose_lines = opt_.line_solve == "transpose";
  lo.batch_bytes = (size_t)opt_.line_batch_mb << 20;
  lo.segmented = problem_.hasSolid();
  if (dim() == 1) sweep3_ = std::make_unique<DirectionSweep<3>>(scheme_, lo);
  if (dim() == 2) sweep4_ = std::make_unique<DirectionSweep<4>>(scheme_, lo);
  if (dim() == 3) sweep5_ = std::make_unique<DirectionSweep<5>>(scheme_, lo);
  const char* stages[3] = {"Euler lines x", "Euler lines y", "Euler lines z"};
  // One log stage per direction of the grid, registered once per process (a target run sets up many runs).
  if (dim() > 1)
    for (int d = 0; d < dim(); ++d) {
      PetscCall(PetscLogStageGetId(stages[d], &stage_lines_[d]));
      if (stage_lines_[d] < 0) PetscCall(PetscLogStageRegister(stages[d], &stage_lines_[d]));
    }
  PetscFunctionReturn(0);
}

void EulerRun::cellCentre(PetscInt i, PetscInt j, PetscInt k, double x[3]) const {
  const PetscInt idx[3] = {i, j, k};
  for (int d = 0; d < 3; ++d) x[d] = d < dim() ? problem_.lo[d] + (idx[d] + 0.5) * dx_[d] : 0.0;
}

void EulerRun::blockDims(suite::Dims* dims, suite::Dims* start, suite::Dims* count) const {
  dims->clear(), start->clear(), count->clear();
  for (int d = dim() - 1; d >= 0; --d) { // slowest first: (z,) (y,) x
    dims->push_back((unsigned long long)opt_.n[d]);
    start->push_back((unsigned long long)s_[d]);
    count->push_back((unsigned long long)m_[d]);
  }
}

PetscErrorCode EulerRun::totals(Vec U, std::vector<double>* sum) const {
  const PetscScalar* a;
  PetscFunctionBeginUser;
  sum->assign(nv(), 0.0);
  const double vol = dx_[0] * dx_[1] * (dim() == 3 ? dx_[2] : 1.0); // 1D: dx_[1] = 1, so vol = dx
  PetscCall(VecGetArrayRead(U, &a));
  for (PetscInt c = 0; c < localCells(); ++c)
    if (!solidCell(c))
      for (int v = 0; v < nv(); ++v) (*sum)[v] += a[c * nv() + v] * vol;
  PetscCall(VecRestoreArrayRead(U, &a));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sum->data(), nv(), MPI_DOUBLE, MPI_SUM, ctx_.comm()));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::setup() {
  double amax[3];
  PetscFunctionBeginUser;
  PetscCall(setupGrid());
  PetscCall(setupLineComms());
  PetscCall(setupSweep());
  PetscCall(setupSolid());
  PetscCall(setInitialState());
  PetscCall(maxWaveSpeeds(U_, 0.0, amax));
  const StepperSettings s{opt_.time, opt_.t_final, opt_.dt > 0 ? opt_.dt : cflTimeStep(amax)};
  PetscCall(createStepper(ctx_.comm(), da_, U_, s, rhsCallback, this, &ts_));
  wall_setup_ = MPI_Wtime() - t_options_; // the slowest rank's (the output's setup_seconds)
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &wall_setup_, 1, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  PetscFunctionReturn(0);
}

} // namespace euler_app
