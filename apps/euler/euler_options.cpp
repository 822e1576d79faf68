// Reading the Euler run's options (see euler_options.hpp): the named choices first (they decide the problem,
// whose options and defaults come next), then grid, numerics and output options in one block.
#include "euler_options.hpp"

#include "core/named_choice.hpp"
#include "core/option_value.hpp"
#include "euler/line_options.hpp"
#include "euler/problem_overrides.hpp"
#include "euler/schemes.hpp"
#include "euler/solid_body.hpp"
#include "euler_stepper.hpp"

namespace euler_app {

using namespace suite::euler;

namespace {
std::vector<suite::Choice> problemChoices(int dim) {
  std::vector<suite::Choice> list;
  if (dim > 1)
    for (const ProblemDoc& p : problemDocsND()) list.push_back({p.name, p.description});
  for (const ProblemDoc& p : problemDocs())
    list.push_back({p.name, dim > 1 ? std::string("planar along -axis: ") + p.description : p.description});
  for (const ProblemDoc& p : userProblemDocs()) list.push_back({p.name, p.description});
  return list;
}

std::vector<suite::Choice> schemeChoices() {
  std::vector<suite::Choice> list;
  for (const SchemeInfo* s : allSchemes()) list.push_back({s->name, s->description});
  return list;
}

std::vector<suite::Choice> lineSolveChoices(int dim) {
  if (dim == 1)
    return {{"substructured", "distributed compact line solve, O(N/P) per rank"},
            {"gather", "the whole line on every rank (for comparison)"}};
  return {{"transpose", "lines split over ranks moved whole to one rank each (two all-to-all exchanges)"},
          {"substructured", "split lines solved in place (partition method); always when lines < ranks"}};
}

const std::vector<suite::Choice> kUpwindings = {
    {"rf-char",
     "each characteristic field upwinded by the sign of its Roe speed, local Lax-Friedrichs only where "
     "it changes (HyPar's rf-char; -characteristic rows)"},
    {"llf", "local Lax-Friedrichs splitting of every field (-local_lf false: global)"}};

const std::vector<suite::Choice> kAxes = {{"x", "along x"}, {"y", "along y"}, {"z", "along z (-dim 3)"}};

const std::vector<suite::Choice> kBoundaries = {{"periodic", "periodic (both ends)"},
                                                {"outflow", "zero-gradient extrapolation"},
                                                {"reflecting", "reflecting wall"},
                                                {"inflow", "the problem's inflow state"}};

// -problem, -scheme, -time and the choices that decide how the problem is built.
PetscErrorCode readChoices(MPI_Comm comm, Options* o) {
  PetscFunctionBeginUser;
  o->problem = o->dim == 1 ? "sod" : "isentropic_vortex";
  const char* text = o->dim == 1 ? "Problem of -dim 1 (-dim 2 or 3 lists the multi-dimensional problems)"
                                 : "Problem of -dim 2|3 (-dim 1 lists the 1D problems alone)";
  PetscOptionsBegin(comm, "", "Euler options", "");
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-problem", text, problemChoices(o->dim), &o->problem));
  PetscCall(
      suite::optionsChoice(PetscOptionsObject, "-scheme", "Spatial scheme", schemeChoices(), &o->scheme));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-time", "Time integrator (then -ts_* refine it)",
                                 timeIntegrators(), &o->time));
  if (o->dim == 1)
    PetscCall(
        suite::optionsInt(PetscOptionsObject, "-scheme_spectrum",
                          "Measure the scheme's modified wavenumber on N periodic points instead of a run",
                          "", o->scheme_spectrum, &o->scheme_spectrum, nullptr));
  else
    PetscCall(
        suite::optionsChoice(PetscOptionsObject, "-axis", "Axis of a planar (1D) problem", kAxes, &o->axis));
  PetscOptionsEnd();
  PetscCheck(o->axis == "x" || o->axis == "y" || (o->axis == "z" && o->dim == 3), comm,
             PETSC_ERR_ARG_OUTOFRANGE, "Invalid -axis %s: x, y%s", o->axis.c_str(),
             o->dim == 3 ? " or z" : "");
  o->implicit = isImplicit(o->time);
  o->upwinding = findScheme(o->scheme)->rf_char_default ? "rf-char" : "llf";
  PetscFunctionReturn(0);
}

// The problem's options, and the run's defaults from it.
PetscErrorCode createProblemOf(MPI_Comm comm, Options* o, Problem* line, ProblemND* pr) {
  PetscFunctionBeginUser;
  if (isUserProblem(o->problem)) { // any dim: a ProblemND directly (1D: the line keeps only the name)
    PetscCall(createUserProblem(comm, o->problem, o->dim, pr));
    line->name = o->problem;
    for (int d = 0; d < 3; ++d) o->n[d] = pr->default_n[d];
    o->t_final = pr->t_final;
  } else if (o->dim == 1) {
    PetscCall(createProblem(comm, o->problem, line));
    o->n[0] = line->default_nx;
    o->t_final = line->t_final;
    o->max_steps = line->default_max_steps;
    o->dt = line->default_dt;
    o->spacetime_every = line->default_spacetime_every;
  } else {
    PetscCall(createProblemND(comm, o->problem, o->dim, o->axis[0] - 'x', pr));
    for (int d = 0; d < 3; ++d) o->n[d] = d < o->dim ? pr->default_n[d] : 1;
    o->t_final = pr->t_final;
  }
  // Implicit steps default to the global alpha: the local one (a max over the stencil) is not
  // differentiable, and Newton stalls on it at shocks (Sod N = 200, weno5, BDF2: stagnates at 1e-4 relative).
  // rf-char switches fields between one-sided reconstructions: not differentiable either, so "llf" there too.
  if (o->implicit) o->positivity = PETSC_FALSE, o->local_lf = PETSC_FALSE, o->upwinding = "llf";
  PetscFunctionReturn(0);
}

// 1D: the domain and boundary conditions of the line (-xmin -xmax -bc_left -bc_right).
PetscErrorCode readLineDomain(PetscOptionItems* PetscOptionsObject, Problem* line) {
  std::string bc[2] = {bcName(line->bc_left), bcName(line->bc_right)};
  PetscFunctionBeginUser;
  PetscCall(suite::optionsReal(PetscOptionsObject, "-xmin", "Left end of the domain", "", line->xmin,
                               &line->xmin, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-xmax", "Right end of the domain", "", line->xmax,
                               &line->xmax, nullptr));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-bc_left", "Left boundary", kBoundaries, &bc[0]));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-bc_right", "Right boundary", kBoundaries, &bc[1]));
  parseBc(bc[0], &line->bc_left);
  parseBc(bc[1], &line->bc_right);
  PetscFunctionReturn(0);
}

PetscErrorCode readGrid(PetscOptionItems* PetscOptionsObject, Options* o, Problem* line) {
  PetscFunctionBeginUser;
  PetscCall(suite::optionsInt(PetscOptionsObject, "-nx", o->dim == 1 ? "Number of cells" : "Cells along x",
                              "", o->n[0], &o->n[0], nullptr));
  if (o->dim >= 2)
    PetscCall(suite::optionsInt(PetscOptionsObject, "-ny", "Cells along y", "", o->n[1], &o->n[1], nullptr));
  if (o->dim == 3)
    PetscCall(suite::optionsInt(PetscOptionsObject, "-nz", "Cells along z", "", o->n[2], &o->n[2], nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-t_final", "End time", "", o->t_final, &o->t_final,
                               &o->t_final_set));
  if (o->dim == 1 && !isUserProblem(o->problem)) PetscCall(readLineDomain(PetscOptionsObject, line));
  PetscFunctionReturn(0);
}

PetscErrorCode readNumerics(PetscOptionItems* PetscOptionsObject, Options* o) {
  PetscFunctionBeginUser;
  PetscCall(suite::optionsReal(PetscOptionsObject, "-cfl",
                               o->dim == 1 ? "CFL number: dt = cfl dx / max(|u| + c)"
                                           : "CFL number: dt = cfl / sum_d(max(|u_d| + c) / dx_d)",
                               "", o->cfl, &o->cfl, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-dt", "Fixed time step (0: CFL-controlled)", "", o->dt,
                               &o->dt, nullptr));
  PetscCall(suite::optionsInt(PetscOptionsObject, "-max_steps", "Maximum number of steps (-1: no limit)", "",
                              o->max_steps, &o->max_steps, nullptr));
  PetscCall(suite::optionsBool(PetscOptionsObject, "-characteristic",
                               "Characteristic-wise reconstruction (false: component-wise)", "",
                               o->characteristic, &o->characteristic, nullptr));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-upwinding",
                                 "Flux upwinding of the flux-split schemes (default: rf-char for enopade6, "
                                 "crweno5 and weno5, llf for implicit steps; muscl2 upwinds by HLLC)",
                                 kUpwindings, &o->upwinding));
  PetscCall(suite::optionsBool(PetscOptionsObject, "-local_lf",
                               "Local Lax-Friedrichs splitting (false: global; implicit default)", "",
                               o->local_lf, &o->local_lf, nullptr));
  PetscCall(
      suite::optionsBool(PetscOptionsObject, "-positivity",
                         "Hu-Adams-Shu positivity-preserving flux limiter (explicit integrators; proven for "
                         "SSP-RK3 up to -cfl 0.5)",
                         "", o->positivity, &o->positivity, nullptr));
  PetscCall(
      suite::optionsInt(PetscOptionsObject, "-max_retries",
                        "Retries of a step at half dt when a stage leaves density or pressure non-positive "
                        "or passes the positivity limiter's CFL bound (0: stop at the first)",
                        "", o->max_retries, &o->max_retries, nullptr));
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-shock_threshold",
                         "ENO-Pade sensor, amplitude test: a shock row needs a relative second difference "
                         "(Jameson phi) above this",
                         "", o->shock_threshold, &o->shock_threshold, nullptr));
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-shock_ppw",
                         "ENO-Pade sensor, resolution test: a shock row needs data less resolved than a sine "
                         "of this many points per wavelength (>= 4; 0: amplitude test alone)",
                         "", o->shock_ppw, &o->shock_ppw, nullptr));
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-filter_alpha",
                         "Sixth-order compact filter (Gaikwad & Visbal) of the state after every step: its "
                         "alpha_f in (-0.5, 0.5], typically 0.4 .. 0.49 (0.5: off)",
                         "", o->filter_alpha, &o->filter_alpha, nullptr));
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-filter_time",
                         "Relaxation time of -filter_alpha: each step blends in the filtered state with "
                         "weight min(1, dt / this), keeping the sixth order on smooth flow (0: the full "
                         "filter every step)",
                         "", o->filter_time, &o->filter_time, nullptr));
  if (o->dim > 1)
    PetscCall(
        suite::optionsInt(PetscOptionsObject, "-line_batch_mb",
                          "Memory (MiB) of one batch of block lines in the compact solves (more batches: "
                          "more messages, less memory)",
                          "", o->line_batch_mb, &o->line_batch_mb, nullptr));
  o->line_solve = lineSolveChoices(o->dim)[0].name; // the default: the first
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-line_solve",
                                 "Compact solves of lines split over ranks", lineSolveChoices(o->dim),
                                 &o->line_solve));
  PetscFunctionReturn(0);
}

PetscErrorCode readOutput(PetscOptionItems* PetscOptionsObject, Options* o) {
  PetscFunctionBeginUser;
  PetscCall(suite::optionsString(PetscOptionsObject, "-output", "HDF5 output file (XDMF sidecar beside it)",
                                 &o->output));
  PetscCall(suite::optionsInt(PetscOptionsObject, "-snapshot_every",
                              "Write a snapshot every N steps (0: none)", "", o->snapshot_every,
                              &o->snapshot_every, nullptr));
  PetscCall(
      suite::optionsBool(PetscOptionsObject, "-output_initial",
                         "Write the initial conservative state to /initial of -output (rho, mom_x.., E: "
                         "an -initial_state input that reproduces the run bitwise)",
                         "", o->output_initial, &o->output_initial, nullptr));
  if (o->dim == 1)
    PetscCall(suite::optionsInt(PetscOptionsObject, "-spacetime_every",
                                "Record density every N steps for the x-t image (0: none)", "",
                                o->spacetime_every, &o->spacetime_every, nullptr));
  PetscCall(suite::optionsBool(PetscOptionsObject, "-error",
                               o->dim == 1 ? "L1/L2/Linf errors against the exact solution (or -reference)"
                                           : "Density errors (L1, L2, Linf) against the exact solution",
                               "", o->error, &o->error, nullptr));
  if (o->dim == 1) {
    PetscCall(suite::optionsString(PetscOptionsObject, "-reference",
                                   "HDF5 file of a finer (or equal) grid run to compare with",
                                   &o->reference));
  } else {
    PetscCall(
        suite::optionsBool(PetscOptionsObject, "-spectrum",
                           "Kinetic-energy spectrum E(k) of the final state and every snapshot (FFTW-MPI)",
                           "", o->spectrum, &o->spectrum, nullptr));
  }
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode readOptions(const suite::RunContext& ctx, Options* o, Problem* line, ProblemND* pr,
                           suite::CheckpointPolicy* ckpt) {
  MPI_Comm comm = ctx.comm();
  PetscFunctionBeginUser;
  PetscCall(readChoices(comm, o));
  PetscCall(createProblemOf(comm, o, line, pr));
  PetscOptionsBegin(comm, "", "Euler discretisation and output options", "");
  PetscCall(readGrid(PetscOptionsObject, o, line));
  PetscCall(readNumerics(PetscOptionsObject, o));
  PetscCall(readOutput(PetscOptionsObject, o));
  PetscOptionsEnd();
  PetscCall(ckpt->setFromOptions(comm, "euler"));
  const bool registered_line = o->dim == 1 && !isUserProblem(o->problem);
  if (registered_line) lineProblemAsGrid(*line, pr);
  // The user's geometry on any problem: domain (a registered line read -xmin -xmax itself), faces, obstacle.
  PetscCall(readDomainOptions(comm, registered_line ? 1 : 0, pr));
  PetscCall(readFaceOptions(comm, pr));
  PetscCall(readSolidOptions(comm, pr));
  PetscCall(validateOptions(ctx, *o, *line, *pr));
  PetscFunctionReturn(0);
}

} // namespace euler_app
