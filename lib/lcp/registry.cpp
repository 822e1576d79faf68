// Registry of the LCP solvers by name: one line per solver with its one-line description (the factories live
// in solvers/*.cpp).
#include "lcp/solver.hpp"

namespace suite::lcp {

std::unique_ptr<Solver> makeLemke();
std::unique_ptr<Solver> makeKeller();
std::unique_ptr<Solver> makeCottleDantzig();
std::unique_ptr<Solver> makeMurty();
std::unique_ptr<Solver> makeBpp();
std::unique_ptr<Solver> makeFbNewton();
std::unique_ptr<Solver> makeSmoothedNewton();
std::unique_ptr<Solver> makePgs();
std::unique_ptr<Solver> makePgsBlock();
std::unique_ptr<Solver> makePetscSsls();
std::unique_ptr<Solver> makePetscRsls();

namespace {
struct Entry {
  const char* name;
  const char* description; // one line, shown by -help of the apps that offer the solvers
  std::unique_ptr<Solver> (*make)();
};

const std::vector<Entry>& table() {
  static const std::vector<Entry> t = {
      {"lemke", "Lemke's complementary pivoting, lexicographic ratio test (box/MLCP via reformulation)",
       makeLemke},
      {"keller", "Keller's principal pivoting for box LCPs (rank-1 LDL^T updates for symmetric M)",
       makeKeller},
      {"cottle_dantzig", "Cottle-Dantzig principal pivoting (box/MLCP via reformulation)", makeCottleDantzig},
      {"murty", "Murty's least-index principal pivoting, box form (finite for P-matrices)", makeMurty},
      {"bpp", "block principal pivoting (Kostreva) with the Judice-Pires safeguard", makeBpp},
      {"fb_newton", "semismooth Newton on the Fischer-Burmeister function, Armijo line search", makeFbNewton},
      {"smoothed_newton", "smoothing Newton on the CHKS-smoothed natural map (Qi, Sun & Zhou)",
       makeSmoothedNewton},
      {"pgs", "projected Gauss-Seidel / SOR (relaxation omega; needs M_ii > 0)", makePgs},
      {"pgs_block", "block projected Gauss-Seidel, blocks of size b solved exactly", makePgsBlock},
      {"petsc_ssls", "PETSc SNESVINEWTONSSLS: semismooth VI Newton (reference)", makePetscSsls},
      {"petsc_rsls", "PETSc SNESVINEWTONRSLS: reduced-space active-set VI Newton (reference)", makePetscRsls},
  };
  return t;
}
} // namespace

std::vector<SolverInfo> solverRegistry() {
  std::vector<SolverInfo> v;
  for (const Entry& e : table()) v.push_back({e.name, e.description});
  return v;
}

std::vector<std::string> solverNames() {
  std::vector<std::string> v;
  for (const Entry& e : table()) v.push_back(e.name);
  return v;
}

std::unique_ptr<Solver> makeSolver(const std::string& name) {
  for (const Entry& e : table())
    if (e.name == name) return e.make();
  return nullptr;
}

const Solver* registeredSolver(const std::string& name) {
  static const std::vector<std::unique_ptr<Solver>> instances = [] {
    std::vector<std::unique_ptr<Solver>> v;
    for (const Entry& e : table()) v.push_back(e.make());
    return v;
  }();
  static const std::vector<std::string> names = solverNames(); // std::string == compares sizes first
  for (size_t i = 0; i < names.size(); ++i)
    if (name == names[i]) return instances[i].get();
  return nullptr;
}

} // namespace suite::lcp
