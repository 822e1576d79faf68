// lcpcompare: the suite's LCP solvers against Siconos numerics (lexicographic Lemke, PGS, FB-Newton; Acary &
// Brogliato 2008) and Bullet's Dantzig box solver (btSolveDantzigLCP, from ODE: Baraff 1994 / Cottle-Dantzig
// principal pivoting with bounds), timed on the same generated problems in the same run, one core. Every
// answer is judged by the suite's acceptance rule (natural residual <= rel_tol (1 + |q|_inf), problem.hpp);
// time = CPU seconds of the calling thread around the solver call (Bullet's input copy excluded: it overwrites
// A and b). Box problems go to Siconos as relay problems (relay_lexicolemke, relay_pgs; no box FB-Newton:
// unsupported); Bullet's Dantzig needs l <= 0 <= u (else unsupported). Siconos uses BLAS: run with
// OPENBLAS_NUM_THREADS=1 for a one-core comparison (set here when the symbol is available).
//
// Example runs (only built when Siconos numerics / Bullet are installed, so not in tests/sample_runs.py):
//   OPENBLAS_NUM_THREADS=1 lcpcompare -family random_box -n 100 -count 200 -output compare.h5
//   OPENBLAS_NUM_THREADS=1 lcpcompare -family random_spd -n 50 -count 100 -ours bpp,lemke,pgs -output compare_spd.h5
#include "core/log.hpp"
#include "core/named_choice.hpp"
#include "core/clocks.hpp"
#include "core/option_value.hpp"
#include "core/resource_checks.hpp"
#include "core/run_context.hpp"
#include "core/run_summary.hpp"
#include "io/h5_output.hpp"
#include "lcp/generators.hpp"
#include "lcp/solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#ifdef LCPCOMPARE_SICONOS
#define restrict __restrict
#include "LCP_Solvers.h"
#include "LinearComplementarityProblem.h"
#include "NonSmoothDrivers.h"
#include "NumericsMatrix.h"
#include "RelayProblem.h"
#include "Relay_Solvers.h"
#include "SolverOptions.h"
#include "lcp_cst.h"
#include "relay_cst.h"
#undef restrict
#endif
#ifdef LCPCOMPARE_BULLET
#include <BulletDynamics/MLCPSolvers/btDantzigLCP.h>
#endif

extern "C" void openblas_set_num_threads(int) __attribute__((weak));

using namespace suite::lcp;

namespace {

struct Outcome {
  int status = 0; // Status codes of solver.hpp (4 = unsupported)
  double cpu = 0.0, residual = kInf;
};

// Judges z by the suite's rule; solver_ok: the external solver's own success flag.
Outcome judge(const Problem& p, const Vec& z, bool solver_ok, double cpu, double rel_tol) {
  Outcome o{0, cpu, kInf};
  if (z.size() == p.size() && z.allFinite()) o.residual = naturalResidual(p, z, slack(p, z));
  if (!(o.residual <= acceptanceTolerance(p, rel_tol)))
    o.status = static_cast<int>(solver_ok ? Status::NotAccepted : Status::Breakdown);
  return o;
}

struct Entry {
  std::string name;
  std::function<Outcome(const Problem&)> run;
  std::vector<int> status = {}; // per problem, filled by runAll
  std::vector<double> cpu = {}, resid = {};
  long long warmup_solves = 0; // untimed solves before the timed ones (runAll)
};

struct Options {
  std::string family = "random_box", output;
  std::vector<std::string> ours = {"bpp", "lemke", "keller", "pgs", "fb_newton"};
  PetscInt n = 100, count = 200, seed = 1, max_it = 0, warmup = 1;
  PetscReal cond = 1e4, qrange = 1e2, rel_tol = 1e-10;
};

// The dense n x n problem within PetscInt, and the memory: one problem at a time with its dense workspace
// (~6 n^2 doubles, as lcpbench) and the per-problem results of every solver (status, CPU time, residual).
PetscErrorCode checkSizes(MPI_Comm comm, const Options& o) {
  const double n = (double)o.n, results = 24.0 * (double)o.count * (o.ours.size() + 3.0);
  char what[96];
  PetscFunctionBeginUser;
  std::snprintf(what, sizeof what, "-n %lld", (long long)o.n);
  PetscCall(suite::checkIndexCount(comm, n * n, "entries of the dense problem matrix", what));
  std::snprintf(what, sizeof what, "-n %lld -count %lld", (long long)o.n, (long long)o.count);
  PetscCall(suite::checkMemoryEstimate(comm, 5e7 + 48.0 * n * n + results, what));
  PetscFunctionReturn(0);
}

// Reads and validates the options; *help_only: -help was given.
PetscErrorCode readOptions(const suite::RunContext& ctx, Options* o, bool* help_only) {
  MPI_Comm comm = ctx.comm();
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "lcpcompare options", "");
  PetscOptionItems* const po = PetscOptionsObject;
  PetscCall(
      suite::optionsChoice(po, "-family", "Problem family", suite::choicesOf(familyRegistry()), &o->family));
  PetscCall(suite::optionsValue(po, "-n", "Problem size", &o->n));
  PetscCall(suite::optionsValue(po, "-count", "Number of problems", &o->count));
  PetscCall(suite::optionsValue(po, "-seed", "Generator seed (same problems as lcpbench -seed)", &o->seed));
  PetscCall(suite::optionsValue(po, "-cond", "Condition number of M", &o->cond));
  PetscCall(
      suite::optionsValue(po, "-qrange", "q uniform in [-qrange, qrange]; box bounds +-qrange", &o->qrange));
  PetscCall(suite::optionsChoiceList(po, "-ours", "The suite's solvers to time",
                                     suite::choicesOf(solverRegistry()), &o->ours));
  PetscCall(
      suite::optionsValue(po, "-max_it", "Iteration cap of the iterative solvers (0: defaults)", &o->max_it));
  PetscCall(
      suite::optionsValue(po, "-rel_tol", "Acceptance: residual <= rel_tol (1 + |q|_inf)", &o->rel_tol));
  PetscCall(
      suite::optionsValue(po, "-warmup",
                          "Untimed solves of the first problems by every solver before timing (the same "
                          "count for every solver)",
                          &o->warmup));
  PetscCall(suite::optionsString(po, "-output", "HDF5 results file", &o->output));
  PetscOptionsEnd();
  PetscCall(ctx.checkUnusedOptions());
  *help_only = ctx.helpRequested();
  if (*help_only) PetscFunctionReturn(0);
  PetscCheck(ctx.size() == 1, comm, PETSC_ERR_ARG_WRONG, "lcpcompare times one core: run it on one rank");
  for (const char* name : {"-n", "-count", "-seed", "-max_it", "-warmup"})
    PetscCall(suite::checkIntOptionRange(comm, name, 0));
  PetscCheck(o->n >= 1 && o->count >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-n and -count must be >= 1");
  PetscCall(checkSizes(comm, *o));
  // The same ranges as lcpbench (a condition number below 1 makes a matrix the Siconos solvers assert on).
  PetscCheck(o->cond >= 1.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-cond %g: must be >= 1", (double)o->cond);
  PetscCheck(o->qrange >= 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-qrange %g: must be >= 0", (double)o->qrange);
  PetscCheck(o->max_it >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-max_it %d: must be >= 0", (int)o->max_it);
  PetscCheck(o->warmup >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-warmup %d: must be >= 0", (int)o->warmup);
  PetscCheck(o->rel_tol > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-rel_tol %g: must be > 0",
             (double)o->rel_tol);
  if (!o->output.empty()) PetscCall(suite::checkOutputWritable(comm, o->output.c_str(), "output"));
  PetscFunctionReturn(0);
}

// The suite's solver s (known: -ours is validated against the registry).
Entry oursEntry(const std::string& s, const suite::lcp::SolverOptions& so) {
  return {s, [solver = std::shared_ptr<const Solver>(makeSolver(s)), so](const Problem& p) {
            const Result r = solve(*solver, p, so);
            return Outcome{static_cast<int>(r.status), r.cpu_time, r.residual};
          }};
}

#ifdef LCPCOMPARE_SICONOS
// Siconos: standard LCP -> lcp_* solvers; box -> relay_* (relay_id < 0: no box version).
Entry siconosEntry(const std::string& name, int lcp_id, int relay_id, const Options& o) {
  return {name, [=, max_it = o.max_it, rel_tol = o.rel_tol](const Problem& p) -> Outcome {
            const int m = p.size();
            const bool box = !p.isStandard();
            if (box && relay_id < 0) return Outcome{static_cast<int>(Status::Unsupported), 0.0, kInf};
            NumericsMatrix* M = NM_create(NM_DENSE, m, m);
            std::copy(p.M.data(), p.M.data() + static_cast<size_t>(m) * m, M->matrix0); // column-major both
            std::vector<double> q(p.q.data(), p.q.data() + m), lb(p.l.data(), p.l.data() + m),
                ub(p.u.data(), p.u.data() + m), z(m, 0.0), w(m, 0.0);
            ::SolverOptions* opt = solver_options_create(box ? relay_id : lcp_id);
            if (max_it > 0) opt->iparam[SICONOS_IPARAM_MAX_ITER] = static_cast<int>(max_it);
            opt->dparam[SICONOS_DPARAM_TOL] = 1e-12;
            int info = 0;
            const double t0 = suite::threadCpuSeconds();
            if (box) {
              RelayProblem rp{m, M, q.data(), lb.data(), ub.data()};
              info = relay_driver(&rp, z.data(), w.data(), opt);
            } else {
              LinearComplementarityProblem lp{m, M, q.data()};
              info = linearComplementarity_driver(&lp, z.data(), w.data(), opt);
            }
            const double cpu = suite::threadCpuSeconds() - t0;
            solver_options_delete(opt);
            NM_free(M);
            return judge(p, Eigen::Map<Vec>(z.data(), m), info == 0, cpu, rel_tol);
          }};
}
#endif

#ifdef LCPCOMPARE_BULLET
// Bullet's btSolveDantzigLCP: A x = b + w, lo <= x <= hi, A row-major n x n (overwritten), so b = -q.
Outcome bulletDantzig(const Problem& p, double rel_tol) {
  const int m = p.size();
  for (int i = 0; i < m; ++i)
    if (p.l[i] > 0.0 || p.u[i] < 0.0) return Outcome{static_cast<int>(Status::Unsupported), 0.0, kInf};
  std::vector<btScalar> A(static_cast<size_t>(m) * m), b(m), x(m, 0.0), w(m, 0.0), lo(m), hi(m);
  std::vector<int> findex(m, -1);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) A[static_cast<size_t>(i) * m + j] = p.M(i, j);
    b[i] = -p.q[i];
    lo[i] = std::isfinite(p.l[i]) ? p.l[i] : -BT_INFINITY;
    hi[i] = std::isfinite(p.u[i]) ? p.u[i] : BT_INFINITY;
  }
  btDantzigScratchMemory scratch;
  const double t0 = suite::threadCpuSeconds();
  const bool ok = btSolveDantzigLCP(m, A.data(), x.data(), b.data(), w.data(), 0, lo.data(), hi.data(),
                                    findex.data(), scratch);
  const double cpu = suite::threadCpuSeconds() - t0;
  return judge(p, Eigen::Map<Vec>(x.data(), m), ok, cpu, rel_tol);
}
#endif

// Every solver timed: the suite's (-ours), then Siconos' and Bullet's where built.
std::vector<Entry> makeEntries(const Options& o) {
  suite::lcp::SolverOptions so;
  so.rel_tol = o.rel_tol;
  so.max_iterations = static_cast<int>(o.max_it);
  std::vector<Entry> entries;
  for (const auto& s : o.ours) entries.push_back(oursEntry(s, so));
#ifdef LCPCOMPARE_SICONOS
  entries.push_back(siconosEntry("siconos_lemke", SICONOS_LCP_LEMKE, SICONOS_RELAY_LEMKE, o));
  entries.push_back(siconosEntry("siconos_pgs", SICONOS_LCP_PGS, SICONOS_RELAY_PGS, o));
  entries.push_back(siconosEntry("siconos_fb_newton", SICONOS_LCP_NEWTON_FB_FBLSA, -1, o));
#endif
#ifdef LCPCOMPARE_BULLET
  entries.push_back(
      {"bullet_dantzig", [rel_tol = o.rel_tol](const Problem& p) { return bulletDantzig(p, rel_tol); }});
#endif
  return entries;
}

// The entry run j-th on problem k: the listed order rotated by k/2 (k even) or the reversed order rotated by k/2
// (k odd). A solve is faster right after some solvers' solves than after others' (their code and data still in
// the caches), so a fixed order would time each entry by its place in the list; this way every entry runs in
// every place and after every other entry alike (as lcpbench, lcpbench_batch.cpp).
size_t entryAt(size_t entries, PetscInt k, size_t j) {
  const size_t i = (j + static_cast<size_t>((k / 2) % static_cast<PetscInt>(entries))) % entries;
  return k % 2 == 0 ? i : entries - 1 - i;
}

// Every problem, solved by every entry, after the same untimed warm-up of every entry: the first -warmup
// problems solved once each, results discarded (the first touch of a solver's code and memory, paid by
// whichever solve comes first, would otherwise make the first entry look slower than when listed later).
void runAll(const Options& o, std::vector<Entry>* entries) {
  const GeneratorParams gp{
      static_cast<int>(o.n), o.cond, o.qrange, -o.qrange, o.qrange, static_cast<std::uint64_t>(o.seed)};
  const size_t E = entries->size();
  for (PetscInt k = 0; k < std::min(o.warmup, o.count); ++k) {
    const Problem p = generate(o.family, gp, static_cast<std::uint64_t>(k));
    for (size_t j = 0; j < E; ++j) {
      Entry& e = (*entries)[entryAt(E, k, j)];
      e.run(p);
      ++e.warmup_solves;
    }
  }
  for (PetscInt k = 0; k < o.count; ++k) {
    const Problem p = generate(o.family, gp, static_cast<std::uint64_t>(k));
    for (size_t j = 0; j < E; ++j) {
      Entry& e = (*entries)[entryAt(E, k, j)];
      const Outcome r = e.run(p);
      e.status.push_back(r.status);
      e.cpu.push_back(r.cpu);
      e.resid.push_back(r.residual);
    }
  }
}

PetscErrorCode writeHeader(const suite::RunContext& ctx, const Options& o, suite::H5Output* out) {
  PetscFunctionBeginUser;
  if (o.output.empty()) PetscFunctionReturn(0); // no -output: the table only
  PetscCall(out->open(ctx.comm(), o.output.c_str()));
  PetscCall(out->writeProvenance(ctx));
  PetscCall(out->writeAttribute("/", "status", "completed")); // written only when every solver ran
  PetscCall(out->writeAttribute("/", "family", o.family));
  PetscCall(out->writeAttribute("/", "n", (long long)o.n));
  PetscCall(out->writeAttribute("/", "count", (long long)o.count));
  PetscCall(out->writeAttribute("/", "cond", (double)o.cond));
  PetscCall(out->writeAttribute("/", "qrange", (double)o.qrange));
  PetscCall(out->writeAttribute("/", "seed", (long long)o.seed));
  PetscCall(
      out->writeAttribute("/", "timing",
                          "CPU seconds of the calling thread around the solver call, every solver after the "
                          "same untimed warm-up (/results/<solver> attribute warmup_solves)"));
  PetscCall(out->writeAttribute("/", "warmup", (long long)o.warmup));
  PetscFunctionReturn(0);
}

// Entry e's datasets and summary attributes, and its line of the table; ref: Bullet's Dantzig or nullptr.
PetscErrorCode writeEntry(const suite::RunContext& ctx, const Options& o, const Entry& e, const Entry* ref,
                          suite::H5Output* out) {
  const unsigned long long C = static_cast<unsigned long long>(o.count);
  const std::string g = "/results/" + e.name;
  auto total = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); };
  std::vector<double> c;
  PetscFunctionBeginUser;
  if (out->isOpen()) {
    PetscCall(out->writeReplicated(g + "/status", e.status.data(), {C}, ""));
    PetscCall(out->writeReplicated(g + "/cpu_time", e.cpu.data(), {C}, "s"));
    PetscCall(out->writeReplicated(g + "/residual", e.resid.data(), {C}, ""));
  }
  for (PetscInt k = 0; k < o.count; ++k)
    if (e.status[k] == 0) c.push_back(e.cpu[k]); // solved
  const long long solved = static_cast<long long>(c.size()),
                  unsupported =
                      std::count(e.status.begin(), e.status.end(), static_cast<int>(Status::Unsupported));
  std::sort(c.begin(), c.end());
  const double med = c.empty() ? std::nan("") : c[c.size() / 2];
  const double tot = total(e.cpu);
  const double rate = tot > 0 ? (o.count - unsupported) / tot : 0.0;
  const double ratio = ref && total(ref->cpu) > 0 && unsupported == 0 ? tot / total(ref->cpu) : std::nan("");
  if (out->isOpen()) {
    PetscCall(out->writeAttribute(g, "solved", solved));
    PetscCall(out->writeAttribute(g, "unsupported", unsupported));
    PetscCall(out->writeAttribute(g, "total_cpu_time", tot));
    PetscCall(out->writeAttribute(g, "problems_per_cpu_second", rate));
    PetscCall(out->writeAttribute(g, "cpu_time_over_bullet_dantzig", ratio));
    PetscCall(out->writeAttribute(g, "warmup_solves", e.warmup_solves));
  }
  PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(), "  %-18s %7lld %7lld %7lld %14.4g %14.1f %12.2f %8lld",
                           e.name.c_str(), solved, o.count - solved - unsupported, unsupported, med, rate,
                           ratio, e.warmup_solves));
  PetscFunctionReturn(0);
}

} // namespace

static PetscErrorCode runCompare(const suite::RunContext& ctx) {
  Options o;
  bool help_only = false;
  suite::H5Output out;
  PetscFunctionBeginUser;
  PetscCall(readOptions(ctx, &o, &help_only));
  if (help_only) PetscFunctionReturn(0);
  if (openblas_set_num_threads) openblas_set_num_threads(1);
  std::vector<Entry> entries = makeEntries(o);
  runAll(o, &entries);
  PetscCall(writeHeader(ctx, o, &out));
  const Entry* ref = nullptr; // reference for the ratio column: Bullet's Dantzig when present
  for (const Entry& e : entries)
    if (e.name == "bullet_dantzig") ref = &e;
  PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(), "lcpcompare: family %s, n = %d, %d problems, one core",
                           o.family.c_str(), (int)o.n, (int)o.count));
  PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(), "  %-18s %7s %7s %7s %14s %14s %12s %8s", "solver",
                           "solved", "failed", "unsupp", "median cpu [s]", "prob/cpu-s", "time/bullet",
                           "warm-up"));
  for (const Entry& e : entries) PetscCall(writeEntry(ctx, o, e, ref, &out));
  std::vector<std::string> written;
  if (out.isOpen()) {
    PetscCall(out.commit(&ctx));
    written.push_back(o.output);
  }
  PetscCall(suite::logRunSummary(ctx, "completed",
                                 std::to_string(entries.size()) + " solvers on " + std::to_string(o.count) +
                                     " problems of " + o.family + " (n = " + std::to_string(o.n) + ")",
                                 written));
  PetscFunctionReturn(0);
}

static const char help[] =
    "Times the suite's LCP solvers against Siconos numerics and Bullet's Dantzig solver.\n";

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, help, "lcpcompare");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(runCompare(ctx));
}
