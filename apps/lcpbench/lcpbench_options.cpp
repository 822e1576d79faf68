// lcpbench's options (see lcpbench.hpp): declared with -help text generated from the registries of lib/lcp,
// defaults, and validation (collective: every rank takes the same error path).
#include "lcpbench.hpp"

#include "core/comma_list.hpp"
#include "core/named_choice.hpp"

#include <algorithm>
#include <cmath>

namespace lcpbench_app {
namespace {

using suite::Choice;
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

template <class Registry> std::vector<Choice> choices(const Registry& r) {
  std::vector<Choice> c;
  for (const auto& x : r) c.push_back({x.name, x.description});
  return c;
}

std::vector<Choice> familyChoices() {
  std::vector<Choice> c = choices(suite::lcp::familyRegistry());
  c.push_back({"file", "problems read from -file (Siconos .dat, suite .h5, FCLib HDF5)"});
  return c;
}

PetscErrorCode readProblemOptions(PetscOptionItems* PetscOptionsObject, Options* o, PetscBool* family_set) {
  char files[8192] = "";
  PetscFunctionBeginUser;
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-family", "Problem family", familyChoices(), &o->family,
                                 family_set));
  PetscCall(PetscOptionsInt("-n", "Problem size (generated families)", "", o->n, &o->n, nullptr));
  PetscCall(
      PetscOptionsInt("-count", "Number of problems (generated families)", "", o->count, &o->count, nullptr));
  PetscCall(PetscOptionsInt("-seed", "Seed of the generators (problem k uses stream (seed, k))", "", o->seed,
                            &o->seed, nullptr));
  PetscCall(PetscOptionsReal("-cond", "Condition number of M (random_spd, random_box, pmatrix)", "", o->cond,
                             &o->cond, nullptr));
  PetscCall(
      PetscOptionsReal("-qrange", "q uniform in [-qrange, qrange]", "", o->qrange, &o->qrange, nullptr));
  o->lower = -o->qrange; // box defaults follow the q range: a mix of free and bound variables
  o->upper = o->qrange;
  PetscCall(PetscOptionsReal("-lower", "Lower bound of random_box problems (default -qrange)", "", o->lower,
                             &o->lower, nullptr));
  PetscCall(PetscOptionsReal("-upper", "Upper bound of random_box problems (default qrange)", "", o->upper,
                             &o->upper, nullptr));
  PetscCall(PetscOptionsString(
      "-file", "Problem files for -family file (comma-separated; .dat Siconos, .h5 suite, FCLib HDF5)", "",
      files, files, sizeof files, nullptr));
  o->files = suite::splitCommaList(files);
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-fclib_model", "FCLib frictional-contact files read as",
                                 choices(kFclibModels), &o->fclib_model));
  PetscFunctionReturn(0);
}

PetscErrorCode readSolverOptions(PetscOptionItems* PetscOptionsObject, Options* o) {
  PetscFunctionBeginUser;
  PetscCall(suite::optionsChoiceList(PetscOptionsObject, "-solvers", "LCP solvers to run",
                                     choices(suite::lcp::solverRegistry()), &o->solvers));
  PetscCall(PetscOptionsInt("-max_it", "Iteration / pivot cap of every solver (0: each solver's default)", "",
                            o->max_it, &o->max_it, nullptr));
  PetscCall(PetscOptionsReal("-omega", "PGS relaxation factor", "", o->omega, &o->omega, nullptr));
  PetscCall(
      PetscOptionsInt("-block_size", "Block size of pgs_block", "", o->block_size, &o->block_size, nullptr));
  PetscCall(PetscOptionsReal("-rel_tol", "Acceptance: residual <= rel_tol (1 + |q|_inf)", "", o->rel_tol,
                             &o->rel_tol, nullptr));
  PetscCall(PetscOptionsBool("-refine", "Active-set refinement of claimed solutions", "", o->refine,
                             &o->refine, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode readRunOptions(PetscOptionItems* PetscOptionsObject, Options* o, PetscBool* strict_set) {
  char output[PETSC_MAX_PATH_LEN] = "";
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsInt("-chunk", "Problems per work request (0: automatic)", "", o->chunk, &o->chunk,
                            nullptr));
  PetscCall(PetscOptionsBool("-strict",
                             "Exit non-zero if a solver leaves a problem unsolved (default: on for "
                             "-family file)",
                             "", o->strict, &o->strict, strict_set));
  PetscCall(PetscOptionsString("-output", "HDF5 results file (OUT.partial while the batch runs)", "", output,
                               output, sizeof output, nullptr));
  o->output = output;
  PetscCall(PetscOptionsInt("-flush_every", "Write and flush results to OUT.partial every N problems", "",
                            o->flush_every, &o->flush_every, nullptr));
  PetscCall(PetscOptionsReal("-flush_seconds", "... and at least every S seconds of wall time", "",
                             o->flush_seconds, &o->flush_seconds, nullptr));
  PetscCall(PetscOptionsBool("-resume",
                             "Continue an interrupted batch found in OUT.partial (same options required); "
                             "-resume 0 discards it",
                             "", o->resume, &o->resume, nullptr));
  PetscCall(PetscOptionsReal("-delay_per_problem", "Testing: sleep this many seconds after each problem", "",
                             o->delay, &o->delay, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode checkRanges(MPI_Comm comm, const Options& o) {
  PetscFunctionBeginUser;
  PetscCheck(o.cond >= 1.0 && std::isfinite(o.cond), comm, PETSC_ERR_ARG_OUTOFRANGE, "-cond %g: must be >= 1",
             (double)o.cond);
  PetscCheck(o.qrange >= 0.0 && std::isfinite(o.qrange), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-qrange %g: must be >= 0", (double)o.qrange);
  PetscCheck(!(o.lower > o.upper), comm, PETSC_ERR_ARG_OUTOFRANGE, "-lower %g > -upper %g (l > u)",
             (double)o.lower, (double)o.upper);
  PetscCheck(o.max_it >= 0 && o.block_size >= 1 && o.block_size <= 4 && o.chunk >= 0, comm,
             PETSC_ERR_ARG_OUTOFRANGE, "-max_it must be >= 0, -block_size in [1, 4], -chunk >= 0");
  PetscCheck(o.flush_every >= 1 && o.flush_seconds > 0 && o.delay >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flush_every must be >= 1, -flush_seconds > 0, -delay_per_problem >= 0");
  PetscFunctionReturn(0);
}

// Context-dependent defaults (-family, -strict unless given) and the checks that involve several options.
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
  PetscCall(checkRanges(comm, *o));
  if (!strict_set) o->strict = o->fromFiles() ? PETSC_TRUE : PETSC_FALSE;
  if (o->fromFiles()) {
    PetscCheck(!o->files.empty(), comm, PETSC_ERR_ARG_WRONG, "-family file needs -file FILE[,FILE...]");
  } else {
    PetscCheck(o->n >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-n %d: must be >= 1", (int)o->n);
    PetscCheck(o->count >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-count %d: must be >= 1", (int)o->count);
  }
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
  PetscCall(finishOptions(ctx.comm(), family_set, strict_set, o));
  PetscFunctionReturn(0);
}

FclibModel fclibModel(const std::string& name) {
  for (const auto& m : kFclibModels)
    if (name == m.name) return m.model;
  return FclibModel::BoxFriction;
}

} // namespace lcpbench_app
