// The options of the Euler run for -dim 1|2|3: one set, read and validated collectively. -problem, -scheme,
// -time, -line_solve, -axis and the 1D boundary conditions are named choices documented by -help from their
// registries (the problem list depends on -dim). 1D only: -xmin -xmax -bc_left -bc_right -spacetime_every
// -reference -scheme_spectrum; 2D/3D only: -ny [-nz] -axis -line_batch_mb -spectrum.
#pragma once

#include "core/run_context.hpp"
#include "euler/problem.hpp"
#include "euler/problem_nd.hpp"
#include "io/checkpoint_policy.hpp"

#include <petscsys.h>

#include <string>

namespace euler_app {

struct Options {
  int dim = 1;
  std::string problem, scheme = "enopade6", time = "ssprk3", axis = "x", upwinding, line_solve, output,
                       reference;
  PetscInt n[3] = {1, 1, 1}, snapshot_every = 0, max_steps = -1, spacetime_every = 0, scheme_spectrum = 0,
           line_batch_mb = 256, max_retries = 6;
  double t_final = 0.0, cfl = 0.4, dt = 0.0, shock_threshold = 0.02, shock_ppw = 8.0, filter_alpha = 0.5,
         filter_time = 0.0;
  PetscBool t_final_set = PETSC_FALSE, output_initial = PETSC_FALSE;
  PetscBool error = PETSC_FALSE, characteristic = PETSC_TRUE, local_lf = PETSC_TRUE, positivity = PETSC_TRUE,
            spectrum = PETSC_FALSE;
  bool implicit = false;
  int nv() const { return dim + 2; }
};

// Reads every option of a -dim `opt->dim` run: the problem's own options (into *line for 1D, which *problem
// then describes as a 1-D grid problem; directly into *problem for 2D/3D), the numerics, the output and the
// checkpoint policy. Under -help it documents them all.
PetscErrorCode readOptions(const suite::RunContext& ctx, Options* opt, suite::euler::Problem* line,
                           suite::euler::ProblemND* problem, suite::CheckpointPolicy* ckpt);

// Collective checks of the options read (euler_option_checks.cpp): ranges, grid sizes against the stencil,
// the rank count and the 32-bit PetscInt, the memory estimate, the output's directory.
PetscErrorCode validateOptions(const suite::RunContext& ctx, const Options& opt,
                               const suite::euler::Problem& line, const suite::euler::ProblemND& problem);

// The 1D problem as a problem on a 1-D grid (x only; Inflow boundaries become Custom faces with the inflow
// state), so that one driver runs every dimension (euler_line_problem.cpp).
void lineProblemAsGrid(const suite::euler::Problem& line, suite::euler::ProblemND* problem);

} // namespace euler_app
