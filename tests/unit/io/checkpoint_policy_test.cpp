// CheckpointPolicy: option checks, due() by step count, file naming, pruning to -checkpoint_keep, and
// -restart latest picking the highest complete step (a .tmp left by a killed write is ignored).
#include "../test_helpers.hpp"
#include "io/checkpoint.hpp"
#include "io/checkpoint_policy.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace {

using suite_test::fileExists;
using suite_test::quietly;

void setOptions(const char* text) {
  PetscOptionsClear(nullptr);
  PetscOptionsInsertString(nullptr, text);
}

PetscErrorCode writeTiny(const std::string& path, long long step) {
  double v[2] = {1.0 * step, 2.0};
  suite::CheckpointHeader h{"unit", "", step, 0.1 * step, 0.1, {2}};
  return suite::writeCheckpoint(PETSC_COMM_WORLD, path, h, {{"v", {2}, {0}, {2}, v}});
}

TEST(CheckpointPolicy, DueEveryNStepsNamesAndPrunes) {
  const std::string dir = "unit_ckpt_policy";
  setOptions(("-checkpoint_dir " + dir + " -checkpoint_every 3 -checkpoint_keep 2").c_str());
  suite::CheckpointPolicy p;
  ASSERT_EQ(p.setFromOptions(PETSC_COMM_WORLD, "unit"), 0);
  EXPECT_TRUE(p.enabled());
  EXPECT_EQ(p.pathForStep(12), dir + "/unit_0000000012.h5");
  std::vector<long long> due;
  for (long long s = 0; s <= 10; ++s) {
    bool yes = false;
    ASSERT_EQ(p.due(s, &yes), 0);
    if (yes) due.push_back(s);
  }
  EXPECT_EQ(due, (std::vector<long long>{3, 6, 9}));
  for (long long s : due) {
    ASSERT_EQ(writeTiny(p.pathForStep(s), s), 0);
    ASSERT_EQ(p.written(s), 0);
  }
  EXPECT_FALSE(fileExists(p.pathForStep(3))); // pruned: keep the newest 2
  EXPECT_TRUE(fileExists(p.pathForStep(6)));
  EXPECT_TRUE(fileExists(p.pathForStep(9)));
  // A killed write leaves only a .tmp: 'latest' must not pick it.
  std::ofstream(p.pathForStep(12) + ".tmp") << "partial";
  setOptions(("-checkpoint_dir " + dir + " -restart latest").c_str());
  suite::CheckpointPolicy r;
  ASSERT_EQ(r.setFromOptions(PETSC_COMM_WORLD, "unit"), 0);
  std::string path;
  ASSERT_EQ(r.restartPath(&path), 0);
  EXPECT_EQ(path, dir + "/unit_0000000009.h5");
  std::remove((p.pathForStep(12) + ".tmp").c_str());
  std::remove(p.pathForStep(6).c_str());
  std::remove(p.pathForStep(9).c_str());
  rmdir(dir.c_str());
  PetscOptionsClear(nullptr);
}

TEST(CheckpointPolicy, RejectsBadOptionsAndMissingRestart) {
  for (const char* bad :
       {"-checkpoint_every 5", "-checkpoint_dir d -checkpoint_every -1",
        "-checkpoint_dir d -checkpoint_keep 0", "-restart latest", "-checkpoint_dir /nonexistent_parent/x"}) {
    setOptions(bad);
    suite::CheckpointPolicy p;
    EXPECT_NE(quietly([&] { return p.setFromOptions(PETSC_COMM_WORLD, "unit"); }), 0) << bad;
  }
  rmdir("d");
  setOptions("-checkpoint_dir unit_ckpt_empty -restart latest");
  suite::CheckpointPolicy p;
  ASSERT_EQ(p.setFromOptions(PETSC_COMM_WORLD, "unit"), 0);
  std::string path;
  EXPECT_NE(quietly([&] { return p.restartPath(&path); }), 0);
  setOptions("-restart no_such_checkpoint.h5");
  suite::CheckpointPolicy q;
  ASSERT_EQ(q.setFromOptions(PETSC_COMM_WORLD, "unit"), 0);
  EXPECT_NE(quietly([&] { return q.restartPath(&path); }), 0);
  rmdir("unit_ckpt_empty");
  PetscOptionsClear(nullptr);
}

} // namespace
