// Unit tests of the LCP solver portfolio: the classifier on matrices of known type (SPD, symmetric indefinite,
// nonsymmetric positive definite, general, diagonally dominant; LCP, box, MLCP; size bands), the chain
// fallback (a problem the first solver of its chain fails and a later one solves: Siconos' lcp_CPS_4bis on
// which Lemke ray-terminates, and a cap of 1 pivot on the first solver), table validation, and the
// built-in table on the Siconos files: auto solves every file that some single solver solves.
#include "lcp/generators.hpp"
#include "lcp/portfolio.hpp"
#include "lcp/readers.hpp"

#include <gtest/gtest.h>

#include <dirent.h>

using namespace suite::lcp;

namespace {

Mat mat2(double a, double b, double c, double d) {
  Mat M(2, 2);
  M << a, b, c, d;
  return M;
}

std::string classOf(const Problem& p) {
  const std::string c = classify(p).name();
  EXPECT_GE(problemClassIndex(c), 0) << c;
  return c;
}

const std::string kSiconos = std::string(SUITE_DATA_DIR) + "/lcp";

} // namespace

TEST(ProblemClass, MatrixTypes) {
  const Vec q = Vec::Constant(2, -1.0);
  EXPECT_EQ(classOf(makeLcp(mat2(2, 1, 1, 2), q)), "lcp-dd-small");      // strictly dominant
  EXPECT_EQ(classOf(makeLcp(mat2(1, 1, 1, 2), q)), "lcp-spd-small");     // SPD, row 0 not strictly dominant
  EXPECT_EQ(classOf(makeLcp(mat2(1, 2, 2, 1), q)), "lcp-sym-small");     // eigenvalues 3, -1
  EXPECT_EQ(classOf(makeLcp(mat2(1, 0, 0, -1), q)), "lcp-sym-small");    // negative diagonal
  EXPECT_EQ(classOf(makeLcp(mat2(1, 1.5, -1.5, 1), q)), "lcp-pd-small"); // symmetric part I
  EXPECT_EQ(classOf(makeLcp(mat2(1, 3, 0.1, 1), q)), "lcp-gen-small");   // symmetric part indefinite
  const ProblemFeatures f = classify(makeLcp(mat2(1, 1.5, -1.5, 1), q), true);
  EXPECT_FALSE(f.symmetric);
  EXPECT_TRUE(f.minors_ok);
  EXPECT_TRUE(f.cholesky_tried && f.cholesky_ok);
  EXPECT_FALSE(
      classify(makeLcp(mat2(1, 1.5, -1.5, 1), q)).cholesky_tried); // default: the 2 x 2 minors decide
  EXPECT_TRUE(f.diag_positive);
  EXPECT_FALSE(f.diag_dominant);
  EXPECT_DOUBLE_EQ(f.density, 1.0);
}

// Triangular with a positive diagonal (a P-matrix, e.g. Murty's example): its own classes "tril" (lower) and
// "triu" (upper), whatever its symmetric part; not with a zero diagonal entry, not when symmetric (a diagonal
// matrix).
TEST(ProblemClass, TriangularPMatrices) {
  GeneratorParams gp;
  gp.n = 8;
  const Problem murty = generate("murty", gp, 0); // I + 2 strict lower triangle: symmetric part indefinite
  const ProblemFeatures f = classify(murty);
  EXPECT_EQ(f.name(), "lcp-tril-small");
  EXPECT_TRUE(f.triangular);
  EXPECT_FALSE(f.minors_ok);
  gp.n = 40;
  EXPECT_EQ(classOf(generate("murty", gp, 0)), "lcp-tril-medium");
  const Vec q = Vec::Constant(2, -1.0);
  EXPECT_EQ(classOf(makeLcp(mat2(1, 3, 0, 1), q)), "lcp-triu-small");   // upper triangular
  EXPECT_EQ(classOf(makeLcp(mat2(1, 0, 3, 1), q)), "lcp-tril-small");   // lower triangular
  EXPECT_EQ(classOf(makeLcp(mat2(1, 1.5, 0, 1), q)), "lcp-triu-small"); // symmetric part positive definite
  EXPECT_EQ(classOf(makeLcp(mat2(0, 3, 0, 1), q)), "lcp-gen-small");    // zero diagonal entry
  EXPECT_EQ(classOf(makeLcp(mat2(2, 0, 0, 1), q)), "lcp-dd-small");     // diagonal: symmetric, dominant
  EXPECT_EQ(classOf(makeLcp(mat2(1, 0, 0, 3), q)), "lcp-dd-small");
  EXPECT_EQ(classOf(makeBox(mat2(1, 0, 3, 1), q, Vec::Constant(2, -1.0), Vec::Constant(2, 1.0))),
            "box-tril-small");
  gp.n = 20;
  gp.cond = 1e2;
  EXPECT_EQ(classOf(generate("random_spd", gp, 0)), "lcp-spd-small"); // symmetric positive definite: not tri
  EXPECT_FALSE(classify(generate("random_spd", gp, 0)).triangular);
  EXPECT_EQ(classOf(generate("pmatrix", gp, 0)), "lcp-pd-small"); // dense nonsymmetric P-matrix: not tri
}

// The scalar tests of n <= 16 (problem_class.cpp, scanTinyInto) against the general path: diag(A, A), of
// size 2 n > 16, has the same features as A (the same rows' sums, the zero cross blocks add positive minors
// and keep a triangle), and is in the same size band while 2 n <= 32.
TEST(ProblemClass, TinyScanAgreesWithTheGeneralPath) {
  GeneratorParams gp;
  gp.cond = 1e3;
  std::vector<Mat> mats;
  for (int n : {9, 12, 16}) {
    gp.n = n;
    for (const char* fam : {"random_spd", "pmatrix", "murty"}) mats.push_back(generate(fam, gp, 0).M);
    mats.push_back(mats.back().transpose());         // upper triangular
    mats.push_back(Mat::Identity(n, n) * (n + 1.0)); // dominant
    mats.push_back(mats.back() + Mat::Ones(n, n));   // symmetric, dominant
    const Mat& pm = mats[mats.size() - 5];
    mats.push_back(pm - pm.transpose() + Mat::Identity(n, n)); // skew part + I: pd
    mats.push_back(generate("random_spd", gp, 1).M);
    mats.back()(n - 1, n - 1) = -1.0;                            // a negative diagonal entry: sym
    mats.push_back(Mat::Ones(n, n) * 2.0 - Mat::Identity(n, n)); // minors <= 0
    mats.push_back(generate("murty", gp, 0).M);
    mats.back().triangularView<Eigen::StrictlyUpper>().setConstant(-0.0); // -0.0 is zero: still tril
    mats.push_back(mats.back());
    mats.back()(0, n - 1) = 1e-300; // one tiny entry in the last column: not triangular
  }
  for (size_t k = 0; k < mats.size(); ++k) {
    const Mat& A = mats[k];
    const Eigen::Index n = A.rows();
    Mat B = Mat::Zero(2 * n, 2 * n);
    B.topLeftCorner(n, n) = A;
    B.bottomRightCorner(n, n) = A;
    const ProblemFeatures a = classify(makeLcp(A, Vec::Constant(n, -1.0)));
    const ProblemFeatures b = classify(makeLcp(B, Vec::Constant(2 * n, -1.0)));
    SCOPED_TRACE("matrix " + std::to_string(k) + ", n = " + std::to_string(n) + ": " + a.name());
    EXPECT_EQ(a.symmetric, b.symmetric);
    EXPECT_EQ(a.diag_positive, b.diag_positive);
    EXPECT_EQ(a.diag_dominant, b.diag_dominant);
    EXPECT_EQ(a.minors_ok, b.minors_ok);
    EXPECT_EQ(a.triangular, b.triangular);
    if (2 * n <= 32)
      EXPECT_EQ(a.name(), b.name());
    else
      EXPECT_EQ(a.matrix, b.matrix);
  }
}

TEST(ProblemClass, StructureSizeAndFeatures) {
  GeneratorParams gp;
  gp.n = 50;
  gp.cond = 1e6;
  const Problem spd = generate("random_spd", gp, 0);
  EXPECT_EQ(classOf(spd), "lcp-spd-medium");
  EXPECT_EQ(classOf(generate("random_box", gp, 0)), "box-spd-medium");
  EXPECT_EQ(classOf(generate("pmatrix", gp, 0)), "lcp-pd-medium");
  gp.n = 33;
  EXPECT_EQ(classOf(generate("random_spd", gp, 1)), "lcp-spd-medium"); // 33: medium band
  gp.n = 257;
  gp.cond = 1e2;
  const ProblemFeatures big = classify(generate("random_spd", gp, 0), true);
  EXPECT_EQ(big.name(), "lcp-spd-large");
  EXPECT_TRUE(big.cholesky_tried && big.cholesky_ok);
  EXPECT_EQ(classify(generate("pmatrix", gp, 0), true).name(), "lcp-pd-large");
  // Murty's M = I + 2 strict lower triangle: symmetric part I + L + L^T with ones off the diagonal, singular,
  // but triangular with a positive diagonal (TriangularPMatrices)
  gp.n = 8;
  EXPECT_EQ(classOf(generate("murty", gp, 0)), "lcp-tril-small");
  // MLCP: one free variable, then one complementarity variable
  const Problem m = makeMlcp(mat2(4, 1, 1, 4), Vec::Constant(2, -1.0), 1);
  EXPECT_EQ(classOf(m), "mlcp-dd-small");
  const ProblemFeatures fm = classify(m);
  EXPECT_EQ(fm.finite_lower, 1);
  EXPECT_EQ(fm.finite_upper, 0);
  Mat D = Mat::Identity(4, 4);
  const Problem box = makeBox(D, Vec::Constant(4, 1.0), Vec::Constant(4, -1.0), Vec::Constant(4, 1.0));
  EXPECT_EQ(classOf(box), "box-dd-small");
  EXPECT_DOUBLE_EQ(classify(box, true).density, 0.25);
  EXPECT_EQ(classify(box).finite_upper, 4);
  EXPECT_EQ(classify(box).finite_lower, 4);
  // Standard bounds are l = 0 (either sign of zero) and u = +inf; each other bound is counted
  Problem s = makeLcp(D, Vec::Constant(4, -1.0));
  s.l[2] = -0.0;
  EXPECT_EQ(classOf(s), "lcp-dd-small");
  EXPECT_EQ(classify(s).finite_lower, 4);
  s.l[3] = -kInf;
  s.u[1] = 2.0;
  const ProblemFeatures fs = classify(s);
  EXPECT_EQ(fs.structure, "box");
  EXPECT_EQ(fs.finite_lower, 3);
  EXPECT_EQ(fs.finite_upper, 1);
}

// M = I + a (ones - I), a = -0.01: diagonal 1, every 2 x 2 minor 1 - a^2 > 0, not dominant (row sum of
// |off-diagonal| (n - 1) |a| > 1), eigenvalue 1 + (n - 1) a < 0 for n > 101: indefinite.
TEST(ProblemClass, CholeskyTestSeesWhatTheMinorsMiss) {
  auto m = [](int n) {
    Mat M = Mat::Constant(n, n, -0.01);
    M.diagonal().setOnes();
    return makeLcp(M, Vec::Constant(n, -1.0));
  };
  const ProblemFeatures chol = classify(m(300), true);
  EXPECT_EQ(chol.name(), "lcp-sym-large");
  EXPECT_TRUE(chol.minors_ok);
  EXPECT_TRUE(chol.cholesky_tried);
  EXPECT_FALSE(chol.cholesky_ok);
  // The O(n^2) tests alone (the portfolio's) cannot see this indefiniteness (documented limit of the class).
  const ProblemFeatures cheap = classify(m(200));
  EXPECT_EQ(cheap.name(), "lcp-spd-medium");
  EXPECT_FALSE(cheap.cholesky_tried);
}

TEST(Portfolio, ValidationNamesTheFault) {
  Portfolio t = builtinPortfolio();
  EXPECT_EQ(validatePortfolio(t), "");
  Portfolio bad{{"default"}, {{"lemke", "nosuch"}}};
  EXPECT_NE(validatePortfolio(bad).find("unknown solver 'nosuch'"), std::string::npos);
  bad = {{"lcp-spd-small"}, {{"lemke"}}};
  EXPECT_NE(validatePortfolio(bad).find("no 'default' class"), std::string::npos);
  bad = {{"default", "lcp-xyz"}, {{"lemke"}, {"bpp"}}};
  EXPECT_NE(validatePortfolio(bad).find("unknown problem class 'lcp-xyz'"), std::string::npos);
  bad = {{"default"}, {{"lemke", "bpp", "lemke"}}};
  EXPECT_NE(validatePortfolio(bad).find("twice"), std::string::npos);
  bad = {{"default"}, {{"lemke", "bpp", "keller", "murty", "pgs"}}};
  EXPECT_NE(validatePortfolio(bad).find("must be 1 to 4"), std::string::npos);
  bad = {{"default"}, {{}}};
  EXPECT_NE(validatePortfolio(bad).find("must be 1 to 4"), std::string::npos);
  const Portfolio two{{"default", "lcp-dd-small"}, {{"lemke"}, {"pgs", "bpp"}}};
  EXPECT_EQ(two.chainFor("lcp-dd-small"), (std::vector<std::string>{"pgs", "bpp"}));
  EXPECT_EQ(two.chainFor("box-gen-large"), (std::vector<std::string>{"lemke"}));
}

// PGS refuses lcp_CPS_2 (a zero diagonal entry: Unsupported, no answer); fb_newton, next in the chain, solves it.
TEST(Portfolio, ChainFallsBackWhenTheFirstSolverFails) {
  const Problem p = readSiconos(kSiconos + "/lcp_CPS_2.dat");
  const Portfolio t{{"default"}, {{"pgs", "fb_newton", "bpp"}}};
  AutoOptions o;
  o.portfolio = &t;
  AutoInfo info;
  const Result r = solveAuto(p, o, &info);
  ASSERT_TRUE(r.ok()) << describeAttempts(info.attempts);
  ASSERT_EQ(info.attempts.size(), 2u);
  EXPECT_EQ(info.attempts[0].solver, "pgs");
  EXPECT_FALSE(info.attempts[0].accepted);
  EXPECT_EQ(info.attempts[0].status, Status::Unsupported);
  EXPECT_EQ(info.attempts[1].solver, "fb_newton");
  EXPECT_TRUE(info.attempts[1].accepted);
  EXPECT_EQ(info.solver, "fb_newton");
  EXPECT_LE(naturalResidual(p, r.z, p.M * r.z + p.q), acceptanceTolerance(p));
  EXPECT_LE(complementarity(p, r.z, p.M * r.z + p.q), 1e-8);
}

// Lemke ray-terminates on lcp_CPS_3 (status 2 when run alone), but the chain's active-set refinement on the
// original problem turns its answer into a verified solution: accepted, no fallback.
TEST(Portfolio, RefinedRayTerminationIsAccepted) {
  const Problem p = readSiconos(kSiconos + "/lcp_CPS_3.dat");
  EXPECT_EQ(solve(*makeSolver("lemke"), p).status, Status::RayTermination);
  const Portfolio t{{"default"}, {{"lemke", "fb_newton"}}};
  AutoOptions o;
  o.portfolio = &t;
  AutoInfo info;
  const Result r = solveAuto(p, o, &info);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(info.attempts.size(), 1u);
  EXPECT_EQ(info.attempts[0].status, Status::RayTermination);
  EXPECT_GE(info.attempts[0].refinements, 1);
  EXPECT_LE(naturalResidual(p, r.z, p.M * r.z + p.q), acceptanceTolerance(p));
}

// A cap of one pivot on the chain's first solver (as -max_it does for auto): Lemke stops, bpp solves.
TEST(Portfolio, IterationCapOnTheFirstSolverFallsBack) {
  GeneratorParams gp;
  gp.n = 50;
  const Problem p = generate("random_spd", gp, 3);
  const Portfolio t{{"default"}, {{"lemke", "bpp"}}};
  AutoOptions o;
  o.portfolio = &t;
  o.max_iterations = 1;
  AutoInfo info;
  const Result r = solveAuto(p, o, &info);
  ASSERT_TRUE(r.ok()) << describeAttempts(info.attempts);
  ASSERT_EQ(info.attempts.size(), 2u);
  EXPECT_EQ(info.attempts[0].status, Status::MaxIterations);
  EXPECT_EQ(info.solver, "bpp");
  // Nobody solves it (w = -z - 1 < 0 for every z >= 0): every attempt recorded, never Solved; the chain {pgs}
  // and its completion, smoothed_newton and lemke, all tried.
  const Portfolio none{{"default"}, {{"pgs"}}};
  o.portfolio = &none;
  AutoInfo fail;
  const Result f = solveAuto(makeLcp(mat2(-1, 0, 0, -1), Vec::Constant(2, -1.0)), o, &fail);
  EXPECT_FALSE(f.ok());
  EXPECT_EQ(fail.solver, "");
  ASSERT_EQ(fail.attempts.size(), 3u);
  EXPECT_EQ(fail.attempts[1].solver, "smoothed_newton");
  EXPECT_EQ(fail.attempts[2].solver, "lemke");
}

// The completion of the families (portfolio.hpp): after a chain of one family, a member of each other family.
TEST(Portfolio, ChainsEndWithEveryFamily) {
  using V = std::vector<std::string>;
  EXPECT_EQ(completeFamilies({"bpp", "lemke", "keller", "cottle_dantzig"}),
            (V{"bpp", "lemke", "keller", "cottle_dantzig", "smoothed_newton", "pgs"}));
  EXPECT_EQ(completeFamilies({"pgs", "fb_newton"}), (V{"pgs", "fb_newton", "lemke"}));
  EXPECT_EQ(completeFamilies({"lemke", "smoothed_newton", "pgs_block"}),
            (V{"lemke", "smoothed_newton", "pgs_block"}));
  // every built-in chain, completed, has all three families within the bound
  const Portfolio& t = builtinPortfolio();
  for (const auto& chain : t.chains) {
    const V c = completeFamilies(chain);
    EXPECT_LE(c.size(), static_cast<size_t>(kAutoMaxTried));
    for (SolverFamily f : {SolverFamily::Pivoting, SolverFamily::Newton, SolverFamily::Iterative})
      EXPECT_TRUE(
          std::any_of(c.begin(), c.end(), [&](const std::string& s) { return solverFamily(s) == f; }));
  }
}

// A problem every solver of its class's chain gives up on, and the completion solves: PGS refuses lcp_CPS_2 (a
// zero diagonal entry), smoothed_newton (the completion's Newton member) solves it; table indexed or not.
TEST(Portfolio, CompletionSolvesWhatTheChainCannot) {
  const Problem p = readSiconos(kSiconos + "/lcp_CPS_2.dat");
  Portfolio t{{"default"}, {{"pgs"}}};
  for (const bool indexed : {false, true}) {
    if (indexed) t.indexRows();
    AutoOptions o;
    o.portfolio = &t;
    AutoInfo info;
    const Result r = solveAuto(p, o, &info);
    ASSERT_TRUE(r.ok()) << describeAttempts(info.attempts);
    EXPECT_EQ(info.chain, (std::vector<std::string>{"pgs", "smoothed_newton", "lemke"}));
    ASSERT_EQ(info.attempts.size(), 2u);
    EXPECT_EQ(info.attempts[0].status, Status::Unsupported);
    EXPECT_EQ(info.solver, "smoothed_newton");
    EXPECT_LE(naturalResidual(p, r.z, p.M * r.z + p.q), acceptanceTolerance(p));
  }
}

// The deferred minors test (portfolio.cpp): a symmetric matrix with a positive diagonal, neither dd nor
// triangular, is classed spd provisionally; the test runs only when the first solver of that chain fails, and
// then the final class's chain is tried without that solver. The same route with the table indexed (runIndexed) or not
// (solveWithChain); the class recorded is the final one.
TEST(Portfolio, DeferredMinorsTestRoutesAfterAFailedFirstSolver) {
  for (const int n : {40, 10}) { // the general path and the scalar one of n <= 16
    SCOPED_TRACE("n = " + std::to_string(n));
    const std::string spd = n > 32 ? "lcp-spd-medium" : "lcp-spd-small";
    const std::string sym = n > 32 ? "lcp-sym-medium" : "lcp-sym-small";
    GeneratorParams gp;
    gp.n = n;
    Problem p = generate("random_spd", gp, 3);
    const double m01 = p.M(0, 1);
    p.M(0, 1) = p.M(1, 0) = 2 * std::sqrt(p.M(0, 0) * p.M(1, 1)); // minor d_0 d_1 - M_01^2 < 0: indefinite
    p.symmetric = -1;                                             // (not known: tested)
    const ProblemFeatures quick = classify(p, false, true);
    EXPECT_TRUE(quick.minors_deferred);
    EXPECT_EQ(quick.name(), spd);
    EXPECT_FALSE(classify(p).minors_deferred);
    EXPECT_EQ(classify(p).name(), sym);
    Portfolio t{{spd, sym, "default"},
                {{"lemke", "keller"}, {"keller", "lemke", "cottle_dantzig"}, {"murty"}}};
    for (const bool indexed : {false, true}) {
      if (indexed) t.indexRows();
      AutoOptions o;
      o.portfolio = &t;
      o.max_iterations = 1; // Lemke stops after one pivot
      AutoInfo info;
      const Result r = solveAuto(p, o, &info);
      ASSERT_TRUE(r.ok()) << describeAttempts(info.attempts);
      EXPECT_EQ(info.features.name(), sym);
      EXPECT_EQ(info.chain,
                (std::vector<std::string>{"lemke", "keller", "cottle_dantzig", "smoothed_newton", "pgs"}));
      ASSERT_EQ(info.attempts.size(), 2u) << indexed;
      EXPECT_EQ(info.attempts[0].solver, "lemke");
      EXPECT_EQ(info.attempts[0].status, Status::MaxIterations);
      EXPECT_EQ(info.solver, "keller");
      EXPECT_LE(naturalResidual(p, r.z, p.M * r.z + p.q), acceptanceTolerance(p));
      // Without the cap Lemke's answer is accepted: no test needed, yet the record has the final class.
      o.max_iterations = 0;
      AutoInfo first;
      ASSERT_TRUE(solveAuto(p, o, &first).ok());
      EXPECT_EQ(first.attempts.size(), 1u);
      EXPECT_EQ(first.solver, "lemke");
      EXPECT_EQ(first.features.name(), sym);
    }
    // The SPD matrix it came from: the provisional class is the final one.
    p.M(0, 1) = p.M(1, 0) = m01;
    EXPECT_TRUE(classify(p, false, true).minors_deferred);
    EXPECT_EQ(classify(p, false, true).name(), spd);
    EXPECT_EQ(classify(p).name(), spd);
    EXPECT_TRUE(classify(p).minors_ok);
  }
}

// The built-in table on every Siconos file: auto solves each file that some single solver solves.
TEST(Portfolio, BuiltinSolvesTheSiconosFilesSomeSolverSolves) {
  DIR* d = opendir(kSiconos.c_str());
  ASSERT_NE(d, nullptr) << kSiconos;
  std::vector<std::string> files;
  while (dirent* e = readdir(d)) {
    const std::string f = e->d_name;
    if (f.size() > 4 && f.substr(f.size() - 4) == ".dat") files.push_back(f);
  }
  closedir(d);
  ASSERT_GE(files.size(), 17u);
  int solvable = 0;
  for (const std::string& f : files) {
    const Problem p = readSiconos(kSiconos + "/" + f);
    bool any = false;
    for (const char* s :
         {"lemke", "keller", "cottle_dantzig", "murty", "bpp", "fb_newton", "smoothed_newton", "pgs"})
      any = any || solve(*makeSolver(s), p).ok();
    if (!any) continue;
    ++solvable;
    AutoInfo info;
    const Result r = solveAuto(p, AutoOptions{}, &info);
    EXPECT_TRUE(r.ok()) << f << " (" << info.features.name() << "): " << describeAttempts(info.attempts);
  }
  EXPECT_EQ(solvable, static_cast<int>(files.size())); // every file is solved by some solver today
}

// solveWithChain's "auto" (the entry point for the chain's users): the built-in chain of the class, then the
// other names not already in it.
TEST(Portfolio, AutoInAChainExpandsToTheBuiltinChain) {
  GeneratorParams gp;
  gp.n = 12;
  const Problem p = generate("random_box", gp, 1);
  const std::vector<std::string>& chain = builtinPortfolio().chainFor(classify(p).name());
  ASSERT_FALSE(chain.empty());
  std::vector<Attempt> att;
  const Result r = solveWithChain(p, {"auto"}, ChainOptions{}, &att);
  ASSERT_TRUE(r.ok()) << describeAttempts(att);
  EXPECT_EQ(att[0].solver, chain[0]);
  // A failing solver first, then auto: its chain follows.
  const Result f = solveWithChain(makeLcp(mat2(0, 1, -1, 0), Vec::Constant(2, 1.0)), {"pgs", "auto"},
                                  ChainOptions{}, &att);
  EXPECT_TRUE(f.ok()); // z = 0 solves it (q >= 0)
  EXPECT_GE(att.size(), 1u);
}
