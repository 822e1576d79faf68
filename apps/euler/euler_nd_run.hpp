// The 2D/3D Euler run (-dim 2|3): a PETSc DMDA with a star stencil of width 3 and NV = dim + 2 unknowns per
// cell, the 1D schemes applied direction by direction (DirectionSweep: lines split over ranks transposed whole
// to one rank each, or solved in place by substructuring; line communicators split from the DMDA's process
// grid), boundary ghosts from the problem, gravity source, PETSc TS, CFL dt = cfl / sum_d(max(|u_d| + c) / dx_d), collective state checks, HDF5 + XDMF
// output, energy spectra (FFTW-MPI), checkpoint/restart at any rank count.
#pragma once

#include "core/progress.hpp"
#include "euler_stepper.hpp"
#include "core/run_context.hpp"
#include "euler/direction_sweep.hpp"
#include "euler/problem_nd.hpp"
#include "io/checkpoint_policy.hpp"
#include "io/h5_output.hpp"

#include <petscdmda.h>
#include <petscts.h>

#include <memory>
#include <string>
#include <vector>

namespace euler_app {

struct OptionsND {
  std::string problem = "isentropic_vortex", scheme = "enopade6", time = "ssprk3", output, axis = "x";
  int dim = 2;
  PetscInt n[3] = {0, 0, 0}, snapshot_every = 0, max_steps = -1, line_batch_mb = 256;
  double t_final = 0.0, cfl = 0.4, dt = 0.0, shock_threshold = 0.02;
  PetscBool error = PETSC_FALSE, characteristic = PETSC_TRUE, local_lf = PETSC_TRUE, positivity = PETSC_TRUE,
            spectrum = PETSC_FALSE;
  bool implicit = false;
  bool transpose_lines = true; // -line_solve transpose (false: substructured)
};

class EulerRunND {
public:
  EulerRunND(const suite::RunContext& ctx, int dim) : ctx_(ctx) { opt_.dim = dim; }
  ~EulerRunND();
  PetscErrorCode readOptions();
  PetscErrorCode setup();
  PetscErrorCode solve();
  PetscErrorCode writeOutput(); // euler_nd_output.cpp

  // TS callbacks
  PetscErrorCode rhs(double t, Vec U, Vec F);
  PetscErrorCode preStep();
  PetscErrorCode postStep();

private:
  int nv() const { return opt_.dim + 2; }
  PetscErrorCode setupGrid();
  PetscErrorCode setupLineComms();
  PetscErrorCode setupTimeStepper();
  template <int NV> PetscErrorCode rhsImpl(double t, const double* ul, double* f);
  template <int NV>
  void gatherLines(int d, double t, const double* ul, std::vector<std::array<double, NV>>* q);
  PetscErrorCode maxWaveSpeeds(Vec U, double amax[3]) const;
  double cflTimeStep(const double amax[3]) const;
  void cellCentre(PetscInt i, PetscInt j, PetscInt k, double x[3]) const;
  PetscErrorCode checkState(Vec U, PetscInt step, double time) const;
  PetscErrorCode totals(Vec U, std::vector<double>* sum) const;
  // output (euler_nd_output.cpp)
  PetscErrorCode primitiveFields(Vec U, std::vector<double> fields[5]) const; // rho, u, v, w, p
  PetscErrorCode writeFields(const std::string& group, Vec U);
  PetscErrorCode writeSnapshot(PetscInt step, double time);
  PetscErrorCode computeErrors();
  PetscErrorCode writeSpectrum(const std::string& group); // E(k) into group/k, group/E
  PetscErrorCode writeXdmf();
  void blockDims(suite::Dims* dims, suite::Dims* start, suite::Dims* count) const;
  // checkpoint/restart (euler_nd_checkpoint.cpp)
  std::string checkpointTag() const;
  PetscErrorCode checkpointIo(bool write, const std::string& path, PetscInt* step, double* time);
  CheckpointIo checkpointFile(); // checkpointIo as a function object
  PetscErrorCode restartIfRequested();
  PetscErrorCode checkpointNow();

  const suite::RunContext& ctx_;
  OptionsND opt_;
  suite::euler::ProblemND problem_;
  const suite::euler::SchemeInfo* scheme_ = nullptr;
  std::unique_ptr<suite::euler::DirectionSweep<4>> sweep4_;
  std::unique_ptr<suite::euler::DirectionSweep<5>> sweep5_;
  DM da_ = nullptr;
  Vec U_ = nullptr;
  TS ts_ = nullptr;
  PetscInt s_[3] = {0, 0, 0}, m_[3] = {1, 1, 1};   // this rank's first cell and cell count per direction
  PetscInt gs_[3] = {0, 0, 0}, gm_[3] = {1, 1, 1}; // ghosted block
  double dx_[3] = {1, 1, 1}, dt_limiter_ = 0.0;
  bool periodic_[3] = {true, true, true};
  MPI_Comm line_comm_[3] = {MPI_COMM_NULL, MPI_COMM_NULL, MPI_COMM_NULL};
  std::vector<double> lines_, faces_; // line buffers of the direction being swept (NV doubles per entry)
  std::vector<double> totals0_;
  suite::H5Output out_;
  std::vector<std::pair<PetscInt, double>> snapshots_;
  suite::CheckpointPolicy ckpt_;
  std::unique_ptr<suite::Progress> progress_;
  PetscInt last_checkpoint_step_ = -1, steps_ = 0;
  double time_ = 0.0, wall_solve_ = 0.0, cpu_solve_ = 0.0;
  bool have_errors_ = false;
  double err_l1_ = 0, err_l2_ = 0, err_linf_ = 0;
  PetscLogStage stage_lines_[3] = {0, 0, 0};
  std::string rhs_failure_; // set by rhsImpl when a line solve throws
};

PetscErrorCode runEulerND(const suite::RunContext& ctx, int dim);

} // namespace euler_app
