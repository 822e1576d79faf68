// Registry of the LCP solvers by name: one line per solver (the factories live in solvers/*.cpp).
#include "lcp/solver.hpp"

#include <functional>
#include <utility>

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
const std::vector<std::pair<std::string, std::function<std::unique_ptr<Solver>()>>>& table() {
  static const std::vector<std::pair<std::string, std::function<std::unique_ptr<Solver>()>>> t = {
      {"lemke", makeLemke},
      {"keller", makeKeller},
      {"cottle_dantzig", makeCottleDantzig},
      {"murty", makeMurty},
      {"bpp", makeBpp},
      {"fb_newton", makeFbNewton},
      {"smoothed_newton", makeSmoothedNewton},
      {"pgs", makePgs},
      {"pgs_block", makePgsBlock},
      {"petsc_ssls", makePetscSsls},
      {"petsc_rsls", makePetscRsls},
  };
  return t;
}
} // namespace

std::vector<std::string> solverNames() {
  std::vector<std::string> v;
  for (const auto& e : table()) v.push_back(e.first);
  return v;
}

std::unique_ptr<Solver> makeSolver(const std::string& name) {
  for (const auto& e : table())
    if (e.first == name) return e.second();
  return nullptr;
}

} // namespace suite::lcp
