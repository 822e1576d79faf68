// FEM kernel benchmark (not a test): CPU time of the calling thread per call of the pieces of a full Newton
// step -- internal force only, force + tangent, numeric factorisation per solver, one solve -- on the benchmark
// meshes of scripts/bench/fem-rate, and the RCM ordering time against DOFs (node graph, expanded to DOFs).
// Run with OPENBLAS_NUM_THREADS=1 for one-core numbers.
// Usage: bench_fem [beam5k|block|beam1k|rcm|all]
#include "fem/assembly.hpp"
#include "core/clocks.hpp"
#include "fem/linear_solver.hpp"
#include "fem/material.hpp"
#include "fem/mesh.hpp"
#include "fem/ordering.hpp"

#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>

using namespace suite::fem;

namespace {

// Minimum CPU time of one call over repetitions for 0.5 s (on a loaded machine the minimum is the least
// disturbed measurement), in ms; *wall_ms: the minimum wall time of one call (work in other threads or waits
// show as wall > CPU).
double timeit(const std::function<void()>& f, double* wall_ms = nullptr) {
  f(); // warm up
  double best = 1e300, best_wall = 1e300;
  const double t0 = suite::threadCpuSeconds();
  do {
    const double t = suite::threadCpuSeconds(), w = suite::wallSeconds();
    f();
    best = std::min(best, suite::threadCpuSeconds() - t);
    best_wall = std::min(best_wall, suite::wallSeconds() - w);
  } while (suite::threadCpuSeconds() - t0 < 0.5);
  if (wall_ms) *wall_ms = 1e3 * best_wall;
  return 1e3 * best;
}

// Flops per P1 element and quadrature point of the element kernels, counted from the code of lib/fem
// (multiply-adds as 2): F = I + sum u (x) g (72), StVK E, S, P (~120), f_e (72); the closed-form tangent
// (addStVKElementTangent: F g, S g 120, F F^T 45, 10 node pairs x up to 9 entries x 13) and its scatter (78).
// The corotational force adds the polar iteration (~4 iterations x ~110) and U, eps, P (~110).
constexpr double kStvkForceFlops = 264, kTangentFlops = 120 + 45 + 10 * 9 * 13 + 78, kPolarFlops = 550;

void kernels(const char* label, std::array<int, 3> cells, double length) {
  BeamSpec s;
  s.length = length;
  s.cells = cells;
  const TetMesh mesh = makeBeam(s);
  Lame lame;
  lameFromYoung(PETSC_COMM_SELF, 1000, 0.3, &lame);
  auto mat = makeStVenantKirchhoff(lame), corot = makeCorotational(lame);
  std::vector<char> fixed(3 * mesh.numNodes(), 0);
  for (int v : nodesOnPlane(mesh, 0, 0.0))
    for (int c = 0; c < 3; ++c) fixed[3 * v + c] = 1;
  ElasticModel model, model_corot;
  model.setup(PETSC_COMM_SELF, mesh, *mat, fixed);
  model_corot.setup(PETSC_COMM_SELF, mesh, *corot, fixed);
  const int n = model.numFree();
  std::vector<double> u(n), f(n), K, Kc;
  for (int i = 0; i < n; ++i) u[i] = 1e-3 * std::sin(0.1 * i);
  const double tf = timeit([&] { model.internalForce(u.data(), f.data(), nullptr, nullptr); });
  const double tk = timeit([&] { model.internalForce(u.data(), f.data(), &K, nullptr); });
  const double cf = timeit([&] { model_corot.internalForce(u.data(), f.data(), nullptr, nullptr); });
  const double ck = timeit([&] { model_corot.internalForce(u.data(), f.data(), &Kc, nullptr); });
  const double ne = mesh.numElems();
  std::printf(
      "%s: %d tets, %d DOFs: internal force %.3f ms (%.2f GFlop/s), force + tangent %.3f ms (%.2f "
      "GFlop/s); corotational: force %.3f ms (%.2f GFlop/s), force + tangent %.3f ms (%.2f GFlop/s)\n",
      label, mesh.numElems(), n, tf, ne * kStvkForceFlops / tf * 1e-6, tk,
      ne * (kStvkForceFlops + kTangentFlops) / tk * 1e-6, cf,
      ne * (kStvkForceFlops + kPolarFlops) / cf * 1e-6, ck,
      ne * (kStvkForceFlops + kPolarFlops + kTangentFlops) / ck * 1e-6);
  const auto M = model.consistentMass(1.0);
  SymCsc A = model.pattern();
  for (size_t k = 0; k < A.val.size(); ++k) A.val[k] = K[k] + 1e4 * M[k];
  // "cholmod+omp": CHOLMOD with its OpenMP loops on (-cholmod_openmp), beside the default (off).
  for (const auto& [ord, solver] :
       {std::make_pair("rcm", "banded"), std::make_pair("rcm", "skyline"), std::make_pair("rcm", "cholmod"),
        std::make_pair("amd", "cholmod"), std::make_pair("metis", "cholmod"),
        std::make_pair("metis", "cholmod+omp")}) {
    OrderingFn fn;
    findOrdering(PETSC_COMM_SELF, ord, &fn);
    const auto perm = expandToDofs(fn(model.nodeGraphOf()), model.eq(), n);
    std::unique_ptr<LinearSolver> ls;
    const bool omp = std::strcmp(solver, "cholmod+omp") == 0;
    createLinearSolver(PETSC_COMM_SELF, omp ? "cholmod" : solver, &ls);
    PetscOptionsSetValue(nullptr, "-cholmod_openmp", omp ? "true" : "false");
    ls->setFromOptions(PETSC_COMM_SELF);
    PetscOptionsClearValue(nullptr, "-cholmod_openmp");
    ls->analyze(PETSC_COMM_SELF, A, perm);
    bool ok;
    double wfac, wsol;
    const double tfac = timeit([&] { ls->factor(A, &ok); }, &wfac);
    std::vector<double> x(n);
    const double tsol = timeit([&] { ls->solve(f.data(), x.data()); }, &wsol);
    std::printf(
        "  %s/%s: factor %.3f ms (wall %.3f), solve %.3f ms (wall %.3f) (nnz(L) %lld, %.3g flops: %.1f "
        "GFlop/s)\n",
        ord, solver, tfac, wfac, tsol, wsol, ls->stats().nnz_L, ls->stats().flops,
        ls->stats().flops / tfac * 1e-6);
  }
}

void rcmScaling() {
  for (const auto& c : {std::array<int, 3>{55, 5, 5}, std::array<int, 3>{110, 10, 10},
                        std::array<int, 3>{23, 23, 23}, std::array<int, 3>{220, 14, 14}}) {
    BeamSpec s;
    s.cells = c;
    const TetMesh mesh = makeBeam(s);
    Graph g;
    nodeGraph(mesh, &g.xadj, &g.adj);
    g.n = mesh.numNodes();
    std::vector<int> eq(3 * g.n);
    for (int i = 0; i < 3 * g.n; ++i) eq[i] = i;
    const double t = timeit([&] { expandToDofs(orderReverseCuthillMcKee(g), eq, 3 * g.n); });
    std::printf("RCM %dx%dx%d: %d DOFs, node graph nnz %zu: %.3f ms (node graph, expanded to DOFs), %.2f ns "
                "per graph entry\n",
                c[0], c[1], c[2], 3 * g.n, g.adj.size(), t, 1e6 * t / (double)g.adj.size());
  }
}

} // namespace

int main(int argc, char** argv) {
  PetscInitializeNoArguments();
  const std::string what = argc > 1 ? argv[1] : "all";
  if (what == "beam1k" || what == "all") kernels("beam-1k 37x2x2", {37, 2, 2}, 18.5);
  if (what == "beam5k" || what == "all") kernels("beam-5k 104x3x3", {104, 3, 3}, 104 / 3.0);
  if (what == "block" || what == "all") kernels("block-5k 20x8x8", {20, 8, 8}, 2.5);
  if (what == "rcm" || what == "all") rcmScaling();
  PetscFinalize();
  return 0;
}
