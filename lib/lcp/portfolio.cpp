// The LCP solver portfolio (see portfolio.hpp): the table's lookup, validation and HDF5 loader, and the auto
// solve (classify, try the class's chain with verification, stop at the first verified answer).
#include "lcp/portfolio.hpp"

#include "core/comma_list.hpp"
#include "io/h5_input.hpp"

#include <algorithm>
#include <array>
#include <ctime>
#include <set>

namespace suite::lcp {

const std::vector<std::string>& Portfolio::chainFor(const std::string& cls) const {
  static const std::vector<std::string> none;
  auto at = [&](const std::string& c) { return std::find(classes.begin(), classes.end(), c); };
  auto it = at(cls);
  if (it == classes.end()) it = at("default");
  return it == classes.end() ? none : chains[it - classes.begin()];
}

const std::vector<std::string>& Portfolio::chainFor(int class_index) const {
  const auto& names = problemClassNames();
  if (class_index < 0 || class_index >= static_cast<int>(names.size()))
    return chainFor(std::string("default"));
  if (rows.size() != names.size()) return chainFor(names[class_index]);
  const int r = rows[class_index];
  static const std::vector<std::string> none;
  return r < 0 ? none : chains[r];
}

void Portfolio::indexRows() {
  const auto& names = problemClassNames();
  const auto at = [&](const std::string& c) {
    const auto it = std::find(classes.begin(), classes.end(), c);
    return it == classes.end() ? -1 : static_cast<int>(it - classes.begin());
  };
  const int dflt = at("default");
  rows.assign(names.size(), dflt);
  for (size_t c = 0; c < names.size(); ++c)
    if (at(names[c]) >= 0) rows[c] = at(names[c]);
  solvers.assign(chains.size(), {});
  for (size_t r = 0; r < chains.size(); ++r)
    for (const std::string& s : chains[r]) solvers[r].push_back(registeredSolver(s));
}

const std::vector<const Solver*>* Portfolio::solversFor(int class_index) const {
  const auto& names = problemClassNames();
  if (rows.size() != names.size() || solvers.size() != chains.size() || class_index < 0 ||
      class_index >= static_cast<int>(names.size()) || rows[class_index] < 0)
    return nullptr;
  return &solvers[rows[class_index]];
}

bool Portfolio::has(const std::string& cls) const {
  return std::find(classes.begin(), classes.end(), cls) != classes.end();
}

std::string validatePortfolio(const Portfolio& t) {
  if (t.classes.size() != t.chains.size()) return "classes and chains differ in number";
  const std::vector<std::string> known = solverNames();
  std::set<std::string> seen;
  for (size_t i = 0; i < t.classes.size(); ++i) {
    const std::string& c = t.classes[i];
    if (c != "default" && problemClassIndex(c) < 0) return "unknown problem class '" + c + "'";
    if (!seen.insert(c).second) return "class '" + c + "' listed twice";
    const auto& ch = t.chains[i];
    if (ch.empty() || ch.size() > static_cast<size_t>(kChainMax))
      return "the chain of class '" + c + "' has " + std::to_string(ch.size()) + " solvers (must be 1 to " +
             std::to_string(kChainMax) + ")";
    for (size_t k = 0; k < ch.size(); ++k) {
      if (std::find(known.begin(), known.end(), ch[k]) == known.end())
        return "unknown solver '" + ch[k] + "' in the chain of class '" + c + "'";
      if (std::count(ch.begin(), ch.end(), ch[k]) > 1)
        return "solver '" + ch[k] + "' twice in the chain of class '" + c + "'";
    }
  }
  if (!seen.count("default")) return "no 'default' class (the chain of classes not in the table)";
  return "";
}

namespace {

// Reads a string attribute of the root, or errors naming it.
PetscErrorCode rootText(MPI_Comm comm, const H5Input& in, const char* name, std::string* v) {
  bool has = false;
  PetscFunctionBeginUser;
  PetscCall(in.hasAttribute("/", name, &has));
  PetscCheck(has, comm, PETSC_ERR_FILE_UNEXPECTED,
             "-portfolio %s: no root attribute '%s' (not a table written by scripts/bench/lcp-portfolio?)",
             in.path().c_str(), name);
  PetscCall(in.readAttribute("/", name, v));
  PetscFunctionReturn(0);
}

// The chains from /chain (classes x L solver indices, -1 padding).
PetscErrorCode readChains(MPI_Comm comm, const H5Input& in, const std::vector<std::string>& solvers,
                          Portfolio* t) {
  std::vector<long long> idx;
  Dims d;
  const char* f = in.path().c_str();
  PetscFunctionBeginUser;
  bool has = false;
  PetscCall(in.hasObject("/chain", &has));
  PetscCheck(has, comm, PETSC_ERR_FILE_UNEXPECTED, "-portfolio %s: no dataset /chain", f);
  PetscCall(in.datasetDims("/chain", &d));
  PetscCheck(d.size() == 2 && d[0] == t->classes.size() && d[1] >= 1, comm, PETSC_ERR_FILE_UNEXPECTED,
             "-portfolio %s: /chain must be %zu (classes) x L", f, t->classes.size());
  PetscCall(in.checkPlausibleSize("/chain", d, sizeof(long long)));
  PetscCall(in.readAll("/chain", &idx, &d));
  t->chains.assign(d[0], {});
  for (size_t i = 0; i < d[0]; ++i)
    for (size_t k = 0; k < d[1]; ++k) {
      const long long s = idx[i * d[1] + k];
      PetscCheck(s >= -1 && s < (long long)solvers.size(), comm, PETSC_ERR_FILE_UNEXPECTED,
                 "-portfolio %s: /chain[%zu][%zu] = %lld is not a solver index (0 to %zu, -1 = none)", f, i,
                 k, s, solvers.size() - 1);
      if (s >= 0) t->chains[i].push_back(solvers[s]);
    }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode loadPortfolio(MPI_Comm comm, const std::string& path, Portfolio* t) {
  H5Input in;
  std::string format, classes, solvers;
  PetscFunctionBeginUser;
  PetscCall(in.open(comm, path));
  PetscCall(rootText(comm, in, "format", &format));
  PetscCheck(format == "suite lcp portfolio 1", comm, PETSC_ERR_FILE_UNEXPECTED,
             "-portfolio %s: format '%s', expected 'suite lcp portfolio 1'", path.c_str(), format.c_str());
  PetscCall(rootText(comm, in, "classes", &classes));
  PetscCall(rootText(comm, in, "solvers", &solvers));
  t->classes = splitCommaList(classes);
  for (auto& c : t->classes) c.erase(0, c.find_first_not_of(' '));
  std::vector<std::string> names = splitCommaList(solvers);
  for (auto& s : names) s.erase(0, s.find_first_not_of(' '));
  PetscCall(readChains(comm, in, names, t));
  PetscCall(in.close());
  t->source = path;
  t->indexRows();
  const std::string why = validatePortfolio(*t);
  PetscCheck(why.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "-portfolio %s: %s", path.c_str(), why.c_str());
  PetscFunctionReturn(0);
}

namespace {

// CPU seconds of the calling thread.
double threadCpuSeconds() {
  timespec c{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c);
  return static_cast<double>(c.tv_sec) + 1e-9 * static_cast<double>(c.tv_nsec);
}

// The only attempt, r by the first solver of the chain, accepted.
void recordAccepted(const Result& r, const std::string& solver, std::vector<Attempt>* attempts) {
  attempts->assign(1, Attempt{});
  Attempt& a = attempts->front();
  a.solver = solver;
  a.accepted = true;
  a.status = r.status;
  a.residual = r.residual;
  a.message = r.message;
  a.iterations = r.iterations;
  a.pivots = r.pivots;
}

// Iteration, pivot and refinement counts summed over the attempts a[0, m).
void sumCounts(const Attempt* a, int m, Result* r) {
  r->iterations = 0;
  r->pivots = 0;
  r->refinements = 0;
  for (int k = 0; k < m; ++k) {
    r->iterations += a[k].iterations;
    r->pivots += a[k].pivots;
    r->refinements += a[k].refinements;
  }
}

// The completion's solver of each family, in the order they are tried (portfolio.hpp).
const std::array<std::pair<SolverFamily, std::string>, 3>& completionSolvers() {
  static const std::array<std::pair<SolverFamily, std::string>, 3> c = {
      {{SolverFamily::Newton, "smoothed_newton"},
       {SolverFamily::Pivoting, "lemke"},
       {SolverFamily::Iterative, "pgs"}}};
  return c;
}

// One solver of an auto run: its name and registered instance (nullptr: unknown or not indexed).
struct Step {
  const std::string* name = nullptr;
  const Solver* solver = nullptr;
};

// The solvers an auto run tries, in order, into out (returns how many, at most kAutoMaxTried): the first of
// the provisional class's chain (the minors test deferred, see solveAuto), then the final class's chain
// without it. Without a deferred test both classes are the same, and this is the class's chain.
int route(const Portfolio& t, int provisional, int final_class, Step* out) {
  const auto& first = t.chainFor(provisional);
  const auto& rest = t.chainFor(final_class);
  const auto* s0 = t.solversFor(provisional);
  const auto* s1 = t.solversFor(final_class);
  int m = 0;
  if (!first.empty()) out[m++] = {&first[0], s0 ? (*s0)[0] : nullptr};
  for (size_t k = 0; k < rest.size() && m < kChainMax; ++k)
    if (m == 0 || rest[k] != *out[0].name) out[m++] = {&rest[k], s1 ? (*s1)[k] : nullptr};
  const bool indexed = s0 && s1;
  for (const auto& [family, name] : completionSolvers()) { // the families the chain lacks
    bool has = false;
    for (int k = 0; k < m; ++k) has = has || solverFamily(*out[k].name) == family;
    if (!has && m < kAutoMaxTried) out[m++] = {&name, indexed ? registeredSolver(name) : nullptr};
  }
  return m;
}

// The names of route(t, provisional, final_class).
std::vector<std::string> routeNames(const Portfolio& t, int provisional, int final_class) {
  Step steps[kAutoMaxTried];
  const int m = route(t, provisional, final_class, steps);
  std::vector<std::string> names;
  for (int k = 0; k < m; ++k) names.push_back(*steps[k].name);
  return names;
}

// The chain's options of an auto run (timed once by solveAuto for the whole sequence, not per attempt).
ChainOptions chainOptions(const AutoOptions& o) {
  ChainOptions co;
  co.rel_tol = o.rel_tol;
  co.first_max_iterations = o.max_iterations;
  co.make = o.make;
  co.timed = false;
  return co;
}

// The route steps[0, m) after the first solver's answer r, which solve() did not accept: its refinement and
// acceptance (finishAttempt), then each next solver by attemptOn, until one is accepted.
Result runRest(const Problem& p, const Step* steps, int m, const ChainOptions& co, Result r,
               std::vector<Attempt>* attempts) {
  Attempt att[kAutoMaxTried];
  const double tol = acceptanceTolerance(p, co.rel_tol);
  int k = 0;
  for (; k < m; ++k) {
    att[k].known = steps[k].solver != nullptr;
    if (!att[k].known) continue;
    if (k == 0)
      finishAttempt(p, co, tol, &r, &att[0]);
    else
      r = attemptOn(*steps[k].solver, p, false, co, tol, &att[k]);
    if (att[k].accepted) break;
  }
  const int tried = std::min(k + 1, m);
  if (k < m)
    r.status = Status::Solved;
  else if (r.status == Status::Solved)
    r.status = Status::NotAccepted;
  if (attempts) {
    attempts->assign(att, att + tried);
    for (int j = 0; j < tried; ++j) (*attempts)[j].solver = *steps[j].name;
  }
  sumCounts(att, tried, &r);
  return r;
}

// The route of an indexed table (registered solvers; no factory; first: the provisional class's chain). The
// first solver runs through solve() directly: when solve() accepts its answer (residual <= the same
// tolerance, z finite), so would the chain, and nothing else is done (a whole solve of a 2 x 2 LCP takes
// ~0.1 us, of n = 10 ~0.5 us: the attempt records, options and refinement checks of the general path cost
// ~0.05 us more). Otherwise the deferred test is done (f completed), and the rest of the route tried.
Result runIndexed(const Problem& p, const Portfolio& t, const std::vector<const Solver*>& first,
                  const AutoOptions& o, ProblemFeatures* f, std::vector<Attempt>* attempts) {
  SolverOptions so;
  so.rel_tol = o.rel_tol;
  so.max_iterations = o.max_iterations;
  so.timed = false;
  Result r = first[0] ? solve(*first[0], p, so) : Result{};
  if (r.ok()) {
    r.refinements = 0; // as the general path counts them: those of the chain, after the method
    if (attempts) recordAccepted(r, t.chainFor(f->class_index)[0], attempts);
    return r;
  }
  const int provisional = f->class_index;
  if (f->minors_deferred) *f = classify(p);
  Step steps[kAutoMaxTried];
  const int m = route(t, provisional, f->class_index, steps);
  return runRest(p, steps, m, chainOptions(o), std::move(r), attempts);
}

} // namespace

// The per-problem cost next to the chain's solves is kept small (a solve of n = 10 takes ~0.3 to 0.5 us): the
// table indexed by class (no class name built), its solvers resolved once (runIndexed), the 2 x 2 minors test
// deferred, and info's copies made only when info is asked for.
//
// The deferred test: the minors test of classify() (O(n^2); at n = 100 to 300 about a fifth of bpp's time on a
// box LCP; at n = 10 ~30 of classify()'s 50 ns) decides only between spd and sym (pd and gen) once the matrix
// is neither dd nor tril / triu. The problem is classed spd / pd provisionally, and the first solver of that
// class's chain runs; only when its answer is not accepted is the test done, and the final class's chain tried
// without that solver (route). A verified answer of the first solver is an answer whatever the test would say;
// the class recorded in info is the final one. An indefinite matrix pays for one failed attempt where the
// first solver fails on it (lcp_CPS_1, symmetric indefinite, when lcp-spd-small starts with bpp).
SolverFamily solverFamily(const std::string& s) {
  if (s == "lemke" || s == "keller" || s == "cottle_dantzig" || s == "murty" || s == "bpp")
    return SolverFamily::Pivoting;
  if (s == "fb_newton" || s == "smoothed_newton" || s == "petsc_ssls" || s == "petsc_rsls")
    return SolverFamily::Newton;
  if (s == "pgs" || s == "pgs_block") return SolverFamily::Iterative;
  return SolverFamily::Other;
}

std::vector<std::string> completeFamilies(std::vector<std::string> chain) {
  for (const auto& [family, name] : completionSolvers()) {
    const bool has = std::any_of(chain.begin(), chain.end(),
                                 [&, fam = family](const std::string& s) { return solverFamily(s) == fam; });
    if (!has && chain.size() < static_cast<size_t>(kAutoMaxTried)) chain.push_back(name);
  }
  return chain;
}

Result solveAuto(const Problem& p, const AutoOptions& o, AutoInfo* info) {
  const double t0 = o.timed ? MPI_Wtime() : 0.0, c0 = o.timed ? threadCpuSeconds() : 0.0;
  const Portfolio& t = o.portfolio ? *o.portfolio : builtinPortfolio();
  ProblemFeatures f = classify(p, false, true);
  const int provisional = f.class_index; // f becomes the final class once the deferred test is done
  std::vector<Attempt>* att = info ? &info->attempts : nullptr;
  const std::vector<const Solver*>* first = o.make ? nullptr : t.solversFor(f.class_index);
  Result r;
  if (first && !first->empty()) {
    r = runIndexed(p, t, *first, o, &f, att);
  } else { // a table built by hand (not indexed) or a solver factory: the general chain, on the same route
    if (f.minors_deferred) f = classify(p);
    std::vector<Attempt> local;
    att = att ? att : &local;
    r = solveWithChain(p, routeNames(t, provisional, f.class_index), chainOptions(o), att);
    sumCounts(att->data(), static_cast<int>(att->size()), &r);
  }
  if (o.timed) {
    r.time = MPI_Wtime() - t0;
    r.cpu_time = threadCpuSeconds() - c0;
  }
  if (info) { // after the clocks: the record's classification is not part of the solve
    info->features = f.minors_deferred ? classify(p) : f;
    info->chain = routeNames(t, provisional, info->features.class_index);
    info->solver = r.ok() ? info->attempts.back().solver : "";
  }
  return r;
}

} // namespace suite::lcp
