// lcpbench's options (see lcpbench.hpp): declared with -help text generated from the registries of lib/lcp,
// defaults, and validation, sizes included (collective: every rank takes the same error path).
#include "lcpbench.hpp"

#include "core/comma_list.hpp"
#include "core/named_choice.hpp"
#include "core/option_text.hpp"
#include "core/option_value.hpp"
#include "core/resource_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lcpbench_app {
namespace {

using suite::Choice;
using suite::optionsValue;
using suite::lcp::FclibModel;

struct FclibModelInfo {
  const char* name;
  const char* description;
  FclibModel model;
};
const FclibModelInfo kFclibModels[] = {
    {"box_friction", "all unknowns, tangential bounds +-mu times the frictionless normal force",
     FclibModel::BoxFriction},
    {"normal", "the frictionless normal LCP", FclibModel::Normal},
};

PetscErrorCode readProblemOptions(PetscOptionItems* PetscOptionsObject, Options* o, PetscBool* family_set) {
  PetscOptionItems* const po = PetscOptionsObject; // the raw PETSc macros below name PetscOptionsObject
  std::vector<Choice> families = suite::choicesOf(suite::lcp::familyRegistry());
  PetscFunctionBeginUser;
  families.push_back({"file", "problems read from -file (Siconos .dat, suite .h5, FCLib HDF5)"});
  PetscCall(suite::optionsChoice(po, "-family", "Problem family", families, &o->family, family_set));
  PetscCall(optionsValue(po, "-n", "Problem size (generated families)", &o->n));
  PetscCall(optionsValue(po, "-count", "Number of problems (generated families)", &o->count));
  PetscCall(optionsValue(po, "-seed", "Seed of the generators (problem k uses stream (seed, k))", &o->seed));
  PetscCall(optionsValue(po, "-cond", "Condition number of M (random_spd, random_box, pmatrix)", &o->cond));
  PetscCall(optionsValue(po, "-qrange", "q uniform in [-qrange, qrange]", &o->qrange));
  o->lower = -o->qrange; // box defaults follow the q range: a mix of free and bound variables
  o->upper = o->qrange;
  // Infinite bounds are meaningful (l = -inf, u = inf: a linear system; l = 0, u = inf: an LCP).
  PetscCall(optionsValue(po, "-lower", "Lower bound of random_box problems (default -qrange; -inf allowed)",
                         &o->lower, nullptr, suite::Real::or_inf));
  PetscCall(optionsValue(po, "-upper", "Upper bound of random_box problems (default qrange; inf allowed)",
                         &o->upper, nullptr, suite::Real::or_inf));
  PetscCall(suite::optionsFileList(po, "-file",
                                   "Problem files for -family file (comma-separated, @LIST or a glob "
                                   "pattern; .dat Siconos, .h5 suite, FCLib HDF5)",
                                   &o->files));
  PetscCall(suite::optionsChoice(po, "-fclib_model", "FCLib frictional-contact files read as",
                                 suite::choicesOf(kFclibModels), &o->fclib_model));
  PetscFunctionReturn(0);
}

PetscErrorCode readSolverOptions(PetscOptionItems* po, Options* o) {
  PetscFunctionBeginUser;
  std::vector<Choice> solvers = suite::choicesOf(suite::lcp::solverRegistry());
  solvers.push_back({"auto", "the portfolio: classify the problem, try its class's chain (-portfolio), first "
                             "verified answer"});
  PetscCall(suite::optionsChoiceList(po, "-solvers", "LCP solvers to run", solvers, &o->solvers));
  PetscCall(suite::optionsString(po, "-portfolio",
                                 "Solver table of -solvers auto (HDF5 from scripts/bench/lcp-portfolio; "
                                 "default: the built-in one)",
                                 &o->portfolio));
  PetscCall(optionsValue(
      po, "-max_it",
      "Iteration / pivot cap of every solver (0: each solver's default; auto: its chain's first)",
      &o->max_it));
  PetscCall(optionsValue(po, "-omega", "PGS relaxation factor", &o->omega));
  PetscCall(optionsValue(po, "-block_size", "Block size of pgs_block", &o->block_size));
  PetscCall(optionsValue(po, "-rel_tol", "Acceptance: residual <= rel_tol (1 + |q|_inf)", &o->rel_tol));
  PetscCall(optionsValue(po, "-refine", "Active-set refinement of claimed solutions", &o->refine));
  PetscFunctionReturn(0);
}

PetscErrorCode readRunOptions(PetscOptionItems* po, Options* o, PetscBool* strict_set) {
  PetscFunctionBeginUser;
  PetscCall(optionsValue(po, "-chunk", "Problems per work request (0: automatic)", &o->chunk));
  PetscCall(optionsValue(po, "-strict",
                         "Exit non-zero if a solver leaves a problem unsolved (default: on for -family file)",
                         &o->strict, strict_set));
  PetscCall(suite::optionsString(po, "-output", "HDF5 results file (OUT.partial while the batch runs)",
                                 &o->output));
  PetscCall(optionsValue(po, "-save_solutions",
                         "Write every solver's z of every problem to /results/<solver>/z (count x largest n, "
                         "NaN-padded)",
                         &o->save_solutions));
  PetscCall(optionsValue(po, "-flush_every", "Write and flush results to OUT.partial every N problems",
                         &o->flush_every));
  PetscCall(
      optionsValue(po, "-flush_seconds", "... and at least every S seconds of wall time", &o->flush_seconds));
  PetscCall(optionsValue(
      po, "-resume",
      "Continue an interrupted batch found in OUT.partial (same options required); -resume 0 discards it",
      &o->resume));
  PetscCall(optionsValue(po, "-time_repeat",
                         "Time each solve by repetition: batches of runs lasting >= this many CPU seconds "
                         "(0: one timed run)",
                         &o->time_repeat));
  PetscCall(optionsValue(po, "-time_batches",
                         "With -time_repeat: batches timed, the fastest one's time per run recorded",
                         &o->time_batches));
  PetscCall(
      optionsValue(po, "-warmup",
                   "Untimed solves of the batch's first problems by every solver, on every rank, before "
                   "timing (the same count for every solver)",
                   &o->warmup));
  PetscCall(optionsValue(po, "-delay_per_problem", "Testing: sleep this many seconds after each problem",
                         &o->delay));
  PetscFunctionReturn(0);
}

// Context-dependent defaults (-family, -strict unless given) and validation.
PetscErrorCode finishOptions(MPI_Comm comm, PetscBool family_set, PetscBool strict_set, Options* o) {
  PetscFunctionBeginUser;
  // -file alone means -family file; -file with a generated family would silently ignore the files.
  if (!o->files.empty() && !family_set) o->family = "file";
  PetscCheck(o->files.empty() || o->fromFiles(), comm, PETSC_ERR_ARG_INCOMP,
             "-file is only read with -family file (given -family %s)", o->family.c_str());
  PetscCheck(!o->solvers.empty(), comm, PETSC_ERR_ARG_WRONG, "-solvers is empty; known: %s",
             suite::joinCommaList(suite::lcp::solverNames()).c_str());
  for (const auto& s : o->solvers)
    PetscCheck(std::count(o->solvers.begin(), o->solvers.end(), s) == 1, comm, PETSC_ERR_ARG_WRONG,
               "Solver '%s' is listed twice in -solvers", s.c_str());
  PetscCheck(!o->output.empty(), comm, PETSC_ERR_ARG_WRONG, "-output FILE.h5 is required");
  PetscCheck(o->portfolio.empty() || o->hasAuto(), comm, PETSC_ERR_ARG_INCOMP,
             "-portfolio is only read with -solvers auto (given -solvers %s)",
             suite::joinCommaList(o->solvers).c_str());
  PetscCheck(o->cond >= 1.0 && std::isfinite(o->cond), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-cond %g: must be >= 1", (double)o->cond);
  PetscCheck(o->qrange >= 0.0 && std::isfinite(o->qrange), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-qrange %g: must be >= 0", (double)o->qrange);
  PetscCheck(!(o->lower > o->upper), comm, PETSC_ERR_ARG_OUTOFRANGE, "-lower %g > -upper %g (l > u)",
             (double)o->lower, (double)o->upper);
  PetscCheck(o->max_it >= 0 && o->block_size >= 1 && o->block_size <= 4 && o->chunk >= 0, comm,
             PETSC_ERR_ARG_OUTOFRANGE, "-max_it must be >= 0, -block_size in [1, 4], -chunk >= 0");
  PetscCheck(o->flush_every >= 1 && o->flush_seconds > 0 && o->delay >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flush_every must be >= 1, -flush_seconds > 0, -delay_per_problem >= 0");
  PetscCheck(o->warmup >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-warmup %d: must be >= 0", (int)o->warmup);
  PetscCheck(o->time_repeat >= 0 && o->time_repeat <= 10 && o->time_batches >= 1 && o->time_batches <= 100,
             comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-time_repeat %g must be in [0, 10] s, -time_batches %d in [1, 100]", (double)o->time_repeat,
             (int)o->time_batches);
  if (!strict_set) o->strict = o->fromFiles() ? PETSC_TRUE : PETSC_FALSE;
  PetscCheck(!o->fromFiles() || !o->files.empty(), comm, PETSC_ERR_ARG_WRONG,
             "-family file needs -file FILE[,FILE...]");
  PetscCheck(o->fromFiles() || o->n >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-n %d: must be >= 1", (int)o->n);
  PetscCheck(o->fromFiles() || o->count >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-count %d: must be >= 1",
             (int)o->count);
  PetscFunctionReturn(0);
}

// Sizes before anything is allocated (the integer options are within PetscInt): for the generated families the
// dense n x n problem (entries within PetscInt) and the memory per rank: one problem at a time, M with the
// generator's and the solver's dense workspace ~ 6 n^2 doubles (measured: 4 n^2, n = 1000 and 1500, lemke, bpp,
// fb_newton, pgs), the done flags of -count problems (1 byte each; measured 2 GB at -count 2e9) and rank 0's
// buffer of -flush_every result records (with -save_solutions n values of z per solver in each).
PetscErrorCode checkSizes(MPI_Comm comm, const Options& o) {
  PetscFunctionBeginUser;
  if (o.fromFiles()) PetscFunctionReturn(0); // the readers bound a file's problem by the file's size
  const double n = (double)o.n, S = (double)o.solvers.size();
  const double record = 8.0 * (2.0 + 6.0 * S + (o.save_solutions ? S * n : 0.0));
  char what[160];
  std::snprintf(what, sizeof what, "-n %lld", (long long)o.n);
  PetscCall(suite::checkIndexCount(comm, n * n, "entries of the dense problem matrix", what));
  std::snprintf(what, sizeof what, "-n %lld -count %lld -flush_every %lld%s", (long long)o.n,
                (long long)o.count, (long long)o.flush_every, o.save_solutions ? " -save_solutions" : "");
  PetscCall(suite::checkMemoryEstimate(
      comm, 5e7 + 48.0 * n * n + 1.5 * (double)o.count + 2.0 * record * o.flush_every, what));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode readOptions(const suite::RunContext& ctx, Options* o, bool* help_only) {
  PetscBool family_set = PETSC_FALSE, strict_set = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx.comm(), "", "lcpbench options", "");
  PetscCall(readProblemOptions(PetscOptionsObject, o, &family_set));
  PetscCall(readSolverOptions(PetscOptionsObject, o));
  PetscCall(readRunOptions(PetscOptionsObject, o, &strict_set));
  PetscOptionsEnd();
  PetscCall(ctx.checkUnusedOptions());
  *help_only = ctx.helpRequested();
  if (*help_only) PetscFunctionReturn(0);
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-max_walltime", &o->max_walltime, nullptr));
  for (const char* name : {"-n", "-count", "-seed", "-max_it", "-block_size", "-chunk", "-flush_every",
                           "-time_batches", "-warmup"})
    PetscCall(suite::checkIntOptionRange(ctx.comm(), name, 0));
  PetscCall(finishOptions(ctx.comm(), family_set, strict_set, o));
  PetscCall(checkSizes(ctx.comm(), *o));
  PetscFunctionReturn(0);
}

FclibModel fclibModel(const std::string& name) {
  for (const auto& m : kFclibModels)
    if (name == m.name) return m.model;
  return FclibModel::BoxFriction;
}

} // namespace lcpbench_app
