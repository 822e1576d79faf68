// Exact Riemann solver, vacuum cases of Toro (2009) sec. 4.6: a right vacuum state (4.76)-(4.78), a left vacuum
// state (4.79)-(4.81) and vacuum generation (4.82)-(4.83), checked against Toro's closed-form fan written out
// here, the Riemann invariant and isentropy across the fan, and the limit of a near-vacuum state.
#include "euler/exact_riemann.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace suite::euler;

namespace {
// Toro (4.77): the left fan in his form, W = (rho, u, p) at s for a state w with sound speed a.
Prim toroLeftFan(const Prim& w, double g, double s) {
  const double a = std::sqrt(g * w.p / w.rho);
  const double base = 2.0 / (g + 1.0) + (g - 1.0) / ((g + 1.0) * a) * (w.u - s);
  return {w.rho * std::pow(base, 2.0 / (g - 1.0)), 2.0 / (g + 1.0) * (a + 0.5 * (g - 1.0) * w.u + s),
          w.p * std::pow(base, 2.0 * g / (g - 1.0))};
}
// Toro (4.80): the right fan.
Prim toroRightFan(const Prim& w, double g, double s) {
  const double a = std::sqrt(g * w.p / w.rho);
  const double base = 2.0 / (g + 1.0) - (g - 1.0) / ((g + 1.0) * a) * (w.u - s);
  return {w.rho * std::pow(base, 2.0 / (g - 1.0)), 2.0 / (g + 1.0) * (-a + 0.5 * (g - 1.0) * w.u + s),
          w.p * std::pow(base, 2.0 * g / (g - 1.0))};
}
void expectState(const Prim& got, const Prim& want, double rel) {
  EXPECT_NEAR(got.rho, want.rho, rel * std::abs(want.rho) + 1e-300);
  EXPECT_NEAR(got.u, want.u, rel * std::abs(want.u) + 1e-14);
  EXPECT_NEAR(got.p, want.p, rel * std::abs(want.p) + 1e-300);
}
} // namespace

TEST(EulerExactRiemannVacuum, RightVacuumMatchesToro4_76) {
  const double g = 1.4;
  const Prim L{1.0, 0.5, 0.4};
  const ExactRiemann rp(L, {0.0, 0.0, 0.0}, g);
  ASSERT_EQ(rp.vacuumKind(), ExactRiemann::Vacuum::Right);
  const double a = std::sqrt(g * L.p / L.rho), front = L.u + 2.0 * a / (g - 1.0); // S*L of (4.78)
  EXPECT_DOUBLE_EQ(rp.pStar(), 0.0);
  EXPECT_DOUBLE_EQ(rp.uStar(), front);
  expectState(rp.sample(L.u - a - 1e-9), L, 0.0);
  for (double f : {0.01, 0.25, 0.5, 0.75, 0.99}) {
    const double s = (L.u - a) + f * (front - (L.u - a));
    const Prim w = rp.sample(s), t = toroLeftFan(L, g, s);
    expectState(w, t, 1e-13);
    // Along the fan the Riemann invariant u + 2 c / (gamma - 1) and the entropy p / rho^gamma are constant.
    EXPECT_NEAR(w.u + 2.0 * std::sqrt(g * w.p / w.rho) / (g - 1.0), front, 1e-12);
    EXPECT_NEAR(w.p / std::pow(w.rho, g), L.p / std::pow(L.rho, g), 1e-12);
  }
  const Prim v = rp.sample(front + 1e-9);
  EXPECT_EQ(v.rho, 0.0);
  EXPECT_EQ(v.p, 0.0);
}

TEST(EulerExactRiemannVacuum, LeftVacuumMatchesToro4_79AndMirrorsTheRight) {
  const double g = 5.0 / 3.0;
  const Prim R{2.0, -0.3, 1.5};
  const ExactRiemann rp({0.0, 0.0, 0.0}, R, g);
  ASSERT_EQ(rp.vacuumKind(), ExactRiemann::Vacuum::Left);
  const double a = std::sqrt(g * R.p / R.rho), front = R.u - 2.0 * a / (g - 1.0); // S*R of (4.81)
  EXPECT_DOUBLE_EQ(rp.uStar(), front);
  expectState(rp.sample(R.u + a + 1e-9), R, 0.0);
  EXPECT_EQ(rp.sample(front - 1e-9).rho, 0.0);
  const ExactRiemann mirror({R.rho, -R.u, R.p}, {0.0, 0.0, 0.0}, g);
  for (double f : {0.02, 0.3, 0.6, 0.97}) {
    const double s = front + f * (R.u + a - front);
    const Prim w = rp.sample(s), m = mirror.sample(-s);
    expectState(w, toroRightFan(R, g, s), 1e-13);
    expectState(w, {m.rho, -m.u, m.p}, 1e-13);
  }
}

TEST(EulerExactRiemannVacuum, GeneratedVacuumBetweenTwoFans) {
  // u = -/+4 at rho = 1, p = 0.4: 2 (cL + cR) / (gamma - 1) = 7.483 < 8, vacuum generated (4.40).
  const double g = 1.4;
  const Prim L{1.0, -4.0, 0.4}, R{1.0, 4.0, 0.4};
  const ExactRiemann rp(L, R, g);
  ASSERT_EQ(rp.vacuumKind(), ExactRiemann::Vacuum::Generated);
  const double a = std::sqrt(g * 0.4), sL = -4.0 + 2.0 * a / (g - 1.0), sR = -sL;
  expectState(rp.sample(0.5 * (sL - 4.0 - a)), toroLeftFan(L, g, 0.5 * (sL - 4.0 - a)), 1e-13);
  expectState(rp.sample(0.5 * (sR + 4.0 + a)), toroRightFan(R, g, 0.5 * (sR + 4.0 + a)), 1e-13);
  EXPECT_EQ(rp.sample(0.0).rho, 0.0);
  EXPECT_EQ(rp.sample(0.99 * sR).p, 0.0);
}

TEST(EulerExactRiemannVacuum, NearVacuumStateTendsToTheVacuumSolution) {
  // The ordinary solver with rho = p = eps on the right: the same left fan, and a contact (the end of the fan)
  // that approaches the vacuum front uL + 2 cL / (gamma - 1) from below as eps -> 0.
  const double g = 1.4;
  const Prim L{1.0, 0.0, 1.0};
  const ExactRiemann vac(L, {0.0, 0.0, 0.0}, g);
  double previous = vac.uStar();
  for (double eps : {1e-6, 1e-10, 1e-14}) {
    const ExactRiemann near(L, {eps, 0.0, eps}, g);
    EXPECT_FALSE(near.vacuum());
    const double gap = vac.uStar() - near.uStar();
    EXPECT_GT(gap, 0.0);
    EXPECT_LT(gap, previous);
    previous = gap;
    expectState(near.sample(0.0), vac.sample(0.0), 1e-14); // inside the left fan of both
  }
  EXPECT_LT(previous, 0.02 * vac.uStar());
}

TEST(EulerExactRiemannVacuum, RefusesTwoVacuaAndHalfVacuumStates) {
  const Prim zero{0.0, 0.0, 0.0};
  EXPECT_THROW(ExactRiemann(zero, zero, 1.4), std::invalid_argument);
  EXPECT_THROW(ExactRiemann({0.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, 1.4), std::invalid_argument); // p > 0, rho = 0
  EXPECT_THROW(ExactRiemann({1.0, 0.0, 1.0}, {-1.0, 0.0, 1.0}, 1.4), std::invalid_argument);
  EXPECT_THROW(ExactRiemann({1.0, 0.0, 1.0}, zero, 1.0), std::invalid_argument);
}
