// Unit tests of the fast end of the contact stepper: the sparse Delassus matrix equals the dense
// one to round-off, the sparse exact path agrees with the dense chain and is chosen only above the
// crossover, contacts keep their identities and impulses across steps, and the balanced / fast modes stay
// within their stated errors on the incline and a stack without ever stopping the run, their sweep budget grows
// with the pile height; block PGS over contact manifolds converges to the active-set answer; the sparse path
// and the splitting do the same for any scale of the masses; the proximal active set solves the narrow friction
// boxes on which the plain one stalls.
#include "contact/body_space_solve.hpp"
#include "contact/block_pgs.hpp"
#include "contact/box_lcp.hpp"
#include "contact/contact_accuracy.hpp"
#include "contact/delassus.hpp"
#include "contact/scenes.hpp"
#include "contact/stepper.hpp"
#include "incline_speed.hpp"
#include "lcp/solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

using namespace suite::contact;

namespace {
constexpr double kG = 9.81;

std::vector<Body> scene(const std::string& name, int size, double theta = 0.0) {
  SceneParams p;
  p.scene = name;
  p.stack_height = size;
  p.pyramid_base = size;
  p.theta_deg = theta;
  return buildScene(p);
}

// max |x - x0| over the dynamic bodies.
double drift(const std::vector<Body>& b, const std::vector<Body>& b0) {
  double d = 0.0;
  for (size_t i = 0; i < b.size(); ++i) d = std::max(d, (b[i].x - b0[i].x).lpNorm<Eigen::Infinity>());
  return d;
}

DelassusSystem system(const std::vector<Body>& b, const StepperOptions& o, bool sparse) {
  std::vector<Mat3> inv_i;
  std::vector<Vec3> v;
  for (const Body& x : b) inv_i.push_back(x.is_static ? Mat3::Zero() : x.invInertiaWorld()), v.push_back(x.v);
  const std::vector<Contact> cs = findContacts(b, o.margin, o.gravity, o.dt);
  return buildDelassus(b, inv_i, v, cs, boxRows(cs, true), o, sparse);
}

using test::downhillSpeed;
} // namespace

TEST(ContactSparse, DelassusEqualsDense) {
  StepperOptions o;
  for (auto [name, size] : {std::make_pair("box_stack", 10), std::make_pair("pyramid", 5)}) {
    const auto b = scene(name, size);
    const DelassusSystem d = system(b, o, false), s = system(b, o, true);
    const double diff = (d.A - suite::lcp::Mat(s.S)).lpNorm<Eigen::Infinity>(),
                 amax = d.A.lpNorm<Eigen::Infinity>();
    std::printf("%s %d: %d rows, nnz %ld of %d, max|A - S| = %.2e (max|A| %.2e)\n", name, size,
                (int)d.b.size(), (long)s.S.nonZeros(), (int)(d.A.size()), diff, amax);
    EXPECT_LE(diff, 1e-14 * amax) << name;
    EXPECT_EQ((d.b - s.b).lpNorm<Eigen::Infinity>(), 0.0) << name;
    EXPECT_LT(s.S.nonZeros(), d.A.size() / 2) << name;
  }
}

TEST(ContactSparse, BodySpaceSolveEqualsDenseSolve) {
  StepperOptions o;
  const auto b = scene("pyramid", 5);
  const DelassusSystem d = system(b, o, false), s = system(b, o, true);
  const int n = (int)d.b.size();
  suite::lcp::Vec reg(n);
  std::vector<int> F;
  for (int i = 0; i < n; ++i) {
    reg[i] = s.S.coeff(i, i) - (d.rows[i].ja.dot(d.rows[i].ma) + d.rows[i].jb.dot(d.rows[i].mb));
    if (i % 5 != 2) F.push_back(i); // a free set: most rows
  }
  suite::lcp::Vec r(F.size()), x;
  for (size_t a = 0; a < F.size(); ++a) r[a] = std::sin(1.0 + a); // any right-hand side
  ASSERT_TRUE(bodySpaceSolve(s.rows, s.mass, reg, F, r, &x));
  const suite::lcp::Mat AFF = d.A(F, F);
  const suite::lcp::Vec xd = AFF.ldlt().solve(r);
  auto rel = [&](const suite::lcp::Vec& y) {
    return (AFF * y - r).lpNorm<Eigen::Infinity>() /
           (AFF.lpNorm<Eigen::Infinity>() * y.lpNorm<Eigen::Infinity>());
  };
  // A_FF is nearly singular (rank <= 6 x bodies, lifted by the compliance 1e-8..1e-6 A_ii): backward errors
  std::printf("pyramid 5: %zu free rows, body-space K of %d rows: backward error %.2e (dense LDL^T %.2e), "
              "|x - x_dense| / |x| %.2e\n",
              F.size(), 6 * (int)b.size(), rel(x), rel(xd),
              (x - xd).lpNorm<Eigen::Infinity>() / xd.lpNorm<Eigen::Infinity>());
  EXPECT_LE(rel(x), 1e-15);
}

TEST(ContactSparse, SparsePathAgreesWithDenseAboveCrossover) {
  const auto b0 = scene("pyramid", 4);
  auto bd = b0, bs = b0;
  StepperOptions od, os;
  od.dense_max_rows = 1 << 20; // dense always
  os.dense_max_rows = 0;       // sparse always
  Stepper sd(od), ss(os);
  for (int k = 0; k < 50; ++k) {
    const StepStats a = sd.step(&bd), c = ss.step(&bs);
    ASSERT_FALSE(a.failed || c.failed) << k;
    EXPECT_NE(a.solver, "sparse_active_set");
    EXPECT_EQ(c.solver, "sparse_active_set") << "step " << k << " fell back";
  }
  std::printf("pyramid 4, 50 steps: |x_sparse - x_dense| = %.2e, drift %.2e\n", drift(bs, bd), drift(bs, b0));
  EXPECT_LE(drift(bs, bd), 1e-9);
  EXPECT_LE(drift(bs, b0), 1e-6);
}

// Every mass scaled by 1,000 scales every impulse by 1,000 and leaves the motion unchanged: the sparse path's
// residual, state read and the splitting's stop rule are in velocities (A_ii-scaled), so the heavy scene takes
// the same passes and ends where the light one does (to the solves' tolerances). A stop rule in impulses
// with an absolute 1 N s floor is 1,000 times stricter on the heavy pile (passes at their cap of 50, 2.5x the
// time per step on pile_grid).
TEST(ContactSparse, SplittingIsTheSameForAnyScaleOfTheMasses) {
  SceneParams sp;
  sp.scene = "pyramid";
  sp.pyramid_base = 6;
  StepperOptions o;
  o.dense_max_rows = 0; // the sparse path
  std::vector<Body> light, heavy;
  for (double density : {1.0, 1000.0}) {
    sp.density = density;
    (density == 1.0 ? light : heavy) = buildScene(sp);
  }
  const auto light0 = light;
  Stepper sl(o), sh(o);
  int passes = 0, fl = 0, fh = 0;
  for (int k = 0; k < 30; ++k) {
    const StepStats a = sl.step(&light), c = sh.step(&heavy);
    ASSERT_FALSE(a.failed || c.failed) << k;
    EXPECT_EQ(a.splitting_iterations, c.splitting_iterations) << "step " << k;
    EXPECT_LT(c.splitting_iterations, o.splitting_max_it) << "step " << k;
    passes += c.splitting_iterations, fl += a.factorizations, fh += c.factorizations;
  }
  std::printf("pyramid 6, 30 steps, 1 and 1,000 kg/m^3: %d passes each, %d / %d factorisations, |x_heavy - "
              "x_light| = %.2e, drift %.2e\n",
              passes, fl, fh, drift(heavy, light), drift(light, light0));
  // equal up to the solves' tolerances (a residual near its threshold may take one more active-set solve in
  // one of the two; measured 3.5e-11 m, 66 / 66 factorisations)
  EXPECT_LE(drift(heavy, light), 1e-9);
  EXPECT_LE(std::abs(fl - fh), fl / 10);
  EXPECT_LE(drift(light, light0), 1e-6);
}

TEST(ContactWarmStart, FirstStepOfARestingPyramidCostsAtMostTenSteadySteps) {
  auto b = scene("pyramid", 8); // 36 boxes, 768 rows: the sparse path
  Stepper st(StepperOptions{});
  std::vector<StepStats> s;
  for (int k = 0; k < 10; ++k) {
    s.push_back(st.step(&b));
    ASSERT_FALSE(s.back().failed);
  }
  int steady = 0;
  for (int k = 1; k < 10; ++k) steady = std::max(steady, s[k].factorizations);
  std::printf("pyramid 8: step 1 %d factorisations, %d passes, %d fallbacks; steps 2-10 at most %d "
              "factorisations\n",
              s[0].factorizations, s[0].splitting_iterations, s[0].fallbacks, steady);
  EXPECT_EQ(s[0].fallbacks, 0);
  EXPECT_EQ(s[0].solver, "sparse_active_set");
  EXPECT_LE(s[0].factorizations, 10 * steady);
}

TEST(ContactWarmStart, IdentitiesAndImpulsesCarried) {
  long long sweeps[2] = {0, 0};
  double residual[2] = {0.0, 0.0};
  for (bool warm : {true, false}) {
    auto b = scene("box_stack", 10);
    StepperOptions o;
    o.warm_start = warm;
    o.accuracy = ContactAccuracy::Fast;
    Stepper st(o);
    ASSERT_FALSE(st.step(&b).failed);
    std::vector<long long> ids = st.contactIds();
    ASSERT_EQ(ids.size(), st.contacts().size());
    std::sort(ids.begin(), ids.end());
    for (int k = 0; k < 100; ++k) {
      const StepStats s = st.step(&b);
      ASSERT_FALSE(s.failed);
      sweeps[warm] += s.iterations;
      residual[warm] = s.residual; // the last step's
    }
    std::vector<long long> now = st.contactIds();
    std::sort(now.begin(), now.end());
    EXPECT_EQ(now, ids); // the same contacts keep their ids, no new one
    std::printf("stack 10 (fast), steps 2-101, warm start %d: %lld block PGS sweeps, last residual %.2e\n",
                (int)warm, sweeps[warm], residual[warm]);
  }
  // the carried impulses are (nearly) the answer: the same 10 sweeps a step end far closer to it (the block sweeps
  // run to their budget either way: the 10-box chain keeps changing velocities by ~1e-8 a sweep, above the stop
  // tolerance; measured at step 101: 1.3e-5 warm, 0.15 cold)
  EXPECT_LT(1e3 * residual[1], residual[0]);
}

TEST(ContactAccuracyModes, InclineWithinStatedError) {
  const double mu = 0.3, th = 30.0;
  const double exact = kG * (std::sin(th * M_PI / 180) - mu * std::cos(th * M_PI / 180));
  for (ContactAccuracy m : {ContactAccuracy::Exact, ContactAccuracy::Balanced, ContactAccuracy::Fast}) {
    auto b = scene("incline", 0, th);
    StepperOptions o;
    o.mu = mu, o.accuracy = m;
    Stepper st(o);
    ASSERT_FALSE(st.step(&b).failed);
    const double v1 = downhillSpeed(b, th);
    for (int k = 1; k < 100; ++k) ASSERT_FALSE(st.step(&b).failed);
    const double a = (downhillSpeed(b, th) - v1) / (99 * 0.01), err = std::abs(a / exact - 1);
    std::printf("incline 30 deg mu 0.3 (%s): a = %.8f exact %.8f rel.err %.2e\n", accuracyName(m), a, exact,
                err);
    EXPECT_LE(err, m == ContactAccuracy::Exact ? 1e-4 : 1e-3) << accuracyName(m);
  }
}

TEST(ContactAccuracyModes, StickingCreepWithinStatedError) {
  for (ContactAccuracy m : {ContactAccuracy::Exact, ContactAccuracy::Balanced, ContactAccuracy::Fast}) {
    auto b = scene("incline", 0, 20.0); // tan 20 < mu: sticks
    const auto b0 = b;
    StepperOptions o;
    o.accuracy = m;
    Stepper st(o);
    for (int k = 0; k < 200; ++k) ASSERT_FALSE(st.step(&b).failed);
    std::printf("incline 20 deg mu 0.5 (%s): creep %.2e m in 2 s\n", accuracyName(m), drift(b, b0));
    // stated bounds (measured: exact 5.2e-9, balanced 2.0e-8, fast 2.5e-8; fast with point PGS: 1.0e-5)
    const double bound = m == ContactAccuracy::Exact ? 1e-8 : 1e-7;
    EXPECT_LE(drift(b, b0), bound) << accuracyName(m);
  }
}

TEST(ContactAccuracyModes, StackOfTenNeverStoppedByTheBudget) {
  for (ContactAccuracy m : {ContactAccuracy::Balanced, ContactAccuracy::Fast}) {
    auto b = scene("box_stack", 10);
    const auto b0 = b;
    StepperOptions o;
    o.accuracy = m;
    Stepper st(o);
    int budget_stops = 0;
    double residual = 0.0;
    for (int k = 0; k < 200; ++k) {
      const StepStats s = st.step(&b);
      ASSERT_FALSE(s.failed);
      budget_stops += s.budget_stop;
      residual = std::max(residual, s.residual);
    }
    std::printf("stack 10 (%s): drift %.2e m in 2 s, %d budget stops of 200, last residual %.2e\n",
                accuracyName(m), drift(b, b0), budget_stops, residual);
    // exact: 4.9e-7. Balanced / fast run their normal rows with Baumgarte factor 0.05 instead of 0.2
    // (StepperOptions::budget_baumgarte), so the compliant stack's resting penetration phi = reg A_nn lambda_n dt /
    // beta is 4x exact's: measured 2.0e-6 (balanced), 2.2e-6 (fast), a fixed offset, not a growing drift
    EXPECT_LE(drift(b, b0), 3e-6) << accuracyName(m);
  }
}

// The budget modes' default sweep budget grows with the square of the pile height (contact_accuracy.hpp): the
// height counts body layers from the ground, and an explicit -contact_sweeps is kept as given.
TEST(ContactAccuracyModes, SweepBudgetGrowsWithThePileHeight) {
  StepperOptions o;
  for (auto [name, size, height] :
       {std::tuple<const char*, int, int>{"box_stack", 10, 10}, {"pyramid", 5, 5}, {"pyramid", 30, 30}}) {
    const auto b = scene(name, size);
    const auto cs = findContacts(b, o.margin, o.gravity, o.dt);
    EXPECT_EQ(pileHeight(cs, b), height) << name << " " << size;
  }
  EXPECT_EQ(pileHeight({}, scene("box_stack", 3)), 0);
  o.accuracy = ContactAccuracy::Fast;
  EXPECT_EQ(sweepBudget(o, 10), 10);
  EXPECT_EQ(sweepBudget(o, 30), 90);
  EXPECT_EQ(sweepBudget(o, 31), 97); // ceil(961 / 10)
  o.accuracy = ContactAccuracy::Balanced;
  EXPECT_EQ(sweepBudget(o, 20), 40);
  EXPECT_EQ(sweepBudget(o, 30), 90);
  o.contact_sweeps = 7;
  EXPECT_EQ(sweepBudget(o, 30), 7);
}

// Block PGS over contact manifolds (block_pgs.hpp) converges to the answer of the active-set solve (exact to
// round-off on its index sets) on small resting problems of one step (gravity in b) with fixed box bounds: wide
// (every tangent row free) and tight (tangent rows at their bounds: the blocks' inner iterations). The corner
// impulses of a face are unique only through the 1e-6 compliance, so the test compares the residual, the row
// velocities w = A z + b and, on the stack, each body pair's total normal impulse.
TEST(ContactBlockPgs, ConvergesToTheActiveSetAnswer) {
  StepperOptions o;
  for (auto [name, size] : {std::make_pair("box_stack", 3), std::make_pair("pyramid", 3)})
    for (double bound : {10.0, 1e-3}) {
      const auto b = scene(name, size);
      const std::vector<Contact> cs = findContacts(b, o.margin, o.gravity, o.dt);
      std::vector<Mat3> inv_i;
      std::vector<Vec3> vstar; // after gravity: the resting problem of a step
      for (const Body& x : b)
        inv_i.push_back(x.is_static ? Mat3::Zero() : x.invInertiaWorld()),
            vstar.push_back(x.is_static ? x.v : Vec3(x.v + o.dt * o.gravity));
      const DelassusSystem s = buildDelassus(b, inv_i, vstar, cs, boxRows(cs, true), o, true);
      const int n = (int)s.b.size();
      suite::lcp::Vec l(n), u(n);
      for (int i = 0; i < n; ++i)
        l[i] = i % 3 == 0 ? 0.0 : -bound, u[i] = i % 3 == 0 ? suite::lcp::kInf : bound;
      SparseBoxLcp p = makeSparseBoxLcp(s, l, u);
      p.order = heightOrder(cs, o.gravity, 3);
      p.symmetric = true;
      suite::lcp::Vec zr = suite::lcp::Vec::Zero(n), zb = zr, wr, wb;
      SparseSolveStats ss;
      freeStart(p, &zr, &ss);
      ASSERT_TRUE(activeSetSolve(p, 50, 1e-12, &zr, &ss, true)) << name;
      const int sweeps = blockPgsSweeps(p, cs, 3, 5000, 1e-13, &zb);
      const double rr = sparseResidual(p, zr, &wr), rb = sparseResidual(p, zb, &wb);
      double dw = 0.0, dn = 0.0, nmax = 0.0;
      for (int i = 0; i < n; ++i) dw = std::max(dw, std::abs(wr[i] - wb[i]));
      std::map<std::pair<int, int>, double> tr, tb; // total normal impulse per body pair
      for (size_t c = 0; c < cs.size(); ++c)
        tr[{cs[c].a, cs[c].b}] += zr[3 * c], tb[{cs[c].a, cs[c].b}] += zb[3 * c];
      for (auto& [k, v] : tr) dn = std::max(dn, std::abs(v - tb[k])), nmax = std::max(nmax, v);
      std::printf(
          "%s %d, bounds %g: %d rows, %d block sweeps, residual %.1e (active set %.1e), max|w - w_ref| "
          "%.1e, max pair normal impulse difference %.1e of %.2e\n",
          name, size, bound, n, sweeps, rb, rr, dw, dn, nmax);
      const bool stack = std::string(name) == "box_stack";
      // the stack: to round-off (measured residual 1e-13, pair totals 2e-10 of 294); the pyramid's load split
      // between the two supports of a box is set by the 1e-6 compliance only, the slowest direction for any
      // Gauss-Seidel: 5,000 sweeps leave velocities within 6e-8 / 1.5e-7 of the answer (the pair totals 3-7% off)
      EXPECT_LE(rb, stack ? 1e-12 : 2e-7) << name << " " << bound;
      EXPECT_LE(dw, stack ? 1e-12 : 2e-7) << name << " " << bound;
      if (stack) {
        EXPECT_LE(dn, 1e-10 * nmax) << name << " " << bound;
      }
    }
}

// The proximal active set (sparse_box_lcp.hpp, proximalSolve) on the case it was made for: one step of a
// resting pyramid of base 6 (21 boxes, 4 contact points per face) with narrow friction boxes, 0.05 times the
// sticking estimate of each normal impulse. The plain active set, from the same start (free start, 20 PGS
// sweeps), stalls above the tolerance (the 8 tangent rows of a face hold 3 degrees of freedom); the proximal
// steps meet it, and the answer's row velocities w = A z + b agree with the dense chain's answer (Cottle-Dantzig
// / smoothed Newton on the dense Delassus matrix) to the tolerance.
TEST(ContactSparse, ProximalActiveSetSolvesNarrowBoxes) {
  StepperOptions o;
  const auto b = scene("pyramid", 6);
  const std::vector<Contact> cs = findContacts(b, o.margin, o.gravity, o.dt);
  std::vector<Mat3> inv_i;
  std::vector<Vec3> vstar;
  for (const Body& x : b)
    inv_i.push_back(x.is_static ? Mat3::Zero() : x.invInertiaWorld()),
        vstar.push_back(x.is_static ? x.v : Vec3(x.v + o.dt * o.gravity));
  const DelassusSystem s = buildDelassus(b, inv_i, vstar, cs, boxRows(cs, true), o, true);
  const int n = (int)s.b.size(), nc = (int)cs.size();
  const std::vector<double> nu = stickingEstimates(s, nc, 3);
  suite::lcp::Vec l(n), u(n);
  for (int i = 0; i < n; ++i) {
    const double bound = 0.05 * nu[i / 3];
    l[i] = i % 3 == 0 ? 0.0 : -bound, u[i] = i % 3 == 0 ? suite::lcp::kInf : bound;
  }
  SparseBoxLcp p = makeSparseBoxLcp(s, l, u);
  suite::lcp::Vec z0 = suite::lcp::Vec::Zero(n);
  SparseSolveStats s0, s1, s2;
  freeStart(p, &z0, &s0);
  pgsSweeps(p, 20, 0.0, &z0);
  suite::lcp::Vec plain = z0, prox = z0;
  const bool plain_ok = activeSetSolve(p, 20, o.lcp_tol, &plain, &s1, true);
  int steps = 0;
  const bool prox_ok = proximalSolve(p, ProximalOptions{}, o.lcp_tol, &prox, &s2, &steps);
  // the reference: the dense chain on the same box LCP
  const suite::lcp::Problem d = suite::lcp::makeBox(denseDelassus(s), s.b, l, u, "pyramid6");
  suite::lcp::ChainOptions co;
  co.rel_tol = 1e-12;
  const suite::lcp::Result r = suite::lcp::solveWithChain(d, {"cottle_dantzig", "smoothed_newton"}, co);
  suite::lcp::Vec w;
  sparseResidual(p, prox, &w);
  const double dw = (w - (d.M * r.z + d.q)).lpNorm<Eigen::Infinity>();
  std::printf("%d rows: plain active set residual %.2e (%d factorisations), proximal %.2e in %d steps (%d "
              "factorisations), tolerance %.2e; max |w - w_dense| %.2e (dense %s, residual %.1e)\n",
              n, s1.residual, s1.factorizations, s2.residual, steps, s2.factorizations, s2.tolerance, dw,
              suite::lcp::statusName(r.status), r.residual);
  EXPECT_FALSE(
      plain_ok); // the stall the proximal steps are for (if it ever solves, this test needs a harder case)
  EXPECT_TRUE(prox_ok);
  EXPECT_LE(s2.residual, s2.tolerance);
  EXPECT_LE(steps, ProximalOptions{}.max_steps);
  ASSERT_TRUE(r.ok());
  EXPECT_LE(dw, 10 * s2.tolerance);
  // The same without the masses: the free rows solved by the sparse LDL^T of A_FF (rowSpaceSolve), which must
  // add the subproblems' compliance to the system's matrix itself.
  SparseBoxLcp pr = p;
  pr.mass = nullptr;
  suite::lcp::Vec rowz = z0;
  SparseSolveStats s3;
  int row_steps = 0;
  EXPECT_TRUE(proximalSolve(pr, ProximalOptions{}, o.lcp_tol, &rowz, &s3, &row_steps));
  sparseResidual(pr, rowz, &w);
  const double dw_row = (w - (d.M * r.z + d.q)).lpNorm<Eigen::Infinity>();
  std::printf("row space: proximal %.2e in %d steps; max |w - w_dense| %.2e\n", s3.residual, row_steps,
              dw_row);
  EXPECT_LE(dw_row, 10 * s3.tolerance);
}
