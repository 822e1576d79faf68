// Size and memory checks (core/resource_checks.hpp): cgroup limit files parsed from a given path, the files
// of a given /proc/self/cgroup listing, the PetscInt count check, and the memory check with its overrides
// (-max_memory_gib, -memory_check false).
#include "../test_helpers.hpp"
#include "core/resource_checks.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

using suite_test::quietly;

// A file with `text` in the temporary directory (one name per rank and test).
std::string writeTemp(const std::string& tag, const std::string& text) {
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  const std::string path =
      "/tmp/suite_cgroup_" + tag + "_" + std::to_string(getpid()) + "_" + std::to_string(rank);
  std::ofstream(path) << text;
  return path;
}

TEST(CgroupLimit, ParsesBytesAndNoLimit) {
  const std::string v2 = writeTemp("v2", "8589934592\n");
  EXPECT_EQ(suite::cgroupLimitBytes(v2), 8589934592.0);
  const std::string none = writeTemp("max", "max\n");
  EXPECT_EQ(suite::cgroupLimitBytes(none), 0.0);
  const std::string v1 = writeTemp("v1", "9223372036854771712\n"); // v1's "unlimited"
  EXPECT_EQ(suite::cgroupLimitBytes(v1), 0.0);
  const std::string bad = writeTemp("bad", "12x\n");
  EXPECT_EQ(suite::cgroupLimitBytes(bad), 0.0);
  const std::string neg = writeTemp("neg", "-5\n");
  EXPECT_EQ(suite::cgroupLimitBytes(neg), 0.0);
  EXPECT_EQ(suite::cgroupLimitBytes("/nonexistent/memory.max"), 0.0);
  for (const auto& p : {v2, none, v1, bad, neg}) std::remove(p.c_str());
}

TEST(CgroupLimit, FilesOfTheProcessCgroup) {
  const std::string proc = writeTemp("proc", "4:memory:/job/42\n1:cpu,cpuacct:/job/42\n0::/user.slice/x\n");
  const auto files = suite::cgroupLimitFiles(proc, "/cg");
  std::remove(proc.c_str());
  const std::vector<std::string> want = {"/cg/memory.max", "/cg/memory/memory.limit_in_bytes",
                                         "/cg/memory/job/42/memory.limit_in_bytes",
                                         "/cg/user.slice/x/memory.max"};
  EXPECT_EQ(files, want);
  const auto root_only = suite::cgroupLimitFiles("/nonexistent", "/cg");
  EXPECT_EQ(root_only.size(), 2u);
}

TEST(CgroupLimit, NodeMemoryIsPositiveAndAtMostPhysical) {
  const double phys = (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGESIZE);
  EXPECT_GT(suite::nodeMemoryBytes(), 0.0);
  EXPECT_LE(suite::nodeMemoryBytes(), phys);
}

TEST(SizeChecks, IndexCountBeyondPetscIntIsAnError) {
  EXPECT_EQ(suite::checkIndexCount(PETSC_COMM_WORLD, 1e6, "cells", "-nx 1000000"), 0);
  EXPECT_EQ(quietly([] { return suite::checkIndexCount(PETSC_COMM_WORLD, 3e11, "DOFs", "-beam_cells"); }),
            PETSC_ERR_ARG_OUTOFRANGE);
}

TEST(SizeChecks, MemoryLimitOptionAndOverride) {
  EXPECT_EQ(suite::checkMemoryEstimate(PETSC_COMM_WORLD, 1e6, "a small run"), 0);
  EXPECT_EQ(quietly([] { return suite::checkMemoryEstimate(PETSC_COMM_WORLD, 1e18, "a huge run"); }),
            PETSC_ERR_MEM);
  PetscOptionsSetValue(nullptr, "-max_memory_gib", "0.001"); // 1 MiB per node
  EXPECT_EQ(quietly([] { return suite::checkMemoryEstimate(PETSC_COMM_WORLD, 2e6, "a 2 MB run"); }),
            PETSC_ERR_MEM);
  EXPECT_EQ(suite::checkMemoryEstimate(PETSC_COMM_WORLD, 1e5, "a 100 kB run"), 0);
  PetscOptionsSetValue(nullptr, "-memory_check", "false");
  EXPECT_EQ(suite::checkMemoryEstimate(PETSC_COMM_WORLD, 1e18, "a huge run"), 0);
  PetscOptionsClearValue(nullptr, "-memory_check");
  PetscOptionsClearValue(nullptr, "-max_memory_gib");
}

TEST(SizeChecks, BytesText) {
  EXPECT_EQ(suite::bytesText(512), "512 bytes");
  EXPECT_EQ(suite::bytesText(1.5 * 1073741824.0), "1.5 GiB");
}

} // namespace
