// Problem registry of the 2D/3D Euler app (lib/euler/problem_nd*.cpp): exact solutions against their defining
// properties (vortex periodicity, planar = 1D), published data (2D Riemann presets, double Mach post-shock
// state and Rankine-Hugoniot relations, Rayleigh-Taylor hydrostatic balance), boundary ghost states and the
// refusal of bad input with a message naming the option.
#include "euler/exact_riemann.hpp"
#include "euler/problem_nd.hpp"

#include "../test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace suite::euler;

namespace {
// Collects the first PETSc error message instead of printing it.
PetscErrorCode captureHandler(MPI_Comm, int, const char*, const char*, PetscErrorCode n, PetscErrorType,
                              const char* mess, void* ctx) {
  auto* s = static_cast<std::string*>(ctx);
  if (s->empty() && mess) *s = mess;
  return n;
}

// Runs createProblemND expecting failure; returns the error message (empty if it succeeded).
std::string failureMessage(const std::string& name, int dim, int axis = 0) {
  std::string msg;
  ProblemND pr;
  PetscPushErrorHandler(captureHandler, &msg);
  PetscErrorCode ierr = createProblemND(PETSC_COMM_WORLD, name, dim, axis, &pr);
  PetscPopErrorHandler();
  if (!ierr) return "";
  return msg.empty() ? "(no message)" : msg;
}

struct ScopedOption {
  std::string name;
  ScopedOption(const char* n, const char* v) : name(n) { PetscOptionsSetValue(nullptr, n, v); }
  ~ScopedOption() { PetscOptionsClearValue(nullptr, name.c_str()); }
};

ProblemND make(const std::string& name, int dim, int axis = 0) {
  ProblemND pr;
  EXPECT_EQ(createProblemND(PETSC_COMM_WORLD, name, dim, axis, &pr), 0) << name;
  return pr;
}

void expectStateNear(const PrimN& a, const PrimN& b, double tol) {
  EXPECT_NEAR(a.rho, b.rho, tol);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(a.u[d], b.u[d], tol);
  EXPECT_NEAR(a.p, b.p, tol);
}
} // namespace

TEST(EulerProblemND, VortexExactAfterOnePeriodIsInitial) {
  for (int dim : {2, 3}) {
    const ProblemND pr = make("isentropic_vortex", dim);
    ASSERT_TRUE(pr.exact);
    EXPECT_DOUBLE_EQ(pr.hi[0] - pr.lo[0], 10.0);
    EXPECT_DOUBLE_EQ(pr.t_final, 10.0);
    double maxdiff = 0.0, minrho = 1.0;
    for (int i = 0; i < 50; ++i)
      for (int j = 0; j < 50; ++j) {
        const double x[3] = {0.1 + 0.2 * i, 0.1 + 0.2 * j, 0.3};
        const PrimN a = pr.initial(x), b = pr.exact(x, pr.t_final);
        maxdiff = std::max({maxdiff, std::abs(a.rho - b.rho), std::abs(a.u[0] - b.u[0]),
                            std::abs(a.u[1] - b.u[1]), std::abs(a.p - b.p)});
        minrho = std::min(minrho, a.rho);
        EXPECT_NEAR(a.p, std::pow(a.rho, pr.gamma), 1e-13); // isentropic: p = rho^gamma
      }
    EXPECT_LT(maxdiff, 1e-12);
    EXPECT_LT(minrho, 0.6); // the vortex core is there (beta = 5: rho_min = 0.5 at r = 0 with gamma 1.4)
  }
}

TEST(EulerProblemND, VortexCoreAndTranslation) {
  const ProblemND pr = make("isentropic_vortex", 2);
  const double c[3] = {5.0, 5.0, 0.0};
  const PrimN core = pr.initial(c);
  const double beta = 5.0, g = 1.4;
  const double T = 1.0 - (g - 1.0) * beta * beta / (8.0 * g * M_PI * M_PI) * std::exp(1.0);
  EXPECT_NEAR(core.rho, std::pow(T, 1.0 / (g - 1.0)), 1e-14);
  EXPECT_NEAR(core.u[0], 1.0, 1e-14); // no swirl at the centre
  // at t = 2.5 the centre is at (7.5, 7.5); at t = 7 at (12, 12) = (2, 2) by periodicity
  const double x1[3] = {7.5, 7.5, 0.0}, x2[3] = {2.0, 2.0, 0.0};
  expectStateNear(pr.exact(x1, 2.5), core, 1e-13);
  expectStateNear(pr.exact(x2, 7.0), core, 1e-13);
  // swirl: counter-clockwise, du = -beta/(2 pi) e^{(1-r^2)/2} yb at (5, 6)
  const double x3[3] = {5.0, 6.0, 0.0};
  EXPECT_NEAR(pr.initial(x3).u[0], 1.0 - beta / (2.0 * M_PI), 1e-14);
}

TEST(EulerProblemND, VortexExactSolvesTheEulerEquations) {
  // Residual of q_t + f(q)_x + g(q)_y = 0 for the exact field, by central differences (h = 1e-4: truncation
  // ~1e-8, round-off ~1e-11); a wrong temperature dip or swirl amplitude leaves an O(1e-2..1) residual.
  const ProblemND pr = make("isentropic_vortex", 2);
  const double g = pr.gamma, h = 1e-4;
  auto cons = [&](const PrimN& w, int k) {
    const double E = w.p / (g - 1) + 0.5 * w.rho * (w.u[0] * w.u[0] + w.u[1] * w.u[1]);
    const double q[4] = {w.rho, w.rho * w.u[0], w.rho * w.u[1], E};
    return q[k];
  };
  auto flux = [&](const PrimN& w, int dir, int k) {
    const double E = w.p / (g - 1) + 0.5 * w.rho * (w.u[0] * w.u[0] + w.u[1] * w.u[1]), un = w.u[dir];
    const double f[4] = {w.rho * un, w.rho * w.u[0] * un + (dir == 0 ? w.p : 0.0),
                         w.rho * w.u[1] * un + (dir == 1 ? w.p : 0.0), (E + w.p) * un};
    return f[k];
  };
  double worst = 0.0;
  for (double t : {0.0, 1.3, 6.0})
    for (double x0 : {4.2, 5.0, 5.7, 9.9})
      for (double y0 : {4.6, 5.3, 0.2}) {
        const double X[3] = {x0 + t, y0 + t, 0.0}; // follow the vortex so the points sample its core
        for (int k = 0; k < 4; ++k) {
          double xp[3] = {X[0] + h, X[1], 0}, xm[3] = {X[0] - h, X[1], 0};
          double yp[3] = {X[0], X[1] + h, 0}, ym[3] = {X[0], X[1] - h, 0};
          const double dt = (cons(pr.exact(X, t + h), k) - cons(pr.exact(X, t - h), k)) / (2 * h);
          const double dfx = (flux(pr.exact(xp, t), 0, k) - flux(pr.exact(xm, t), 0, k)) / (2 * h);
          const double dgy = (flux(pr.exact(yp, t), 1, k) - flux(pr.exact(ym, t), 1, k)) / (2 * h);
          worst = std::max(worst, std::abs(dt + dfx + dgy));
        }
      }
  EXPECT_LT(worst, 1e-6);
}

TEST(EulerProblemND, VortexDomainOption) {
  ScopedOption o("-vortex_domain", "20");
  const ProblemND pr = make("isentropic_vortex", 2);
  EXPECT_DOUBLE_EQ(pr.hi[0], 20.0);
  EXPECT_DOUBLE_EQ(pr.hi[1], 20.0);
  EXPECT_DOUBLE_EQ(pr.t_final, 20.0);
  const double c[3] = {10.0, 10.0, 0.0}, far[3] = {0.1, 19.9, 0.0};
  EXPECT_LT(pr.initial(c).rho, 0.6);                            // the core is at the centre
  EXPECT_NEAR(pr.initial(far).rho, 1.0, 1e-15);                 // and the edge is unperturbed
  EXPECT_NEAR(pr.exact(c, 20.0).rho, pr.initial(c).rho, 1e-14); // one period
}

TEST(EulerProblemND, VortexTooStrongIsRefused) {
  {
    ScopedOption o("-vortex_strength", "20");
    EXPECT_NE(failureMessage("isentropic_vortex", 2).find("-vortex_strength"), std::string::npos);
  }
  ScopedOption o("-vortex_domain", "2");
  EXPECT_NE(failureMessage("isentropic_vortex", 2).find("-vortex_domain"), std::string::npos);
}

TEST(EulerProblemND, PlanarSodAlongYEqualsOneD) {
  Problem p1;
  ASSERT_EQ(createProblem(PETSC_COMM_WORLD, "sod", &p1), 0);
  const ProblemND pr = make("sod", 2, 1);
  EXPECT_DOUBLE_EQ(pr.lo[1], p1.xmin);
  EXPECT_DOUBLE_EQ(pr.hi[1], p1.xmax);
  EXPECT_DOUBLE_EQ(pr.t_final, p1.t_final);
  EXPECT_EQ(pr.default_n[1], p1.default_nx);
  EXPECT_EQ(pr.default_n[0], 6);
  EXPECT_TRUE(pr.bc[0][0] == BcN::Periodic && pr.bc[0][1] == BcN::Periodic);
  EXPECT_TRUE(pr.bc[1][0] == BcN::Outflow && pr.bc[1][1] == BcN::Outflow);
  ASSERT_TRUE(pr.exact);
  for (double t : {0.0, 0.1, 0.2})
    for (int j = 0; j < 100; ++j) {
      const double y = (j + 0.5) / 100.0;
      const Prim w = t == 0.0 ? p1.initial(y) : p1.exact(y, t);
      for (double x : {0.125, 0.625}) {
        const double pos[3] = {x, y, 0.0};
        const PrimN q = t == 0.0 ? pr.initial(pos) : pr.exact(pos, t);
        EXPECT_EQ(q.rho, w.rho);
        EXPECT_EQ(q.u[1], w.u);
        EXPECT_EQ(q.u[0], 0.0);
        EXPECT_EQ(q.u[2], 0.0);
        EXPECT_EQ(q.p, w.p);
      }
    }
}

TEST(EulerProblemND, PlanarInflowBecomesCustomGhost) {
  Problem p1;
  ASSERT_EQ(createProblem(PETSC_COMM_WORLD, "shu_osher", &p1), 0);
  ASSERT_EQ(p1.bc_left, Bc::Inflow);
  const ProblemND pr = make("shu_osher", 3, 2);
  EXPECT_TRUE(pr.bc[2][0] == BcN::Custom);
  EXPECT_TRUE(pr.bc[2][1] == BcN::Outflow);
  ASSERT_TRUE(pr.ghost);
  const double x[3] = {0.5, 0.5, p1.xmin - 0.01};
  const PrimN edge{9.0, {0, 0, 0}, 9.0};
  const PrimN g = pr.ghost(2, 0, x, 0.3, edge, edge);
  EXPECT_EQ(g.rho, p1.inflow_left.rho);
  EXPECT_EQ(g.u[2], p1.inflow_left.u);
  EXPECT_EQ(g.u[0], 0.0);
  EXPECT_EQ(g.p, p1.inflow_left.p);
}

TEST(EulerProblemND, PlanarAxisMustExist) {
  const std::string msg = failureMessage("sod", 2, 2);
  EXPECT_NE(msg.find("-axis"), std::string::npos) << msg;
}

TEST(EulerProblemND, DoubleMachPostShockSatisfiesRankineHugoniot) {
  const ProblemND pr = make("double_mach", 2);
  EXPECT_EQ(pr.default_n[0], 480);
  EXPECT_EQ(pr.default_n[1], 120);
  EXPECT_DOUBLE_EQ(pr.hi[0], 4.0);
  EXPECT_DOUBLE_EQ(pr.t_final, 0.2);
  const double behind[3] = {0.05, 0.5, 0}, ahead[3] = {3.0, 0.5, 0};
  const PrimN post = pr.initial(behind), pre = pr.initial(ahead);
  // Woodward & Colella's numbers
  EXPECT_NEAR(post.rho, 8.0, 1e-12);
  EXPECT_NEAR(post.p, 116.5, 1e-11);
  EXPECT_NEAR(post.u[0], 8.25 * std::cos(M_PI / 6), 1e-12);
  EXPECT_NEAR(post.u[1], -8.25 * 0.5, 1e-12);
  EXPECT_NEAR(pre.rho, 1.4, 1e-15);
  EXPECT_NEAR(pre.p, 1.0, 1e-15);
  // Rankine-Hugoniot across a shock moving at S = 10 along the normal n = (sin 60, -cos 60)
  const double n[2] = {std::sqrt(3.0) / 2, -0.5}, S = 10.0, g = pr.gamma;
  auto fluxes = [&](const PrimN& w, double f[4]) {
    const double un = w.u[0] * n[0] + w.u[1] * n[1] - S, ut = -w.u[0] * n[1] + w.u[1] * n[0];
    f[0] = w.rho * un;
    f[1] = w.rho * un * un + w.p;
    f[2] = w.rho * un * ut;
    // energy flux in the shock frame: rho un (e + p / rho + (un^2 + ut^2) / 2)
    f[3] = w.rho * un * (w.p / ((g - 1) * w.rho) + w.p / w.rho + 0.5 * (un * un + ut * ut));
  };
  double a[4], b[4];
  fluxes(post, a);
  fluxes(pre, b);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(a[k], b[k], 1e-10 * (1 + std::abs(b[k]))) << k;
  // initial shock line passes through (1/6, 0) at 60 degrees
  const double just_left[3] = {1.0 / 6 + 0.5 / std::sqrt(3.0) - 1e-9, 0.5, 0};
  const double just_right[3] = {1.0 / 6 + 0.5 / std::sqrt(3.0) + 1e-9, 0.5, 0};
  EXPECT_EQ(pr.initial(just_left).rho, post.rho);
  EXPECT_EQ(pr.initial(just_right).rho, pre.rho);
}

TEST(EulerProblemND, DoubleMachGhostStates) {
  const ProblemND pr = make("double_mach", 2);
  ASSERT_TRUE(pr.ghost);
  EXPECT_TRUE(pr.bc[0][0] == BcN::Custom && pr.bc[0][1] == BcN::Outflow);
  EXPECT_TRUE(pr.bc[1][0] == BcN::Custom && pr.bc[1][1] == BcN::Custom);
  const double behind[3] = {0.05, 0.5, 0};
  const PrimN post = pr.initial(behind);
  const PrimN mirror{2.0, {0.3, 0.7, 0.0}, 3.0}, edge{2.5, {0.1, 0.2, 0.0}, 3.5};
  // top: switches at x_s(t) = 1/6 + (y + 20 t) / sqrt(3), the exact shock line at the ghost centre
  for (double t : {0.0, 0.1, 0.2}) {
    const double y = 1.0 + 0.5 / 120;
    const double xs = 1.0 / 6 + (y + 20 * t) / std::sqrt(3.0);
    const double l[3] = {xs - 1e-6, y, 0}, r[3] = {xs + 1e-6, y, 0};
    EXPECT_EQ(pr.ghost(1, 1, l, t, mirror, edge).rho, post.rho) << t;
    EXPECT_EQ(pr.ghost(1, 1, r, t, mirror, edge).rho, 1.4) << t;
    // and within half a cell of the top-face formula 1/6 + (1 + 20 t) / sqrt(3)
    EXPECT_NEAR(xs, 1.0 / 6 + (1 + 20 * t) / std::sqrt(3.0), 0.5 / 120);
  }
  // bottom: post-shock for x < 1/6, reflecting wall beyond
  const double b1[3] = {0.1, -0.004, 0}, b2[3] = {0.2, -0.004, 0};
  expectStateNear(pr.ghost(1, 0, b1, 0.1, mirror, edge), post, 0.0);
  const PrimN w = pr.ghost(1, 0, b2, 0.1, mirror, edge);
  expectStateNear(w, PrimN{2.0, {0.3, -0.7, 0.0}, 3.0}, 0.0);
  // left: post-shock inflow
  const double lft[3] = {-0.004, 0.9, 0};
  expectStateNear(pr.ghost(0, 0, lft, 0.1, mirror, edge), post, 0.0);
}

TEST(EulerProblemND, RayleighTaylorHydrostaticAndUnstable) {
  const ProblemND pr = make("rayleigh_taylor", 2);
  EXPECT_NEAR(pr.gamma, 5.0 / 3.0, 1e-15);
  EXPECT_DOUBLE_EQ(pr.hi[0], 0.25);
  EXPECT_DOUBLE_EQ(pr.t_final, 1.95);
  const double g = pr.gravity[1];
  EXPECT_EQ(pr.gravity[0], 0.0);
  // dp/dy = rho g by central differences on a 256-cell column (cells not touching the interface y = 1/2)
  const int ny = 256;
  const double h = 1.0 / ny;
  double maxres = 0.0;
  for (int j = 1; j < ny - 1; ++j) {
    const double y = (j + 0.5) * h;
    if (std::abs(y - 0.5) < 1.5 * h) continue;
    const double xa[3] = {0.0625, y + h, 0}, xb[3] = {0.0625, y - h, 0}, xc[3] = {0.0625, y, 0};
    const double dpdy = (pr.initial(xa).p - pr.initial(xb).p) / (2 * h);
    maxres = std::max(maxres, std::abs(dpdy - pr.initial(xc).rho * g));
  }
  EXPECT_LT(maxres, 1e-10);
  // the heavy fluid sits on the side gravity points to... the wrong way: rho decreases along g (unstable)
  const double lo[3] = {0.1, 0.25, 0}, hi[3] = {0.1, 0.75, 0};
  EXPECT_GT((pr.initial(lo).rho - pr.initial(hi).rho) * g, 0.0);
  // the paper's data: p(0.25) = 1.5, p(0.75) = 2.25, v = -0.025 c cos(8 pi x)
  EXPECT_NEAR(pr.initial(lo).p, 1.5, 1e-15);
  EXPECT_NEAR(pr.initial(hi).p, 2.25, 1e-15);
  const double x0[3] = {0.0, 0.25, 0};
  EXPECT_NEAR(pr.initial(x0).u[1], -0.025 * std::sqrt(5.0 / 3.0 * 1.5 / 2.0), 1e-15);
  // top / bottom ghosts: the fixed states
  const PrimN m{1, {0, 0, 0}, 1};
  const double gb[3] = {0.1, -0.002, 0}, gt[3] = {0.1, 1.002, 0};
  expectStateNear(pr.ghost(1, 0, gb, 0.5, m, m), PrimN{2.0, {0, 0, 0}, 1.0}, 0.0);
  expectStateNear(pr.ghost(1, 1, gt, 0.5, m, m), PrimN{1.0, {0, 0, 0}, 2.5}, 0.0);
  EXPECT_TRUE(pr.bc[0][0] == BcN::Reflecting && pr.bc[0][1] == BcN::Reflecting);
}

TEST(EulerProblemND, Riemann2dPresetsArePublishedStates) {
  struct Case {
    const char* name;
    double t;
    PrimN q[4]; // ne, nw, sw, se
  };
  const Case cases[] = {
      {"liska_wendroff_3",
       0.3,
       {{1.5, {0, 0, 0}, 1.5},
        {0.5323, {1.206, 0, 0}, 0.3},
        {0.138, {1.206, 1.206, 0}, 0.029},
        {0.5323, {0, 1.206, 0}, 0.3}}},
      {"lax_liu_4",
       0.25,
       {{1.1, {0, 0, 0}, 1.1},
        {0.5065, {0.8939, 0, 0}, 0.35},
        {1.1, {0.8939, 0.8939, 0}, 1.1},
        {0.5065, {0, 0.8939, 0}, 0.35}}},
      {"lax_liu_6",
       0.3,
       {{1, {0.75, -0.5, 0}, 1}, {2, {0.75, 0.5, 0}, 1}, {1, {-0.75, 0.5, 0}, 1}, {3, {-0.75, -0.5, 0}, 1}}},
  };
  const double pts[4][3] = {{0.75, 0.75, 0}, {0.25, 0.75, 0}, {0.25, 0.25, 0}, {0.75, 0.25, 0}};
  for (const auto& c : cases) {
    const ProblemND pr = make(c.name, 2);
    EXPECT_DOUBLE_EQ(pr.t_final, c.t) << c.name;
    EXPECT_TRUE(pr.bc[0][0] == BcN::Outflow && pr.bc[1][1] == BcN::Outflow);
    for (int k = 0; k < 4; ++k) expectStateNear(pr.initial(pts[k]), c.q[k], 0.0);
  }
}

TEST(EulerProblemND, Riemann2dShocksSatisfyRankineHugoniot) {
  // Configurations 3 and 4: each interface emits a single shock, so the 1D Riemann problem normal to it has a
  // star state equal (to the four published digits) to one of its two states.
  for (const char* name : {"liska_wendroff_3", "lax_liu_4"}) {
    const ProblemND pr = make(name, 2);
    const double ne[3] = {0.75, 0.75, 0}, nw[3] = {0.25, 0.75, 0}, sw[3] = {0.25, 0.25, 0},
                 se[3] = {0.75, 0.25, 0};
    struct Pair {
      const double *a, *b; // a left/below, b right/above
      int dir;
    };
    const Pair pairs[] = {{nw, ne, 0}, {sw, se, 0}, {se, ne, 1}, {sw, nw, 1}};
    for (const auto& pp : pairs) {
      const PrimN A = pr.initial(pp.a), B = pr.initial(pp.b);
      EXPECT_NEAR(A.u[1 - pp.dir], B.u[1 - pp.dir], 1e-12); // tangential velocity continuous across a shock
      ExactRiemann rs({A.rho, A.u[pp.dir], A.p}, {B.rho, B.u[pp.dir], B.p}, pr.gamma);
      const double dA = std::abs(rs.pStar() - A.p) / A.p + std::abs(rs.uStar() - A.u[pp.dir]);
      const double dB = std::abs(rs.pStar() - B.p) / B.p + std::abs(rs.uStar() - B.u[pp.dir]);
      EXPECT_LT(std::min(dA, dB), 2e-3)
          << name << " dir " << pp.dir << " p* " << rs.pStar() << " u* " << rs.uStar();
    }
  }
}

TEST(EulerProblemND, Riemann2dSlipLinesOfConfiguration6) {
  const ProblemND pr = make("lax_liu_6", 2);
  const double ne[3] = {0.75, 0.75, 0}, nw[3] = {0.25, 0.75, 0}, sw[3] = {0.25, 0.25, 0},
               se[3] = {0.75, 0.25, 0};
  const PrimN NE = pr.initial(ne), NW = pr.initial(nw), SW = pr.initial(sw), SE = pr.initial(se);
  // contact / slip lines: pressure and normal velocity continuous
  EXPECT_EQ(NE.u[0], NW.u[0]);
  EXPECT_EQ(SE.u[0], SW.u[0]);
  EXPECT_EQ(NE.u[1], SE.u[1]);
  EXPECT_EQ(NW.u[1], SW.u[1]);
  for (const PrimN* q : {&NE, &NW, &SW, &SE}) EXPECT_EQ(q->p, 1.0);
}

TEST(EulerProblemND, Riemann2dOptionsAndNegativeDensityRefused) {
  {
    ScopedOption a("-rho_sw", "0.7"), b("-x0", "0.3");
    const ProblemND pr = make("riemann2d", 2);
    const double x[3] = {0.2, 0.1, 0}, y[3] = {0.35, 0.1, 0};
    EXPECT_EQ(pr.initial(x).rho, 0.7);
    EXPECT_EQ(pr.initial(y).rho, 0.5323); // se of the default (configuration 3)
  }
  ScopedOption o("-rho_ne", "-1");
  const std::string msg = failureMessage("riemann2d", 2);
  EXPECT_NE(msg.find("-rho_ne"), std::string::npos) << msg;
}

TEST(EulerProblemND, TaylorGreenNeedsThreeDimensions) {
  const std::string msg = failureMessage("taylor_green", 2);
  EXPECT_NE(msg.find("-dim 3"), std::string::npos) << msg;
  const ProblemND pr = make("taylor_green", 3);
  EXPECT_NEAR(pr.hi[0], 2 * M_PI, 1e-15);
  // divergence-free velocity (central differences, O(h^2)) and p0 = 1 / (gamma M^2)
  const double h = 1e-4, x[3] = {0.3, 1.1, 2.2};
  double div = 0.0;
  for (int d = 0; d < 3; ++d) {
    double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
    xp[d] += h;
    xm[d] -= h;
    div += (pr.initial(xp).u[d] - pr.initial(xm).u[d]) / (2 * h);
  }
  EXPECT_NEAR(div, 0.0, 1e-8);
  const double c[3] = {M_PI / 4, M_PI / 4, M_PI / 4}; // cos 2x = cos 2y = 0
  EXPECT_NEAR(pr.initial(c).p, 1.0 / (1.4 * 0.01), 1e-12);
}

TEST(EulerProblemND, ExplosionAndSedov) {
  for (int dim : {2, 3}) {
    const ProblemND pr = make("explosion", dim);
    const double in[3] = {0.2, 0.2, 0.1}, out[3] = {0.5, 0.5, 0.0};
    expectStateNear(pr.initial(in), PrimN{1, {0, 0, 0}, 1}, 0.0);
    expectStateNear(pr.initial(out), PrimN{0.125, {0, 0, 0}, 0.1}, 0.0);
    EXPECT_TRUE(pr.bc[dim - 1][0] == BcN::Outflow);
    EXPECT_DOUBLE_EQ(pr.t_final, 0.25);
  }
  // Sedov: the deposited energy sum p / (gamma - 1) dV converges to E = 1 (cells by centre)
  for (int dim : {2, 3}) {
    const ProblemND pr = make("sedov", dim);
    const int n = dim == 2 ? 400 : 128;
    const double h = 2.0 / n;
    double e = 0.0;
    const int nz = dim == 3 ? n : 1;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const double x[3] = {-1 + (i + 0.5) * h, -1 + (j + 0.5) * h, dim == 3 ? -1 + (k + 0.5) * h : 0.0};
          const PrimN w = pr.initial(x);
          if (w.p > 1e-3) e += w.p / (pr.gamma - 1) * std::pow(h, dim);
        }
    std::printf("  sedov dim %d: deposited energy %.4f\n", dim, e);
    // staircase error of a ball with a radius of 12.5 (2D) or 4 (3D) cells
    EXPECT_NEAR(e, 1.0, dim == 2 ? 0.03 : 0.08) << dim;
  }
}

TEST(EulerProblemND, UnknownProblemAndDimensionRefused) {
  const std::string msg = failureMessage("no_such_problem", 2);
  EXPECT_NE(msg.find("no_such_problem"), std::string::npos) << msg;
  for (const char* name : {"isentropic_vortex", "double_mach", "taylor_green", "sod"})
    EXPECT_NE(msg.find(name), std::string::npos) << msg;
  EXPECT_NE(failureMessage("isentropic_vortex", 4).find("-dim"), std::string::npos);
  EXPECT_NE(failureMessage("sod", 1).find("-dim"), std::string::npos);
}

TEST(EulerProblemND, EveryProblemBuildsInTwoAndThreeDimensions) {
  const char* names[] = {"isentropic_vortex",
                         "riemann2d",
                         "lax_liu_4",
                         "lax_liu_6",
                         "liska_wendroff_3",
                         "double_mach",
                         "rayleigh_taylor",
                         "explosion",
                         "sedov",
                         "density_wave",
                         "pulse"};
  for (int dim : {2, 3})
    for (const char* name : names) {
      const ProblemND pr = make(name, dim, 0);
      EXPECT_EQ(pr.dim, dim);
      EXPECT_EQ(pr.name, name);
      ASSERT_TRUE(pr.initial) << name;
      for (int d = 0; d < 3; ++d) {
        EXPECT_LT(pr.lo[d], pr.hi[d]) << name;
        EXPECT_GE(pr.default_n[d], 1) << name;
        for (int s = 0; s < 2; ++s)
          if (pr.bc[d][s] == BcN::Custom) {
            EXPECT_TRUE(pr.ghost) << name;
          }
      }
      if (dim == 2) {
        EXPECT_EQ(pr.default_n[2], 1) << name;
      }
      const double mid[3] = {0.5 * (pr.lo[0] + pr.hi[0]) + 0.01, 0.5 * (pr.lo[1] + pr.hi[1]) + 0.02,
                             0.5 * (pr.lo[2] + pr.hi[2])};
      const PrimN w = pr.initial(mid);
      EXPECT_GT(w.rho, 0.0) << name;
      EXPECT_GT(w.p, 0.0) << name;
    }
}
