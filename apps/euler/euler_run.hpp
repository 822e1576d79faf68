// The 1D Euler run: options, DMDA line with ghost cells, PETSc TS (SSP-RK3, RK4, implicit), CFL-controlled
// dt, collective checks, snapshots and the final HDF5 output.
#pragma once

#include "core/progress.hpp"
#include "euler_stepper.hpp"
#include "core/run_context.hpp"
#include "euler/direction_sweep.hpp"
#include "euler/problem.hpp"
#include "io/checkpoint_policy.hpp"
#include "io/h5_output.hpp"

#include <petscdmda.h>
#include <petscts.h>

#include <memory>
#include <string>
#include <vector>

namespace euler_app {

using suite::euler::Bc;
using suite::euler::Vec3;

struct Options {
  std::string problem = "sod", scheme = "enopade6", time = "ssprk3", output, reference;
  PetscInt nx = 0, snapshot_every = 0, max_steps = -1, spacetime_every = 0, scheme_spectrum = 0;
  double t_final = 0.0, cfl = 0.4, dt = 0.0, shock_threshold = 0.02;
  bool gather_lines = false;
  PetscBool error = PETSC_FALSE, characteristic = PETSC_TRUE, local_lf = PETSC_TRUE, positivity = PETSC_TRUE;
  bool implicit = false;
};

struct Snapshot {
  PetscInt step;
  double time;
};

class EulerRun {
public:
  explicit EulerRun(const suite::RunContext& ctx) : ctx_(ctx) {}
  ~EulerRun();
  PetscErrorCode readOptions();
  PetscErrorCode setup();
  PetscErrorCode solve();
  PetscErrorCode writeOutput();
  bool spectrumOnly() const { return opt_.scheme_spectrum != 0; }
  PetscErrorCode schemeSpectrum(); // -scheme_spectrum N (euler_spectrum.cpp)

  // TS callbacks
  PetscErrorCode rhs(double t, Vec U, Vec F);
  PetscErrorCode preStep();
  PetscErrorCode postStep();

private:
  PetscErrorCode setupTimeStepper();
  PetscErrorCode fillGhosts(Vec3* q) const; // q[0] is cell xs-3
  PetscErrorCode maxWaveSpeed(Vec U, double* amax) const;
  PetscErrorCode primitiveArrays(Vec U, std::vector<double>* rho, std::vector<double>* u,
                                 std::vector<double>* p) const;
  PetscErrorCode checkState(Vec U, PetscInt step, double time) const;
  PetscErrorCode writeSnapshot(PetscInt step, double time);
  PetscErrorCode totals(Vec U, Vec3* sum) const;
  PetscErrorCode computeErrors();
  // Checkpoint/restart (euler_checkpoint.cpp)
  std::string checkpointTag() const;
  PetscErrorCode checkpointIo(bool write, const std::string& path, PetscInt* step, double* time);
  CheckpointIo checkpointFile(); // checkpointIo as a function object
  PetscErrorCode restartIfRequested();
  PetscErrorCode checkpointNow();

  const suite::RunContext& ctx_;
  Options opt_;
  suite::euler::Problem problem_;
  const suite::euler::SchemeInfo* scheme_ = nullptr;
  std::unique_ptr<suite::euler::DirectionSweep<3>> op_; // the line's fluxes
  DM da_ = nullptr;
  Vec U_ = nullptr;
  TS ts_ = nullptr;
  PetscInt xs_ = 0, xm_ = 0;
  double dx_ = 0.0, dt_limiter_ = 0.0;
  bool periodic_ = false;
  std::vector<Vec3> q_, h_;
  std::vector<double> xc_; // local cell centres
  // output
  suite::H5Output out_;
  std::vector<Snapshot> snapshots_;
  std::vector<double> spacetime_rho_, spacetime_t_;
  Vec3 totals0_{};
  suite::CheckpointPolicy ckpt_;
  std::unique_ptr<suite::Progress> progress_; // progress line every -progress_interval seconds
  PetscInt last_checkpoint_step_ = -1;
  struct ErrorSet {
    double l1[3], l2[3], linf[3];
  };
  bool have_errors_ = false;
  std::vector<double> exact_[3]; // exact (or reference) rho, u, p at this rank's cells
  ErrorSet errors_{};
  double ref_diff_ = -1.0;
  PetscInt steps_ = 0;
  double time_ = 0.0, wall_solve_ = 0.0, cpu_solve_ = 0.0;
};

PetscErrorCode runEuler(const suite::RunContext& ctx);
// -dim 2|3 (euler_nd_run.cpp)
PetscErrorCode runEulerND(const suite::RunContext& ctx, int dim);

} // namespace euler_app
