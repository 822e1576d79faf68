// The Euler run for -dim 1|2|3: a PETSc DMDA with NV = dim + 2 unknowns per cell and 3 ghost cells, the 1D
// schemes applied direction by direction (DirectionSweep<NV>: in 1D the one line over all ranks; in 2D/3D lines
// split over ranks transposed whole to one rank each, or solved in place by substructuring, on line
// communicators split from the DMDA's process grid), boundary ghosts from the problem, gravity source, PETSc
// TS stepped by the suite's TimeLoop (this class is its TimeStepped), CFL dt, collective state checks,
// checkpoint/restart at any rank count, HDF5 + XDMF output in the 1D or the 2D/3D layout.
#pragma once

#include "core/run_context.hpp"
#include "core/time_loop.hpp"
#include "euler/direction_sweep.hpp"
#include "euler_options.hpp"
#include "io/checkpoint_policy.hpp"
#include "io/h5_output.hpp"
#include "model_choice/grid_distance.hpp"

#include <petscdmda.h>
#include <petscts.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace euler_app {

class EulerRun : public suite::TimeStepped {
public:
  EulerRun(const suite::RunContext& ctx, int dim) : ctx_(ctx) { opt_.dim = dim; }
  ~EulerRun() override;
  PetscErrorCode readOptions() {
    t_options_ = MPI_Wtime(); // setup_seconds counts from here (options: a file inspected, formulas parsed)
    return euler_app::readOptions(ctx_, &opt_, &line_, &problem_, &ckpt_);
  }
  bool spectrumOnly() const { return opt_.scheme_spectrum != 0; }
  PetscErrorCode schemeSpectrum(); // -scheme_spectrum N instead of a run (euler_scheme_spectrum.cpp)
  PetscErrorCode setup();          // euler_grid.cpp
  PetscErrorCode solve();          // the time loop (euler_run.cpp)
  PetscErrorCode rhs(double t, Vec U, Vec F); // TS right-hand side (euler_rhs.cpp)

  // suite::TimeStepped: start, proposeDt, advance (euler_step.cpp), saveState, loadState (euler_checkpoint.cpp),
  // writeSnapshot (euler_output.cpp), writeFinal (euler_report.cpp)
  PetscErrorCode start(PetscInt step, double t, bool restarted) override;
  PetscErrorCode proposeDt(PetscInt step, double t, double* dt) override;
  PetscErrorCode advance(PetscInt step, double t, double dt, suite::StepOutcome* out) override;
  PetscErrorCode saveState(const std::string& path, PetscInt step, double t) override;
  PetscErrorCode loadState(const std::string& path, PetscInt* step, double* t) override;
  PetscErrorCode writeSnapshot(PetscInt step, double t) override;
  PetscErrorCode writeFinal(const suite::LoopSummary& summary) override;

  // For the accuracy-target driver (euler_target.cpp): runs whose log lines are left out (pilots), the options
  // read, the final density on the whole grid on every rank (euler_density_field.cpp), the solve's cost (CPU
  // seconds, the maximum over the ranks), its steps, its end time and the L1 density error of -error (NaN
  // without).
  void setQuiet(bool q) { quiet_ = q; }
  const Options& options() const { return opt_; }
  PetscErrorCode densityField(suite::model_choice::GridField* g) const;
  // after_first_step: without the first step (the steady cost: the first step touches the work arrays first)
  PetscErrorCode solveSeconds(double* seconds, bool after_first_step = false) const;
  PetscInt steps() const { return step_; }
  double finalTime() const { return time_; }
  double l1DensityError() const { return err_.have ? err_.l1[0] : NAN; }

private:
  bool quiet() const { return quiet_ || ctx_.quiet(); }
  int dim() const { return opt_.dim; }
  int nv() const { return opt_.nv(); }
  PetscInt localCells() const { return m_[0] * m_[1] * m_[2]; }
  template <int NV> suite::euler::DirectionSweep<NV>& sweepOf() {
    if constexpr (NV == 3)
      return *sweep3_;
    else if constexpr (NV == 4)
      return *sweep4_;
    else
      return *sweep5_;
  }
  // grid (euler_grid.cpp)
  PetscErrorCode setupGrid();
  PetscErrorCode setupLineComms();
  PetscErrorCode setupSweep();
  PetscErrorCode setInitialState(); // euler_initial_state.cpp
  PetscErrorCode initialFromFile(double* u);
  PetscErrorCode initialFromProblem(double* u);
  PetscErrorCode writeInitial(); // -output_initial: /initial (rho, mom_x.., E)
  // solid obstacle (euler_solid.cpp): solid_ per owned cell (x fastest), solid_local_ per cell of the ghosted
  // block; both empty without an obstacle
  PetscErrorCode setupSolid();
  bool solidCell(PetscInt c) const { return !solid_.empty() && solid_[c]; }
  void zeroSolidCells(double* f) const;
  void cellCentre(PetscInt i, PetscInt j, PetscInt k, double x[3]) const;
  void blockDims(suite::Dims* dims, suite::Dims* start, suite::Dims* count) const; // (z,) (y,) x order
  PetscErrorCode totals(Vec U, std::vector<double>* sum) const;
  // right-hand side (euler_rhs.cpp)
  template <int NV> PetscErrorCode rhsImpl(double t, const double* ul, double* f);
  // amax: max |u_d| + c per direction; flux_scale: max p + rho |u|^2. false: a cell not admissible.
  template <int NV> bool stageSpeeds(const double* ul, double amax[3], double* flux_scale) const;
  long long unattainableFaces() const; // DirectionSweep's count, this rank
  template <int NV>
  void gatherLines(int d, double t, const double* ul, std::vector<std::array<double, NV>>* q);
  template <int NV>
  void fillBoundaryGhosts(int d, double t, PetscInt ja, PetscInt jb, std::array<double, NV>* ql);
  template <int NV>
  void addFluxDifferences(int d, const std::vector<std::array<double, NV>>& h, double* f) const;
  void addGravity(const double* ul, double* f) const;
  // steps (euler_step.cpp)
  PetscErrorCode maxWaveSpeeds(Vec U, double t, double amax[3]) const; // owned cells and Custom-face ghosts
  void customGhostSpeeds(const double* u, double t, double a[3]) const;
  double cflTimeStep(const double amax[3]) const;
  PetscErrorCode checkState(Vec U, PetscInt step, double time) const;
  // The first non-positive density or pressure (or non-finite value) of U as checkState's message, "" if none.
  PetscErrorCode findInvalidState(Vec U, PetscInt step, double time, std::string* message) const;
  PetscErrorCode stepProblem(PetscInt step, double t_new, std::string* why); // after TSStep: "" to accept
  PetscErrorCode rollBack(PetscInt step, double t);                          // the state before the step
  PetscErrorCode recordSpacetime(Vec U, double t);
  // -filter_alpha (euler_filter.cpp): the compact filter of the state after a step
  bool filterOn() const;
  PetscErrorCode applyFilter(double t, double dt, Vec U);
  template <int NV> PetscErrorCode filterDirection(int d, double t, Vec U);
  // output (euler_output.cpp, euler_energy_spectrum.cpp, euler_errors.cpp)
  PetscErrorCode primitiveFields(Vec U, std::vector<double> fields[5]) const; // rho, u, v, w, p
  PetscErrorCode writeFields(const std::string& group, Vec U, double t);
  // ENO-Pade shock rows of the state U per cell (euler_shock_flags.cpp): bit d set when a face of the cell in
  // direction d is a shock row; false for schemes without the switch (nothing to write).
  bool hasShockFlags() const;
  PetscErrorCode shockFlags(Vec U, double t, std::vector<double>* flags);
  template <int NV> void shockFlagsImpl(double t, const double* ul, std::vector<double>* flags);
  PetscErrorCode writeOutput();
  PetscErrorCode writeRunAttributes();
  PetscErrorCode writeLineResults();
  PetscErrorCode writeGridResults();
  PetscErrorCode writeXdmf();
  PetscErrorCode writeSpectrum(const std::string& group); // E(k) into group/k, group/E
  // -scheme_spectrum table into -output (euler_scheme_spectrum.cpp)
  PetscErrorCode writeSchemeSpectrum(int n, const std::vector<double> cols[6]);
  PetscErrorCode computeErrors();
  PetscErrorCode computeLineErrors(); // rho, u, p against the exact solution or -reference
  PetscErrorCode computeGridErrors(); // rho against the exact solution
  PetscErrorCode readReference(std::vector<double> ref[3], double scale[3]) const;
  void exactLineFields(std::vector<double> ref[3]) const; // ref[c] = exact rho, u, p at this rank's cells
  // end of run (euler_report.cpp)
  PetscErrorCode reportConservation();
  PetscErrorCode reportStatistics(const suite::LoopSummary& summary);
  // checkpoint (euler_checkpoint.cpp)
  std::string checkpointTag() const;
  PetscErrorCode checkpointIo(bool write, const std::string& path, PetscInt* step, double* time);

  const suite::RunContext& ctx_;
  bool quiet_ = false;
  Options opt_;
  suite::euler::Problem line_;      // -dim 1: the 1D problem (names, boundary attributes)
  suite::euler::ProblemND problem_; // every dim: the problem on the grid
  const suite::euler::SchemeInfo* scheme_ = nullptr;
  std::unique_ptr<suite::euler::DirectionSweep<3>> sweep3_;
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
  PetscLogStage stage_lines_[3] = {0, 0, 0};
  std::string rhs_failure_; // set by rhsImpl when a line solve throws
  // Retries of a step (euler_step.cpp): the state before the step, a stage state found non-positive (rhs, explicit
  // integrators: its message), the limiter's unattainable faces before the step, the step being retried and its
  // attempt.
  Vec U0_ = nullptr;
  std::string stage_failure_;
  bool stage_rejected_ = false; // this rhs call's stage state was not admissible
  long long unattainable0_ = 0;
  PetscInt retry_step_ = -1, retry_attempt_ = 0;
  std::vector<double> totals0_;
  std::vector<char> solid_, solid_local_;
  long long solid_cells_ = 0;                           // over all ranks
  suite::linalg::SubstructuredBlockLines filter_lines_; // -filter_alpha's line solves
  std::vector<double> filter_abc_, filter_rhs_, filter_x_;
  Vec Ufilter_ = nullptr; // -filter_time: the filtered state blended in
  suite::CheckpointPolicy ckpt_;
  // output
  suite::H5Output out_;
  std::vector<std::pair<PetscInt, double>> snapshots_;
  std::vector<double> spacetime_rho_, spacetime_t_; // -spacetime_every (1D)
  PetscInt step_ = 0;                // the last completed step (messages of the right-hand side)
  std::string status_ = "completed"; // the output's status attribute (core/run_summary.hpp)
  PetscInt retries_ = 0;             // steps retried at half dt (TimeLoop's summary, for the output)
  long long shock_rows_[2] = {0, 0}; // shock rows, rows the sensor examined (all ranks; reportStatistics)
  // readOptions() to the end of setup(): options, grid, line communicators, sweep, solid, initial state, stepper
  double t_options_ = 0.0, wall_setup_ = 0.0;
  double time_ = 0.0, wall_solve_ = 0.0, cpu_solve_ = 0.0, cpu_first_step_ = 0.0;
  struct Errors {
    bool have = false;
    double l1[3] = {0, 0, 0}, l2[3] = {0, 0, 0}, linf[3] = {0, 0, 0}; // rho, u, p (2D/3D: rho only)
    std::vector<double> exact[3]; // 1D: the exact (or reference) rho, u, p at this rank's cells
  } err_;
};

PetscErrorCode runEuler(const suite::RunContext& ctx);

} // namespace euler_app
