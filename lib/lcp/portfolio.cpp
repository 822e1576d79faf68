// The LCP solver portfolio (see portfolio.hpp): the table's lookup, validation and HDF5 loader, and the auto
// solve (classify, try the class's chain with verification, stop at the first verified answer).
#include "lcp/portfolio.hpp"

#include "core/comma_list.hpp"
#include "io/h5_input.hpp"

#include <algorithm>
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
    if (ch.empty() || ch.size() > static_cast<size_t>(kAutoMaxTried))
      return "the chain of class '" + c + "' has " + std::to_string(ch.size()) + " solvers (must be 1 to " +
             std::to_string(kAutoMaxTried) + ")";
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
  const std::string why = validatePortfolio(*t);
  PetscCheck(why.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "-portfolio %s: %s", path.c_str(), why.c_str());
  PetscFunctionReturn(0);
}

Result solveAuto(const Problem& p, const AutoOptions& o, AutoInfo* info) {
  AutoInfo local;
  AutoInfo& in = info ? *info : local;
  const double t0 = MPI_Wtime();
  timespec c0{}, c1{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c0);
  const Portfolio& t = o.portfolio ? *o.portfolio : builtinPortfolio();
  in.features = classify(p);
  in.chain = t.chainFor(in.features.name());
  if (in.chain.size() > static_cast<size_t>(kAutoMaxTried)) in.chain.resize(kAutoMaxTried);
  ChainOptions co;
  co.rel_tol = o.rel_tol;
  co.first_max_iterations = o.max_iterations;
  co.make = o.make;
  co.timed = false; // timed here, once for the whole sequence
  Result r = solveWithChain(p, in.chain, co, &in.attempts);
  r.iterations = 0;
  r.pivots = 0;
  r.refinements = 0;
  for (const Attempt& a : in.attempts) {
    r.iterations += a.iterations;
    r.pivots += a.pivots;
    r.refinements += a.refinements;
  }
  in.solver = r.ok() ? in.attempts.back().solver : "";
  r.time = MPI_Wtime() - t0;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c1);
  r.cpu_time =
      static_cast<double>(c1.tv_sec - c0.tv_sec) + 1e-9 * static_cast<double>(c1.tv_nsec - c0.tv_nsec);
  return r;
}

} // namespace suite::lcp
