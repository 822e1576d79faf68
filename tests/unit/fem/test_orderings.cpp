// Orderings and solvers: Boost's Cuthill-McKee example (bandwidth 8 -> 4), a shuffled beam mesh (RCM
// bandwidth reduced >= 10x), auto keeping an optimal input order, RCM equal to SPARSEPAK's GENRCM (a small
// case worked by hand; PETSc's translation of SPARSEPAK on shuffled meshes), symbolic nnz(L) equal to CHOLMOD's
// analysis, auto no worse than the best of natural/rcm/amd/metis and naming the one it took, and skyline and
// CHOLMOD solutions agreeing on a beam stiffness matrix.
#include "fem_test_util.hpp"

#include "fem/linear_solver.hpp"
#include "fem/ordering.hpp"

#include <gtest/gtest.h>
#include <petscmat.h>

#include <algorithm>
#include <random>

using namespace suite::fem;

namespace {
Graph graphOfEdges(int n, const std::vector<std::pair<int, int>>& edges) {
  std::vector<std::vector<int>> nb(n);
  for (auto [a, b] : edges) nb[a].push_back(b), nb[b].push_back(a);
  Graph g;
  g.n = n;
  g.xadj.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    std::sort(nb[i].begin(), nb[i].end());
    g.adj.insert(g.adj.end(), nb[i].begin(), nb[i].end());
    g.xadj[i + 1] = static_cast<int>(g.adj.size());
  }
  return g;
}

TetMesh beam(int nx, int ny, int nz) {
  BeamSpec s;
  s.cells = {nx, ny, nz};
  return makeBeam(s);
}

Graph shuffledBeamGraph(int nx, int ny, int nz, unsigned seed) {
  TetMesh m = beam(nx, ny, nz);
  std::vector<int> p(m.numNodes());
  for (int i = 0; i < m.numNodes(); ++i) p[i] = i;
  std::mt19937 rng(seed);
  std::shuffle(p.begin(), p.end(), rng);
  for (auto& v : m.elems) v = p[v];
  auto nodes = m.nodes;
  for (int i = 0; i < m.numNodes(); ++i) m.nodes[p[i]] = nodes[i];
  Graph g;
  g.n = m.numNodes();
  nodeGraph(m, &g.xadj, &g.adj);
  return g;
}
// PETSc's MatGetOrdering "rcm" (its f2c translation of SPARSEPAK's GENRCM) on the graph's pattern.
std::vector<int> petscSparsepakRcm(const Graph& g) {
  Mat A;
  std::vector<int> nnz(g.n);
  for (int v = 0; v < g.n; ++v) nnz[v] = g.degree(v) + 1;
  MatCreateSeqAIJ(PETSC_COMM_SELF, g.n, g.n, 0, nnz.data(), &A);
  MatSetOption(A, MAT_USE_INODES, PETSC_FALSE); // order vertices, not inodes
  for (int v = 0; v < g.n; ++v) {
    MatSetValue(A, v, v, 1.0, INSERT_VALUES);
    for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k) MatSetValue(A, v, g.adj[k], 1.0, INSERT_VALUES);
  }
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  IS row, col;
  MatGetOrdering(A, MATORDERINGRCM, &row, &col);
  const PetscInt* idx;
  ISGetIndices(row, &idx);
  std::vector<int> p(idx, idx + g.n);
  ISRestoreIndices(row, &idx);
  ISDestroy(&row);
  ISDestroy(&col);
  MatDestroy(&A);
  return p;
}
} // namespace

// SPARSEPAK by hand on a 4-cycle 0-1-2-3 and a path 4-5-6. GENRCM starts at node 0: levels {0}, {1, 3}, {2};
// FNROOT's candidate 2 has no more levels and is the root returned; CM from 2 is 2, 1, 3 (equal degrees:
// node order), 0. The path from 4 is a chain (root 4), CM 4, 5, 6. Each component is reversed on its own.
TEST(FemOrdering, SparsepakGenrcmByHand) {
  const Graph g = graphOfEdges(7, {{0, 1}, {1, 2}, {2, 3}, {0, 3}, {4, 5}, {5, 6}});
  EXPECT_EQ(pseudoPeripheralNode(g, 0, std::vector<char>(7, 1)), 2);
  EXPECT_EQ(orderReverseCuthillMcKee(g), (std::vector<int>{0, 3, 1, 2, 6, 5, 4}));
  EXPECT_EQ(orderCuthillMcKee(g), (std::vector<int>{2, 1, 3, 0, 4, 5, 6}));
}

// Shuffled beams (one, and two interleaved with isolated vertices): the same permutation as PETSc's SPARSEPAK.
TEST(FemOrdering, RcmEqualsPetscSparsepak) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Graph g = shuffledBeamGraph(12 + 3 * seed, 3, 2, seed);
    EXPECT_EQ(orderReverseCuthillMcKee(g), petscSparsepakRcm(g)) << seed;
  }
  const Graph a = shuffledBeamGraph(9, 2, 2, 4), b = shuffledBeamGraph(7, 3, 2, 5);
  std::vector<std::pair<int, int>> e;
  for (int v = 0; v < a.n; ++v)
    for (int k = a.xadj[v]; k < a.xadj[v + 1]; ++k) e.push_back({2 * v, 2 * a.adj[k]});
  for (int v = 0; v < b.n; ++v)
    for (int k = b.xadj[v]; k < b.xadj[v + 1]; ++k) e.push_back({2 * v + 1, 2 * b.adj[k] + 1});
  std::vector<std::pair<int, int>> once;
  for (auto [x, y] : e)
    if (x < y) once.push_back({x, y});
  const int n = 2 * std::max(a.n, b.n) + 3; // odd or even ids beyond the smaller graph and 3 more: isolated
  const Graph g = graphOfEdges(n, once);
  const auto p = orderReverseCuthillMcKee(g);
  ASSERT_LT(profileOf(g, p), profileOf(g, orderNatural(g))); // a case where the order matters
  EXPECT_EQ(p, petscSparsepakRcm(g));
}

// Boost Graph Library example/cuthill_mckee_ordering.cpp: 10 vertices, 14 edges; original bandwidth 8, RCM 4.
TEST(FemOrdering, BoostExampleBandwidth) {
  const Graph g = graphOfEdges(10, {{0, 3},
                                    {0, 5},
                                    {1, 2},
                                    {1, 4},
                                    {1, 6},
                                    {1, 9},
                                    {2, 3},
                                    {2, 4},
                                    {3, 5},
                                    {3, 8},
                                    {4, 6},
                                    {5, 6},
                                    {5, 7},
                                    {6, 7}});
  EXPECT_EQ(bandwidthOf(g, orderNatural(g)), 8);
  const auto rcm = orderReverseCuthillMcKee(g);
  ASSERT_TRUE(isPermutation(rcm, 10));
  EXPECT_EQ(bandwidthOf(g, rcm), 4);
  EXPECT_LE(bandwidthOf(g, orderCuthillMcKee(g)), 4);
}

TEST(FemOrdering, ShuffledBeamBandwidthReducedTenfold) {
  const Graph g = shuffledBeamGraph(60, 4, 4, 12345);
  const long long b0 = bandwidthOf(g, orderNatural(g));
  const long long b1 = bandwidthOf(g, orderReverseCuthillMcKee(g));
  EXPECT_GE(b0, 10 * b1) << "shuffled " << b0 << " rcm " << b1;
  // The cross-section of 5x5 nodes bounds the achievable bandwidth from below (about 2 layers).
  EXPECT_LE(b1, 60);
}

// Where the input order is already optimal, auto keeps it (takes natural on ties) and RCM finds an order as
// good.
TEST(FemOrdering, AutoKeepsAnOptimalInputOrder) {
  // A path 0-1-...-9 with a chord (0,2): natural is optimal (no fill: nnz(L) = the 10 edges).
  std::vector<std::pair<int, int>> e;
  for (int i = 0; i < 9; ++i) e.push_back({i, i + 1});
  e.push_back({0, 2});
  const Graph g = graphOfEdges(10, e);
  for (OrderingFn fn : {orderCuthillMcKee, orderReverseCuthillMcKee})
    EXPECT_LE(profileOf(g, fn(g)), profileOf(g, orderNatural(g)));
  EXPECT_EQ(chooseOrdering(g).name, "natural");
  // Structured beam numbered x fastest is already banded; RCM must not make the profile worse.
  const TetMesh m = beam(10, 3, 3);
  Graph gb;
  gb.n = m.numNodes();
  nodeGraph(m, &gb.xadj, &gb.adj);
  EXPECT_LE(profileOf(gb, orderReverseCuthillMcKee(gb)), profileOf(gb, orderNatural(gb)));
}

TEST(FemOrdering, PermutationsSymbolicCountsAndAuto) {
  const TetMesh m = beam(12, 3, 3);
  auto mat = makeLinearMaterial({576.9, 384.6});
  std::vector<char> fixed(3 * m.numNodes(), 0);
  for (int v : nodesOnPlane(m, 0, 0.0))
    for (int c = 0; c < 3; ++c) fixed[3 * v + c] = 1;
  ElasticModel model;
  ASSERT_EQ(model.setup(PETSC_COMM_SELF, m, *mat, fixed), 0);
  SymCsc K = model.pattern();
  std::vector<double> f(model.numFree()), u(3 * m.numNodes(), 0.0);
  model.assemble(u.data(), f.data(), &K.val);
  const Graph g = graphOfMatrix(K);
  long long best = -1;
  for (const auto& name : orderingNames()) {
    OrderingFn fn;
    ASSERT_EQ(findOrdering(PETSC_COMM_SELF, name, &fn), 0);
    const auto p = fn(g);
    ASSERT_TRUE(isPermutation(p, g.n)) << name;
    const OrderingMetrics met = computeMetrics(g, p);
    auto chol = makeCholmodSolver();
    ASSERT_EQ(chol->analyze(PETSC_COMM_SELF, K, p), 0);
    EXPECT_EQ(met.nnz_L, chol->stats().nnz_L) << name;
    EXPECT_LE(met.nnz_L, met.profile + g.n) << name; // fill stays inside the envelope
    if (name == "natural" || name == "rcm" || name == "amd" || name == "metis")
      best = best < 0 ? met.nnz_L : std::min(best, met.nnz_L);
    if (name == "auto") {
      EXPECT_EQ(met.nnz_L, best);
      const OrderingChoice c = chooseOrdering(g);
      OrderingFn taken;
      ASSERT_EQ(findOrdering(PETSC_COMM_SELF, c.name, &taken), 0);
      EXPECT_EQ(c.perm, taken(g)) << c.name; // the name auto reports is the ordering it took
    }
    // Skyline, banded (LAPACK) and CHOLMOD agree and solve K x = b.
    auto sky = makeSkylineSolver(), band = makeBandedSolver();
    ASSERT_EQ(sky->analyze(PETSC_COMM_SELF, K, p), 0);
    ASSERT_EQ(band->analyze(PETSC_COMM_SELF, K, p), 0);
    EXPECT_EQ(sky->stats().nnz_L, met.profile + g.n) << name; // envelope storage
    bool ok1, ok2, ok3;
    ASSERT_EQ(sky->factor(K, &ok1), 0);
    ASSERT_EQ(chol->factor(K, &ok2), 0);
    ASSERT_EQ(band->factor(K, &ok3), 0);
    ASSERT_TRUE(ok1 && ok2 && ok3);
    std::vector<double> b(g.n), x1(g.n), x2(g.n), x3(g.n), r(g.n);
    for (int i = 0; i < g.n; ++i) b[i] = std::sin(0.37 * i);
    ASSERT_EQ(sky->solve(b.data(), x1.data()), 0);
    ASSERT_EQ(chol->solve(b.data(), x2.data()), 0);
    ASSERT_EQ(band->solve(b.data(), x3.data()), 0);
    for (int i = 0; i < g.n; ++i) x2[i] = std::abs(x2[i] - x1[i]) > std::abs(x3[i] - x1[i]) ? x2[i] : x3[i];
    symMultiply(K, K.val, x1.data(), r.data());
    double res = 0, diff = 0, xn = 0;
    for (int i = 0; i < g.n; ++i)
      res = std::max(res, std::abs(r[i] - b[i])), diff = std::max(diff, std::abs(x1[i] - x2[i])),
      xn = std::max(xn, std::abs(x1[i]));
    EXPECT_LT(res, 1e-10) << name;
    EXPECT_LT(diff, 1e-9 * xn) << name;
    // The PETSc path (one rank here; default KSP: MUMPS Cholesky, or CG + GAMG) gives the same solution.
    auto pet = makePetscSolver();
    ASSERT_EQ(pet->setFromOptions(PETSC_COMM_SELF), 0);
    pet->setNodeGraph(model.nodeGraphOf(), model.eq());
    ASSERT_EQ(pet->analyze(PETSC_COMM_SELF, K, p), 0);
    bool ok4;
    ASSERT_EQ(pet->factor(K, &ok4), 0);
    ASSERT_TRUE(ok4);
    std::vector<double> x4(g.n);
    ASSERT_EQ(pet->solve(b.data(), x4.data()), 0);
    double d4 = 0;
    for (int i = 0; i < g.n; ++i) d4 = std::max(d4, std::abs(x4[i] - x1[i]));
    EXPECT_LT(d4, 1e-6 * xn) << name;
  }
}

TEST(FemOrdering, NodeOrderExpandsToDofs) {
  const std::vector<int> eq = {0, 1, 2, -1, -1, -1, 3, 4, 5};
  EXPECT_EQ(expandToDofs({2, 0, 1}, eq, 6), (std::vector<int>{3, 4, 5, 0, 1, 2}));
}

// Several components and isolated vertices: a permutation, each component numbered contiguously, never worse
// than the input order by profileOf.
TEST(FemOrdering, ComponentsAndIsolatedVertices) {
  const Graph a = shuffledBeamGraph(20, 2, 2, 7), b = shuffledBeamGraph(12, 3, 2, 9);
  std::vector<std::pair<int, int>> e;
  const int na = a.n, nb = b.n, niso = 3, n = na + nb + niso;
  // Interleave: vertex ids of a are even-ish, b odd-ish, isolated ones at the end.
  std::vector<int> ida(na), idb(nb);
  int next = 0, ia = 0, ib = 0;
  while (ia < na || ib < nb) {
    if (ia < na) ida[ia++] = next++;
    if (ib < nb) idb[ib++] = next++;
  }
  for (int v = 0; v < na; ++v)
    for (int k = a.xadj[v]; k < a.xadj[v + 1]; ++k)
      if (v < a.adj[k]) e.push_back({ida[v], ida[a.adj[k]]});
  for (int v = 0; v < nb; ++v)
    for (int k = b.xadj[v]; k < b.xadj[v + 1]; ++k)
      if (v < b.adj[k]) e.push_back({idb[v], idb[b.adj[k]]});
  const Graph g = graphOfEdges(n, e);
  for (OrderingFn fn : {orderCuthillMcKee, orderReverseCuthillMcKee}) {
    const auto p = fn(g);
    ASSERT_TRUE(isPermutation(p, n));
    EXPECT_LE(profileOf(g, p), profileOf(g, orderNatural(g)));
    // Components contiguous: the component label changes at most (components - 1) times along the order.
    std::vector<int> comp(n, 2);
    for (int v : ida) comp[v] = 0;
    for (int v : idb) comp[v] = 1;
    int changes = 0;
    for (int i = 1; i < n; ++i)
      changes += comp[p[i]] != comp[p[i - 1]] && !(comp[p[i]] == 2 && comp[p[i - 1]] == 2);
    EXPECT_LE(changes, 4); // a, b and the three isolated vertices in some order
  }
  // The shuffled, interleaved input is far from banded; RCM of the union is banded like its components.
  const long long bu = bandwidthOf(g, orderReverseCuthillMcKee(g));
  EXPECT_LE(5 * bu, bandwidthOf(g, orderNatural(g)));
  EXPECT_LE(bu, 2 * std::max(bandwidthOf(a, orderReverseCuthillMcKee(a)),
                             bandwidthOf(b, orderReverseCuthillMcKee(b))));
}

// George & Liu's pseudo-peripheral node on a masked path 0-1-...-9 without vertex 9: an end of 0..8.
TEST(FemOrdering, PseudoPeripheralNodeRespectsMask) {
  std::vector<std::pair<int, int>> e;
  for (int i = 0; i < 9; ++i) e.push_back({i, i + 1});
  const Graph g = graphOfEdges(10, e);
  std::vector<char> mask(10, 1);
  mask[9] = 0;
  const int r = pseudoPeripheralNode(g, 4, mask);
  EXPECT_TRUE(r == 0 || r == 8) << r;
  mask.assign(10, 1);
  const int r2 = pseudoPeripheralNode(g, 4, mask);
  EXPECT_TRUE(r2 == 0 || r2 == 9) << r2;
}
