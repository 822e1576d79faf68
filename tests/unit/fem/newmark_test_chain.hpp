// A small nonlinear test system for the Newmark integrator's Newton variants (tests/unit/fem): two masses on
// hardening springs (ground - m1 - m2), f = K u + c (u_1^3, (u_2 - u_1)^3 terms), SPD tangent, driven by
// f_2 = 2 sin(3 t) (times load_scale).
#pragma once

#include "fem/linear_solver.hpp"
#include "fem/newmark.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace femtest {

class CubicChain final : public suite::fem::SecondOrderSystem {
public:
  CubicChain() { K_.n = 2, K_.colptr = {0, 1, 3}, K_.rowind = {0, 0, 1}, K_.val = {0, 0, 0}; }
  const suite::fem::SymCsc& pattern() const override { return K_; }
  bool internalForce(const double* u, double* f, std::vector<double>* K, double* energy) override {
    const double d = u[1] - u[0];
    const double s1 = u[0] + c_ * u[0] * u[0] * u[0], s2 = d + c_ * d * d * d;
    f[0] = s1 - s2, f[1] = s2;
    const double k1 = 1 + 3 * c_ * u[0] * u[0], k2 = 1 + 3 * c_ * d * d;
    if (K) *K = {k1 + k2, -k2, k2};
    if (energy)
      *energy =
          0.5 * u[0] * u[0] + 0.25 * c_ * u[0] * u[0] * u[0] * u[0] + 0.5 * d * d + 0.25 * c_ * d * d * d * d;
    return true;
  }

private:
  suite::fem::SymCsc K_;
  double c_ = 20.0;
};

inline suite::fem::NewmarkParams chainParams(bool tangent_predictor) {
  suite::fem::NewmarkParams p;
  p.newton_rtol = 1e-10;
  p.newton_atol = 0;
  p.tangent_predictor = tangent_predictor;
  return p;
}

// The chain with unit masses (M = I), its solver, integrator and state; load_scale scales the drive.
struct ChainRun {
  CubicChain sys;
  std::unique_ptr<suite::fem::LinearSolver> solver = suite::fem::makeBandedSolver();
  suite::fem::Newmark nm;
  suite::fem::NewmarkState s;
  double load_scale = 1.0;
  static void load(double t, double scale, double* f) { f[0] = 0, f[1] = 2 * scale * std::sin(3 * t); }
  explicit ChainRun(const suite::fem::NewmarkParams& p) {
    EXPECT_EQ(solver->analyze(PETSC_COMM_SELF, sys.pattern(), {0, 1}), 0);
    EXPECT_EQ(nm.setup(PETSC_COMM_SELF, &sys, solver.get(), {1.0, 0.0, 1.0}, p,
                       [this](double t, double* f) { load(t, load_scale, f); }),
              0);
    s.u = {0.0, 0.0}, s.v = {1.5, -1.0};
    EXPECT_EQ(nm.initialize(&s), 0);
  }
};

} // namespace femtest
