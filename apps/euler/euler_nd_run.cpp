// 2D/3D Euler run: options, DMDA and line communicators, boundary ghosts, TS callbacks (see euler_nd_run.hpp).
#include "euler_nd_run.hpp"

#include "core/error_handler.hpp"
#include "core/field_check.hpp"
#include "core/log.hpp"
#include "core/resource_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>

namespace euler_app {

using namespace suite::euler;

namespace {
// Conserved state of a primitive one (global frame: rho, m_x, m_y [, m_z], E).
void toConsND(const PrimN& w, int dim, double gamma, double* q) {
  double v2 = 0.0;
  q[0] = w.rho;
  for (int d = 0; d < dim; ++d) {
    q[1 + d] = w.rho * w.u[d];
    v2 += w.u[d] * w.u[d];
  }
  q[dim + 1] = w.p / (gamma - 1.0) + 0.5 * w.rho * v2;
}
PrimN toPrimND(const double* q, int dim, double gamma) {
  PrimN w{q[0], {0, 0, 0}, 0};
  double ke = 0.0;
  for (int d = 0; d < dim; ++d) {
    w.u[d] = q[1 + d] / q[0];
    ke += 0.5 * q[1 + d] * w.u[d];
  }
  w.p = (gamma - 1.0) * (q[dim + 1] - ke);
  return w;
}
} // namespace

// Component c of the line frame of direction d -> component of the global frame.
static inline int frameComponent(int dim, int d, int c) {
  if (c == 0 || c == dim + 1) return c;
  if (c == 1) return 1 + d;
  int t = c - 2, other = -1; // t-th direction other than d, in increasing order
  for (int e = 0; e < dim; ++e)
    if (e != d && t-- == 0) other = e;
  return 1 + other;
}

EulerRunND::~EulerRunND() {
  TSDestroy(&ts_);
  VecDestroy(&U_);
  DMDestroy(&da_);
  for (MPI_Comm& c : line_comm_)
    if (c != MPI_COMM_NULL) MPI_Comm_free(&c);
}

PetscErrorCode EulerRunND::readOptions() {
  MPI_Comm comm = ctx_.comm();
  char buf[PETSC_MAX_PATH_LEN];
  PetscBool set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Euler 2D/3D options", "");
  PetscCall(PetscStrncpy(buf, opt_.problem.c_str(), sizeof(buf)));
  PetscCall(PetscOptionsString("-problem", "Problem", "", buf, buf, sizeof(buf), nullptr));
  opt_.problem = buf;
  PetscCall(PetscStrncpy(buf, opt_.scheme.c_str(), sizeof(buf)));
  PetscCall(PetscOptionsString("-scheme", "Spatial scheme: enopade6, crweno5, weno5, muscl2", "", buf, buf,
                               sizeof(buf), nullptr));
  opt_.scheme = buf;
  PetscCall(PetscStrncpy(buf, opt_.time.c_str(), sizeof(buf)));
  PetscCall(PetscOptionsString("-time", "Time integrator: ssprk3, rk4, beuler, cn, bdf2", "", buf, buf,
                               sizeof(buf), nullptr));
  opt_.time = buf;
  PetscCall(PetscStrncpy(buf, opt_.axis.c_str(), sizeof(buf)));
  PetscCall(PetscOptionsString("-axis", "Axis of a 1D problem on the 2D/3D grid: x, y, z", "", buf, buf,
                               sizeof(buf), nullptr));
  opt_.axis = buf;
  PetscOptionsEnd();
  PetscCheck(opt_.axis == "x" || opt_.axis == "y" || (opt_.axis == "z" && opt_.dim == 3), comm,
             PETSC_ERR_ARG_OUTOFRANGE, "Invalid -axis %s: x, y%s", opt_.axis.c_str(),
             opt_.dim == 3 ? " or z" : "");
  PetscCall(createProblemND(comm, opt_.problem, opt_.dim, opt_.axis[0] - 'x', &problem_));
  scheme_ = findScheme(opt_.scheme);
  PetscCheck(scheme_, comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
             "Unknown scheme '%s' (option -scheme); known schemes: %s", opt_.scheme.c_str(),
             schemeNames().c_str());
  PetscCheck(isKnownTimeScheme(opt_.time), comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
             "Unknown time integrator '%s' (option -time); known: %s", opt_.time.c_str(), kTimeSchemes);
  opt_.implicit = isImplicit(opt_.time);
  if (opt_.implicit) opt_.positivity = PETSC_FALSE, opt_.local_lf = PETSC_FALSE;
  for (int d = 0; d < 3; ++d) opt_.n[d] = d < opt_.dim ? problem_.default_n[d] : 1;
  opt_.t_final = problem_.t_final;
  PetscOptionsBegin(comm, "", "Euler 2D/3D discretisation and output options", "");
  PetscCall(PetscOptionsInt("-nx", "Cells along x", "", opt_.n[0], &opt_.n[0], nullptr));
  PetscCall(PetscOptionsInt("-ny", "Cells along y", "", opt_.n[1], &opt_.n[1], nullptr));
  if (opt_.dim == 3) PetscCall(PetscOptionsInt("-nz", "Cells along z", "", opt_.n[2], &opt_.n[2], nullptr));
  PetscCall(PetscOptionsReal("-t_final", "End time", "", opt_.t_final, &opt_.t_final, nullptr));
  PetscCall(PetscOptionsReal("-cfl", "CFL number: dt = cfl / sum_d(max(|u_d| + c) / dx_d)", "", opt_.cfl,
                             &opt_.cfl, nullptr));
  PetscCall(PetscOptionsReal("-dt", "Fixed time step (0: CFL-controlled)", "", opt_.dt, &opt_.dt, nullptr));
  PetscCall(PetscOptionsInt("-max_steps", "Maximum number of steps (-1: no limit)", "", opt_.max_steps,
                            &opt_.max_steps, nullptr));
  PetscCall(PetscOptionsBool("-characteristic", "Characteristic-wise reconstruction (false: component-wise)",
                             "", opt_.characteristic, &opt_.characteristic, nullptr));
  PetscCall(PetscOptionsBool("-local_lf", "Local Lax-Friedrichs splitting (false: global)", "", opt_.local_lf,
                             &opt_.local_lf, nullptr));
  PetscCall(PetscOptionsBool("-positivity", "Hu-Adams-Shu positivity-preserving flux limiter", "",
                             opt_.positivity, &opt_.positivity, nullptr));
  PetscCall(PetscOptionsReal("-shock_threshold", "ENO-Pade switch threshold (0: CRWENO rows everywhere)", "",
                             opt_.shock_threshold, &opt_.shock_threshold, nullptr));
  PetscCall(
      PetscOptionsInt("-line_batch_mb",
                      "Memory (MiB) of one batch of block lines in the compact solves (more batches: more "
                      "messages, less memory)",
                      "", opt_.line_batch_mb, &opt_.line_batch_mb, nullptr));
  char line_solve[32] = "transpose";
  PetscCall(
      PetscOptionsString("-line_solve",
                         "Compact solves of lines split over ranks: transpose (whole lines moved to one "
                         "rank each, two all-to-all exchanges) or substructured (solved in place, partition "
                         "method); lines fewer than ranks are always substructured",
                         "", line_solve, line_solve, sizeof(line_solve), nullptr));
  const char* const line_solves[] = {"transpose", "substructured"};
  PetscInt which = 0;
  PetscCall(suite::checkChoice(comm, "-line_solve", line_solve, line_solves, 2, &which));
  opt_.transpose_lines = which == 0;
  buf[0] = 0;
  PetscCall(PetscOptionsString("-output", "HDF5 output file (XDMF sidecar beside it)", "", buf, buf,
                               sizeof(buf), &set));
  if (set) opt_.output = buf;
  PetscCall(PetscOptionsInt("-snapshot_every", "Write a snapshot every N steps (0: none)", "",
                            opt_.snapshot_every, &opt_.snapshot_every, nullptr));
  PetscCall(PetscOptionsBool("-error", "Density errors (L1, L2, Linf) against the exact solution", "",
                             opt_.error, &opt_.error, nullptr));
  PetscCall(PetscOptionsBool("-spectrum",
                             "Kinetic-energy spectrum E(k) of the final state and every snapshot (FFTW-MPI)",
                             "", opt_.spectrum, &opt_.spectrum, nullptr));
  PetscOptionsEnd();
  PetscCall(ckpt_.setFromOptions(comm, "euler"));
  if (!opt_.output.empty()) PetscCall(suite::checkOutputWritable(comm, opt_.output, "-output"));

  PetscCall(suite::checkIntOptionRange(comm, "-nx", 1));
  PetscCall(suite::checkIntOptionRange(comm, "-ny", 1));
  if (opt_.dim == 3) PetscCall(suite::checkIntOptionRange(comm, "-nz", 1));
  PetscCall(suite::checkIntOptionRange(comm, "-max_steps", -1));
  PetscCall(suite::checkIntOptionRange(comm, "-snapshot_every", 0));
  const char* names[3] = {"-nx", "-ny", "-nz"};
  double cells = 1.0;
  for (int d = 0; d < opt_.dim; ++d) {
    const bool periodic = problem_.bc[d][0] == BcN::Periodic;
    const PetscInt need = periodic ? kLineGhost : 2 * kLineGhost;
    PetscCheck(opt_.n[d] >= need, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "Invalid %s %" PetscInt_FMT ": below the %s stencil width %" PetscInt_FMT " of the schemes",
               names[d], opt_.n[d], periodic ? "periodic" : "bounded", need);
    cells *= (double)opt_.n[d];
  }
  PetscCheck(cells * nv() <= (double)PETSC_MAX_INT, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Grid too large: %.3g cells x %d unknowns exceed the 32-bit PetscInt", cells, nv());
  char what[96];
  std::snprintf(what, sizeof what, "a %.3g-cell grid", cells);
  // Measured layout: ~7 state vectors (TS stages, local ghosted copy) + line buffers + one direction's scalar
  // batch and transposed lines ~ 130 NV bytes per cell, plus the block-line batch (LineOptions::batch_bytes,
  // 256 MiB). Measured peak: 1.14 GB per rank for the 3D explosion at 128^3 on 2 ranks (estimate 1.05 GB).
  PetscCall(suite::checkMemoryEstimate(
      comm, 130.0 * nv() * cells / ctx_.size() + 5e7 + 1.2 * (opt_.line_batch_mb << 20), what));
  PetscCall(suite::checkIntOptionRange(comm, "-line_batch_mb", 1));
  PetscCheck(opt_.cfl > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid -cfl %g: must be > 0", opt_.cfl);
  PetscCheck(opt_.dt >= 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid -dt %g: must be >= 0", opt_.dt);
  PetscCheck(opt_.t_final > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid -t_final %g: must be > 0",
             opt_.t_final);
  PetscCheck(!opt_.error || problem_.exact, comm, PETSC_ERR_ARG_WRONG,
             "-error: problem '%s' has no exact solution", opt_.problem.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::setupGrid() {
  MPI_Comm comm = ctx_.comm();
  PetscFunctionBeginUser;
  DMBoundaryType bt[3];
  for (int d = 0; d < 3; ++d) {
    periodic_[d] = d >= opt_.dim || problem_.bc[d][0] == BcN::Periodic;
    PetscCheck(d >= opt_.dim || (problem_.bc[d][0] == BcN::Periodic) == (problem_.bc[d][1] == BcN::Periodic),
               comm, PETSC_ERR_ARG_WRONG, "Periodic boundaries must be set on both faces of direction %d", d);
    bt[d] = periodic_[d] ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_GHOSTED;
    dx_[d] = d < opt_.dim ? (problem_.hi[d] - problem_.lo[d]) / opt_.n[d] : 1.0;
  }
  const PetscInt w = kLineGhost;
  if (opt_.dim == 2)
    PetscCall(DMDACreate2d(comm, bt[0], bt[1], DMDA_STENCIL_STAR, opt_.n[0], opt_.n[1], PETSC_DECIDE,
                           PETSC_DECIDE, nv(), w, nullptr, nullptr, &da_));
  else
    PetscCall(DMDACreate3d(comm, bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, opt_.n[0], opt_.n[1], opt_.n[2],
                           PETSC_DECIDE, PETSC_DECIDE, PETSC_DECIDE, nv(), w, nullptr, nullptr, nullptr,
                           &da_));
  PetscCall(DMSetFromOptions(da_)); // -da_processors_x ...
  PetscCall(DMSetUp(da_));
  const char* fields[5] = {"rho", "rho_u", "rho_v", "rho_w", "E"};
  for (int c = 0; c < nv(); ++c) PetscCall(DMDASetFieldName(da_, c, c == nv() - 1 ? "E" : fields[c]));
  PetscCall(DMDAGetCorners(da_, &s_[0], &s_[1], &s_[2], &m_[0], &m_[1], &m_[2]));
  PetscCall(DMDAGetGhostCorners(da_, &gs_[0], &gs_[1], &gs_[2], &gm_[0], &gm_[1], &gm_[2]));
  for (int d = 0; d < opt_.dim; ++d)
    PetscCheck(m_[d] >= w, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
               "Each rank needs at least %d cells per direction (has %" PetscInt_FMT " along %c)", (int)w,
               m_[d], 'x' + d);
  PetscFunctionReturn(0);
}

// Line communicators: the ranks with the same process coordinates in the other directions, ordered along d.
PetscErrorCode EulerRunND::setupLineComms() {
  PetscInt procs[3] = {1, 1, 1};
  const PetscInt* ranges[3] = {nullptr, nullptr, nullptr};
  PetscFunctionBeginUser;
  PetscCall(DMDAGetInfo(da_, nullptr, nullptr, nullptr, nullptr, &procs[0], &procs[1], &procs[2], nullptr,
                        nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(da_, &ranges[0], &ranges[1], opt_.dim == 3 ? &ranges[2] : nullptr));
  int coord[3] = {0, 0, 0};
  for (int d = 0; d < opt_.dim; ++d) {
    PetscInt start = 0;
    for (PetscInt p = 0; p < procs[d]; ++p) {
      if (start == s_[d]) coord[d] = (int)p;
      start += ranges[d][p];
    }
  }
  for (int d = 0; d < opt_.dim; ++d) {
    const int a = (d + 1) % 3, b = (d + 2) % 3;
    const int color = coord[a] + (int)procs[a] * coord[b];
    PetscCallMPI(MPI_Comm_split(ctx_.comm(), color, coord[d], &line_comm_[d]));
  }
  PetscFunctionReturn(0);
}

void EulerRunND::cellCentre(PetscInt i, PetscInt j, PetscInt k, double x[3]) const {
  const PetscInt idx[3] = {i, j, k};
  for (int d = 0; d < 3; ++d) x[d] = d < opt_.dim ? problem_.lo[d] + (idx[d] + 0.5) * dx_[d] : 0.0;
}

PetscErrorCode EulerRunND::setup() {
  PetscFunctionBeginUser;
  PetscCall(setupGrid());
  PetscCall(setupLineComms());
  LineOptions lo;
  lo.gamma = problem_.gamma;
  lo.characteristic = opt_.characteristic;
  lo.local_lf = opt_.local_lf;
  lo.shock_threshold = opt_.shock_threshold;
  lo.positivity = opt_.positivity;
  lo.batch_bytes = (size_t)opt_.line_batch_mb << 20;
  lo.transpose_lines = opt_.transpose_lines;
  if (opt_.dim == 2)
    sweep4_ = std::make_unique<DirectionSweep<4>>(scheme_, lo);
  else
    sweep5_ = std::make_unique<DirectionSweep<5>>(scheme_, lo);
  PetscCall(DMCreateGlobalVector(da_, &U_));
  PetscScalar* u;
  PetscCall(VecGetArray(U_, &u));
  size_t idx = 0;
  for (PetscInt k = s_[2]; k < s_[2] + m_[2]; ++k)
    for (PetscInt j = s_[1]; j < s_[1] + m_[1]; ++j)
      for (PetscInt i = s_[0]; i < s_[0] + m_[0]; ++i, idx += nv()) {
        double x[3];
        cellCentre(i, j, k, x);
        toConsND(problem_.initial(x), opt_.dim, problem_.gamma, u + idx);
      }
  PetscCall(VecRestoreArray(U_, &u));
  PetscCall(totals(U_, &totals0_));
  PetscCall(PetscLogStageRegister("Euler lines x", &stage_lines_[0]));
  PetscCall(PetscLogStageRegister("Euler lines y", &stage_lines_[1]));
  if (opt_.dim == 3) PetscCall(PetscLogStageRegister("Euler lines z", &stage_lines_[2]));
  PetscCall(setupTimeStepper());
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::setupTimeStepper() {
  PetscFunctionBeginUser;
  double amax[3];
  PetscCall(maxWaveSpeeds(U_, amax));
  StepperSettings s{opt_.time, opt_.t_final, opt_.max_steps, opt_.dt > 0 ? opt_.dt : cflTimeStep(amax)};
  PetscCall(createStepper(ctx_.comm(), da_, s, rhsCallback<EulerRunND>, this, preStepCallback<EulerRunND>,
                          postStepCallback<EulerRunND>, &ts_));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::maxWaveSpeeds(Vec U, double amax[3]) const {
  const PetscScalar* u;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  double a[3] = {0, 0, 0};
  const PetscInt ncell = m_[0] * m_[1] * m_[2];
  const int dim = opt_.dim;
  for (PetscInt c = 0; c < ncell; ++c) {
    const PrimN w = toPrimND(u + c * nv(), dim, problem_.gamma);
    const double cs = std::sqrt(std::abs(problem_.gamma * w.p / w.rho));
    for (int d = 0; d < dim; ++d) {
      const double s = std::abs(w.u[d]) + cs;
      a[d] = (std::isnan(s) || s > a[d]) ? (std::isnan(a[d]) ? a[d] : s) : a[d];
    }
  }
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, a, 3, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  for (int d = 0; d < 3; ++d) amax[d] = a[d];
  PetscFunctionReturn(0);
}

double EulerRunND::cflTimeStep(const double amax[3]) const {
  double s = 0.0;
  for (int d = 0; d < opt_.dim; ++d) s += amax[d] / dx_[d];
  return opt_.cfl / s;
}

// Fills q with the lines of direction d: cells s_d-3 .. s_d+m_d+2 of every (j, k) of this rank, in the frame of
// d, ghosts outside a non-periodic domain from the boundary conditions at time t.
template <int NV>
void EulerRunND::gatherLines(int d, double t, const double* ul, std::vector<std::array<double, NV>>* q) {
  const int dim = opt_.dim, g = kLineGhost;
  const int a = d == 0 ? 1 : 0,
            b = (dim == 3) ? (d == 2 ? 1 : 2) : 2; // the other directions (b = 2 in 2D: size 1)
  const PetscInt ncell = m_[d] + 2 * g, n = opt_.n[d];
  const PetscInt nlines = m_[a] * m_[b];
  q->resize((size_t)nlines * ncell);
  int comp[NV];
  for (int c = 0; c < NV; ++c) comp[c] = frameComponent(dim, d, c);
  auto local = [&](const PetscInt idx[3]) {
    const PetscInt off = ((idx[2] - gs_[2]) * gm_[1] + (idx[1] - gs_[1])) * gm_[0] + (idx[0] - gs_[0]);
    return ul + (size_t)off * NV;
  };
  auto rotate = [&](const double* src, std::array<double, NV>* dst) {
    for (int c = 0; c < NV; ++c) (*dst)[c] = src[comp[c]];
  };
  PetscInt line = 0;
  for (PetscInt jb = s_[b]; jb < s_[b] + m_[b]; ++jb)
    for (PetscInt ja = s_[a]; ja < s_[a] + m_[a]; ++ja, ++line) {
      std::array<double, NV>* ql = q->data() + (size_t)line * ncell;
      PetscInt idx[3];
      idx[a] = ja, idx[b] = jb;
      for (PetscInt m = 0; m < ncell; ++m) {
        const PetscInt i = s_[d] - g + m;
        if (periodic_[d] || (i >= 0 && i < n)) {
          idx[d] = i;
          rotate(local(idx), &ql[m]);
        }
      }
      if (periodic_[d]) continue;
      for (int side = 0; side < 2; ++side) {
        if ((side == 0 && s_[d] != 0) || (side == 1 && s_[d] + m_[d] != n)) continue;
        for (PetscInt gi = 0; gi < g; ++gi) {
          const PetscInt i = side == 0 ? -1 - gi : n + gi;     // ghost cell
          const PetscInt mirror = side == 0 ? gi : n - 1 - gi; // interior cell mirrored across the face
          const PetscInt edge = side == 0 ? 0 : n - 1;         // interior cell next to the face
          auto at = [&](PetscInt c) -> std::array<double, NV>& { return ql[c - (s_[d] - g)]; };
          std::array<double, NV>& ghost = at(i);
          switch (problem_.bc[d][side]) {
          case BcN::Outflow:
            ghost = at(edge);
            break;
          case BcN::Reflecting:
            ghost = at(mirror);
            ghost[1] = -ghost[1];
            break;
          case BcN::Custom: {
            double x[3], qm[5], qe[5], qg[5];
            idx[d] = i;
            cellCentre(idx[0], idx[1], idx[2], x);
            for (int c = 0; c < NV; ++c) qm[comp[c]] = at(mirror)[c], qe[comp[c]] = at(edge)[c];
            const PrimN w = problem_.ghost(d, side, x, t, toPrimND(qm, dim, problem_.gamma),
                                           toPrimND(qe, dim, problem_.gamma));
            toConsND(w, dim, problem_.gamma, qg);
            rotate(qg, &ghost);
            break;
          }
          case BcN::Periodic:
            break;
          }
        }
      }
    }
}

template <int NV> PetscErrorCode EulerRunND::rhsImpl(double t, const double* ul, double* f) {
  using V = std::array<double, NV>;
  static_assert(NV == 4 || NV == 5);
  PetscFunctionBeginUser;
  const int dim = opt_.dim;
  DirectionSweep<NV>& sweep = *[this]() {
    if constexpr (NV == 4)
      return sweep4_.get();
    else
      return sweep5_.get();
  }();
  // Max |u_d| + c over the cells this rank owns, per direction (one Allreduce).
  double amax[3] = {0, 0, 0};
  {
    for (PetscInt k = s_[2]; k < s_[2] + m_[2]; ++k)
      for (PetscInt j = s_[1]; j < s_[1] + m_[1]; ++j)
        for (PetscInt i = s_[0]; i < s_[0] + m_[0]; ++i) {
          const PetscInt off = ((k - gs_[2]) * gm_[1] + (j - gs_[1])) * gm_[0] + (i - gs_[0]);
          const PrimN w = toPrimND(ul + (size_t)off * NV, dim, problem_.gamma);
          const double cs = std::sqrt(std::abs(problem_.gamma * w.p / w.rho));
          for (int d = 0; d < dim; ++d) amax[d] = std::max(amax[d], std::abs(w.u[d]) + cs);
        }
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, amax, 3, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  }
  const size_t ncells = (size_t)m_[0] * m_[1] * m_[2];
  std::fill(f, f + ncells * NV, 0.0);
  std::vector<V> q;
  std::vector<V> h;
  for (int d = 0; d < dim; ++d) {
    PetscCall(PetscLogStagePush(stage_lines_[d]));
    gatherLines<NV>(d, t, ul, &q);
    const int a = d == 0 ? 1 : 0, b = (dim == 3) ? (d == 2 ? 1 : 2) : 2;
    const int nlines = (int)(m_[a] * m_[b]), xm = (int)m_[d];
    h.resize((size_t)nlines * (xm + 1));
    const double lambda = opt_.positivity ? dim * dt_limiter_ / dx_[d] : 0.0;
    try {
      sweep.faceFluxes(line_comm_[d], q.data(), nlines, opt_.n[d], s_[d], xm, periodic_[d],
                       amax[d] * (1.0 + 1e-12), lambda, h.data());
    } catch (const std::exception& e) {
      // Reduced over the whole grid by rhs(). The other directions still run: their line communicators hold
      // ranks that did not fail here and wait for this rank in their collectives.
      if (rhs_failure_.empty()) rhs_failure_ = e.what();
      PetscCall(PetscLogStagePop());
      continue;
    }
    int comp[NV];
    for (int c = 0; c < NV; ++c) comp[c] = frameComponent(dim, d, c);
    const double inv = 1.0 / dx_[d];
    const size_t stride[3] = {1, (size_t)m_[0], (size_t)m_[0] * m_[1]};
    size_t line = 0;
    for (PetscInt jb = 0; jb < m_[b]; ++jb)
      for (PetscInt ja = 0; ja < m_[a]; ++ja, ++line) {
        const V* hl = h.data() + line * (xm + 1);
        const size_t base = ja * stride[a] + jb * (b < 3 ? stride[b] : 0);
        for (int i = 0; i < xm; ++i) {
          double* fc = f + (base + i * stride[d]) * NV;
          for (int c = 0; c < NV; ++c) fc[comp[c]] -= (hl[i + 1][c] - hl[i][c]) * inv;
        }
      }
    PetscCall(PetscLogStagePop());
  }
  const double* grav = problem_.gravity;
  if (grav[0] != 0.0 || grav[1] != 0.0 || grav[2] != 0.0) {
    size_t c = 0;
    for (PetscInt k = s_[2]; k < s_[2] + m_[2]; ++k)
      for (PetscInt j = s_[1]; j < s_[1] + m_[1]; ++j)
        for (PetscInt i = s_[0]; i < s_[0] + m_[0]; ++i, ++c) {
          const PetscInt off = ((k - gs_[2]) * gm_[1] + (j - gs_[1])) * gm_[0] + (i - gs_[0]);
          const double* qc = ul + (size_t)off * NV;
          for (int d = 0; d < dim; ++d) {
            f[c * NV + 1 + d] += qc[0] * grav[d];
            f[c * NV + NV - 1] += qc[1 + d] * grav[d];
          }
        }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::rhs(double t, Vec U, Vec F) {
  Vec Ul;
  const PetscScalar* ul;
  PetscScalar* f;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(da_, &Ul));
  PetscCall(DMGlobalToLocal(da_, U, INSERT_VALUES, Ul));
  PetscCall(VecGetArrayRead(Ul, &ul));
  PetscCall(VecGetArray(F, &f));
  rhs_failure_.clear();
  PetscCall(opt_.dim == 2 ? rhsImpl<4>(t, ul, f) : rhsImpl<5>(t, ul, f));
  PetscCall(VecRestoreArray(F, &f));
  PetscCall(VecRestoreArrayRead(Ul, &ul));
  PetscCall(DMRestoreLocalVector(da_, &Ul));
  // A line-solve failure is the same on the ranks of a line but not of the grid: agree before returning.
  PetscCall(suite::agreeOnFailure(ctx_.comm(), &rhs_failure_));
  PetscCheck(rhs_failure_.empty(), ctx_.comm(), PETSC_ERR_NOT_CONVERGED,
             "Euler right-hand side failed at step %" PetscInt_FMT ", t = %g (a compact line solve: %s)",
             steps_, t, rhs_failure_.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::preStep() {
  PetscReal t;
  Vec U;
  PetscFunctionBeginUser;
  PetscCall(TSGetTime(ts_, &t));
  PetscCall(TSGetSolution(ts_, &U));
  double dt = opt_.dt;
  if (dt <= 0.0) {
    double amax[3];
    PetscCall(maxWaveSpeeds(U, amax));
    dt = cflTimeStep(amax);
    PetscCheck(std::isfinite(dt) && dt > 0.0, ctx_.comm(), PETSC_ERR_FP,
               "Wave speed is not finite at step %" PetscInt_FMT ", time %g", steps_, t);
  }
  if (t + dt > opt_.t_final) dt = opt_.t_final - t;
  dt_limiter_ = dt;
  PetscCall(TSSetTimeStep(ts_, dt));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::checkState(Vec U, PetscInt step, double time) const {
  const PetscScalar* a;
  PetscFunctionBeginUser;
  const PetscInt ncell = m_[0] * m_[1] * m_[2];
  std::vector<double> rho(ncell), p(ncell);
  PetscCall(VecGetArrayRead(U, &a));
  for (PetscInt c = 0; c < ncell; ++c) {
    const PrimN w = toPrimND(a + c * nv(), opt_.dim, problem_.gamma);
    rho[c] = w.rho, p[c] = w.p;
  }
  PetscCall(VecRestoreArrayRead(U, &a));
  // Offsets are this rank's cell numbers in its block (x fastest): the message names rank-local cells.
  suite::FieldLocation where{"rho", step, time, 0, nullptr};
  PetscCall(suite::checkAbove(ctx_.comm(), rho.data(), ncell, 1, 0, 0.0, where));
  where.field = "p";
  PetscCall(suite::checkAbove(ctx_.comm(), p.data(), ncell, 1, 0, 0.0, where));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::postStep() {
  PetscReal t;
  Vec U;
  PetscFunctionBeginUser;
  PetscCall(TSGetTime(ts_, &t));
  PetscCall(TSGetStepNumber(ts_, &steps_));
  PetscCall(TSGetSolution(ts_, &U));
  time_ = t;
  PetscCall(checkState(U, steps_, t));
  if (opt_.snapshot_every > 0 && steps_ % opt_.snapshot_every == 0 && !opt_.output.empty())
    PetscCall(writeSnapshot(steps_, t));
  PetscCall(endOfStep(ctx_, ts_, ckpt_, progress_.get(), steps_, t, [this] { return checkpointNow(); }));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::totals(Vec U, std::vector<double>* sum) const {
  const PetscScalar* a;
  PetscFunctionBeginUser;
  sum->assign(nv(), 0.0);
  const double vol = dx_[0] * dx_[1] * (opt_.dim == 3 ? dx_[2] : 1.0);
  const PetscInt ncell = m_[0] * m_[1] * m_[2];
  PetscCall(VecGetArrayRead(U, &a));
  for (PetscInt c = 0; c < ncell; ++c)
    for (int v = 0; v < nv(); ++v) (*sum)[v] += a[c * nv() + v] * vol;
  PetscCall(VecRestoreArrayRead(U, &a));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sum->data(), nv(), MPI_DOUBLE, MPI_SUM, ctx_.comm()));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::solve() {
  PetscFunctionBeginUser;
  PetscCall(restartIfRequested());
  PetscCall(checkState(U_, steps_, time_));
  if (opt_.snapshot_every > 0 && !opt_.output.empty() && steps_ == 0) PetscCall(writeSnapshot(0, 0.0));
  PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                           "euler: problem %s, dim %d, scheme %s, time %s, grid %" PetscInt_FMT
                           " x %" PetscInt_FMT " x %" PetscInt_FMT ", t_final %g, %d rank(s)",
                           opt_.problem.c_str(), opt_.dim, opt_.scheme.c_str(), opt_.time.c_str(), opt_.n[0],
                           opt_.n[1], opt_.n[2], opt_.t_final, ctx_.size()));
  progress_ =
      std::make_unique<suite::Progress>(ctx_.comm(), ctx_.quiet(), ctx_.progressInterval(), opt_.t_final);
  const double w0 = MPI_Wtime(), c0 = cpuSeconds();
  PetscCall(TSSolve(ts_, U_));
  wall_solve_ = MPI_Wtime() - w0;
  cpu_solve_ = cpuSeconds() - c0;
  PetscCall(TSGetStepNumber(ts_, &steps_));
  PetscReal t;
  PetscCall(TSGetTime(ts_, &t));
  time_ = t;
  if (ckpt_.enabled() && last_checkpoint_step_ != steps_) PetscCall(checkpointNow());
  std::vector<double> tot;
  PetscCall(totals(U_, &tot));
  const char* names[5] = {"mass", "momentum_x", "momentum_y", "momentum_z", "energy"};
  for (int c = 0; c < nv(); ++c) {
    const double scale = std::max(std::abs(totals0_[c]), 1e-300);
    PetscCall(suite::logInfo(
        ctx_.comm(), ctx_.quiet(), "conservation %s: initial %.15e final %.15e rel_change %.3e",
        c == nv() - 1 ? "energy" : names[c], totals0_[c], tot[c], std::abs(tot[c] - totals0_[c]) / scale));
  }
  const double cells = (double)opt_.n[0] * opt_.n[1] * opt_.n[2] * steps_;
  const LineStats& st = opt_.dim == 2 ? sweep4_->stats() : sweep5_->stats();
  // Shock rows, limited faces and fallbacks summed over the ranks; the solve calls and lines are rank 0's.
  long long sums[3] = {st.shock_rows, st.limited_faces,
                       opt_.dim == 2 ? sweep4_->lineFallbacks() : sweep5_->lineFallbacks()};
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_LONG_LONG, MPI_SUM, ctx_.comm()));
  const long long solves = opt_.dim == 2 ? sweep4_->lineSolves() : sweep5_->lineSolves();
  const long long lines = opt_.dim == 2 ? sweep4_->linesSolved() : sweep5_->linesSolved();
  PetscCall(suite::logInfo(
      ctx_.comm(), ctx_.quiet(),
      "euler: %" PetscInt_FMT " steps to t = %.6g in %.3f s (%.3e cell-steps/s, %.3e per rank; "
      "rank 0 CPU %.3f s); shock rows %lld, limited faces %lld; rank 0: %lld batched line solves of %lld "
      "lines; exact fallbacks %lld",
      steps_, t, wall_solve_, cells / wall_solve_, cells / wall_solve_ / ctx_.size(), cpu_solve_, sums[0],
      sums[1], solves, lines, sums[2]));
  if (opt_.error) PetscCall(computeErrors());
  PetscFunctionReturn(0);
}

PetscErrorCode runEulerND(const suite::RunContext& ctx, int dim) {
  EulerRunND run(ctx, dim);
  PetscFunctionBeginUser;
  PetscCall(run.readOptions());
  if (ctx.helpRequested()) {
    PetscCall(ctx.checkUnusedOptions());
    PetscFunctionReturn(0);
  }
  PetscCall(run.setup());
  PetscCall(ctx.checkUnusedOptions());
  PetscCall(run.solve());
  PetscCall(run.writeOutput());
  PetscFunctionReturn(0);
}

} // namespace euler_app
