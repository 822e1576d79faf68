// The one time loop (lib/core/time_loop): a toy app, y' = -y by forward Euler, checks the loop's bookkeeping:
// the last step lands on t_final, max_steps, bounded retries at half dt, failure after the final write,
// observers, snapshot cadence, checkpoint cadence, and a restart that continues bitwise.
#include "../test_helpers.hpp"
#include "core/clocks.hpp"
#include "core/run_context.hpp"
#include "core/time_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace {

using suite::StepOutcome;
using suite::StepStatus;

class DecayApp : public suite::TimeStepped {
public:
  double y = 1.0, dt = 0.3, max_ok_dt = 1e9; // advance asks for a retry above max_ok_dt
  bool fail_at_step_3 = false;
  double first_step_cpu = 0.0, later_step_cpu = 0.0; // CPU seconds the first / every later step spins for
  std::vector<PetscInt> snapshots;
  std::vector<double> dts;
  suite::LoopSummary final_summary;
  bool final_written = false;

  PetscErrorCode start(PetscInt, double, bool) override { return 0; }
  PetscErrorCode proposeDt(PetscInt, double, double* d) override {
    *d = dt;
    return 0;
  }
  PetscErrorCode advance(PetscInt step, double t, double d, StepOutcome* out) override {
    if (d > max_ok_dt) {
      out->status = StepStatus::Retry, out->message = "dt too large";
    } else if (fail_at_step_3 && step + 1 == 3) {
      out->status = StepStatus::Failed, out->message = "injected failure";
    } else {
      const double c0 = suite::processCpuSeconds();
      while (suite::processCpuSeconds() - c0 < (step == 0 ? first_step_cpu : later_step_cpu)) {
      }
      y -= d * y;
      dts.push_back(d);
      out->t_new = t + d;
    }
    return 0;
  }
  PetscErrorCode saveState(const std::string& path, PetscInt step, double t) override {
    int rank;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    if (rank == 0) std::ofstream(path) << step << " " << std::hexfloat << t << " " << y << "\n";
    return MPI_Barrier(PETSC_COMM_WORLD);
  }
  PetscErrorCode loadState(const std::string& path, PetscInt* step, double* t) override {
    std::ifstream in(path);
    std::string ts, ys;
    in >> *step >> ts >> ys;
    *t = std::strtod(ts.c_str(), nullptr), y = std::strtod(ys.c_str(), nullptr);
    return 0;
  }
  PetscErrorCode writeSnapshot(PetscInt step, double) override {
    snapshots.push_back(step);
    return 0;
  }
  PetscErrorCode writeFinal(const suite::LoopSummary& s) override {
    final_summary = s, final_written = true;
    return 0;
  }
};

struct CountingObserver : suite::StepObserver {
  std::vector<PetscInt> before, after;
  PetscErrorCode beforeStep(PetscInt step, double, double) override {
    before.push_back(step);
    return 0;
  }
  PetscErrorCode afterStep(PetscInt step, double, double) override {
    after.push_back(step);
    return 0;
  }
};

// A RunContext over the PETSc the test main started, and a checkpoint policy from the given options.
struct Fixture {
  int argc = 1;
  char name[16] = "time_loop_test";
  char* args[2] = {name, nullptr};
  char** argv = args;
  std::unique_ptr<suite::RunContext> ctx;
  suite::CheckpointPolicy policy;
  using Options = std::vector<std::pair<std::string, std::string>>;
  explicit Fixture(const Options& opts = Options()) {
    ctx = std::make_unique<suite::RunContext>(&argc, &argv, "", "time_loop_test");
    for (const auto& [k, v] : opts) PetscOptionsSetValue(nullptr, k.c_str(), v.c_str());
    EXPECT_EQ(policy.setFromOptions(PETSC_COMM_WORLD, "decay"), 0);
    for (const auto& [k, v] : opts) PetscOptionsClearValue(nullptr, k.c_str());
  }
};

suite::TimeLoopSettings settings(double t_final, PetscInt max_steps) {
  suite::TimeLoopSettings s;
  s.app = "decay", s.t_final = t_final, s.max_steps = max_steps;
  return s;
}

TEST(TimeLoop, LastStepLandsOnFinalTime) {
  Fixture f(Fixture::Options{{"-quiet", "1"}});
  DecayApp app;
  suite::TimeLoop loop(*f.ctx, f.policy, settings(1.0, -1));
  ASSERT_EQ(loop.run(app), 0);
  EXPECT_EQ(loop.summary().steps, 4); // 0.3, 0.6, 0.9, then the clipped step to 1.0
  EXPECT_EQ(loop.summary().t, 1.0);
  ASSERT_EQ(app.dts.size(), 4u);
  EXPECT_NEAR(app.dts.back(), 0.1, 1e-15);
  EXPECT_NEAR(app.y, 0.7 * 0.7 * 0.7 * 0.9, 1e-15);
  EXPECT_TRUE(app.final_written);
  EXPECT_FALSE(loop.summary().failed || loop.summary().stopped);
}

TEST(TimeLoop, MaxStepsEndsTheRun) {
  Fixture f;
  DecayApp app;
  suite::TimeLoop loop(*f.ctx, f.policy, settings(100.0, 5));
  ASSERT_EQ(loop.run(app), 0);
  EXPECT_EQ(loop.summary().steps, 5);
  EXPECT_NEAR(loop.summary().t, 1.5, 1e-14);
}

// The summary's cpu_first is the first step's share of cpu (the accuracy-target runs time the steps after it).
TEST(TimeLoop, FirstStepCpuIsReportedApart) {
  Fixture f;
  DecayApp app;
  app.first_step_cpu = 0.02, app.later_step_cpu = 0.005;
  suite::TimeLoop loop(*f.ctx, f.policy, settings(100.0, 5));
  ASSERT_EQ(loop.run(app), 0);
  const suite::LoopSummary& s = loop.summary();
  EXPECT_GE(s.cpu_first, 0.02);
  EXPECT_LT(s.cpu_first, 0.025);        // not the second step's too
  EXPECT_GE(s.cpu - s.cpu_first, 0.02); // the four later steps
}

TEST(TimeLoop, RejectedStepRetriedAtHalfDt) {
  Fixture f;
  DecayApp app;
  app.max_ok_dt = 0.2; // 0.3 rejected once, 0.15 accepted
  auto s = settings(0.0, 2);
  s.max_retries = 3;
  suite::TimeLoop loop(*f.ctx, f.policy, s);
  ASSERT_EQ(loop.run(app), 0);
  EXPECT_EQ(loop.summary().retries, 2);
  ASSERT_EQ(app.dts.size(), 2u);
  EXPECT_EQ(app.dts[0], 0.15);
  EXPECT_EQ(loop.summary().t, 0.3);
}

TEST(TimeLoop, RetriesAreBoundedAndFailureStopsAfterFinalWrite) {
  Fixture f;
  DecayApp app;
  app.max_ok_dt = 0.01; // 0.3 -> 0.15 -> 0.075: still too large after two retries
  auto s = settings(0.0, 2);
  s.max_retries = 2;
  suite::TimeLoop loop(*f.ctx, f.policy, s);
  EXPECT_EQ(suite_test::quietly([&] { return loop.run(app); }), PETSC_ERR_NOT_CONVERGED);
  EXPECT_TRUE(app.final_written);
  EXPECT_TRUE(app.final_summary.failed);
  EXPECT_EQ(app.final_summary.steps, 0);
  EXPECT_EQ(app.final_summary.failure, "dt too large");
}

TEST(TimeLoop, FailedStepKeepsTheStateBeforeIt) {
  Fixture f;
  DecayApp app;
  app.fail_at_step_3 = true;
  suite::TimeLoop loop(*f.ctx, f.policy, settings(0.0, 10));
  EXPECT_EQ(suite_test::quietly([&] { return loop.run(app); }), PETSC_ERR_NOT_CONVERGED);
  EXPECT_EQ(app.final_summary.steps, 2);
  EXPECT_EQ(app.final_summary.failure, "injected failure");
}

TEST(TimeLoop, ObserversAndSnapshotCadence) {
  Fixture f;
  DecayApp app;
  CountingObserver obs;
  auto s = settings(0.0, 5);
  s.snapshot_every = 2;
  suite::TimeLoop loop(*f.ctx, f.policy, s);
  loop.addObserver(&obs);
  ASSERT_EQ(loop.run(app), 0);
  EXPECT_EQ(obs.before, (std::vector<PetscInt>{0, 1, 2, 3, 4}));
  EXPECT_EQ(obs.after, (std::vector<PetscInt>{1, 2, 3, 4, 5}));
  EXPECT_EQ(app.snapshots, (std::vector<PetscInt>{0, 2, 4}));
}

// A stop request ends the run after the current step with a checkpoint; a restart from it continues to the
// same state, bitwise, as an uninterrupted run.
struct StopAt : suite::StepObserver {
  PetscInt at;
  explicit StopAt(PetscInt s) : at(s) {}
  PetscErrorCode afterStep(PetscInt step, double, double) override {
    if (step == at) suite::g_stop_signal = SIGTERM;
    return 0;
  }
};

TEST(TimeLoop, StopCheckpointAndRestartContinueBitwise) {
  const std::string dir = std::filesystem::temp_directory_path() / ("time_loop_" + std::to_string(getpid()));
  int rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  DecayApp whole;
  {
    Fixture f;
    suite::TimeLoop loop(*f.ctx, f.policy, settings(0.0, 7));
    ASSERT_EQ(loop.run(whole), 0);
  }
  DecayApp first;
  {
    Fixture f(Fixture::Options{{"-checkpoint_dir", dir}, {"-checkpoint_every", "2"}});
    StopAt stop(3);
    suite::TimeLoop loop(*f.ctx, f.policy, settings(0.0, 7));
    loop.addObserver(&stop);
    ASSERT_EQ(loop.run(first), 0);
    suite::g_stop_signal = 0;
    EXPECT_TRUE(loop.summary().stopped);
    EXPECT_EQ(loop.summary().stop_reason, "signal");
    EXPECT_EQ(loop.summary().steps, 3);
    EXPECT_TRUE(std::filesystem::exists(f.policy.pathForStep(2)));
    EXPECT_TRUE(std::filesystem::exists(f.policy.pathForStep(3)));
  }
  DecayApp second;
  {
    Fixture f(Fixture::Options{{"-checkpoint_dir", dir}, {"-restart", "latest"}});
    suite::TimeLoop loop(*f.ctx, f.policy, settings(0.0, 7));
    ASSERT_EQ(loop.run(second), 0);
    EXPECT_TRUE(loop.summary().restarted);
    EXPECT_EQ(loop.summary().first_step, 3);
    EXPECT_EQ(loop.summary().stepsTaken(), 4);
    EXPECT_TRUE(std::filesystem::exists(f.policy.pathForStep(7))); // the final checkpoint
  }
  EXPECT_EQ(second.y, whole.y);
  MPI_Barrier(PETSC_COMM_WORLD);
  if (rank == 0) std::filesystem::remove_all(dir);
}

} // namespace
