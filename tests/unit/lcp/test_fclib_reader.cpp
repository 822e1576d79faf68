// FCLib reader: two files written by libfclib itself (tests/lcpbench/fclib_gen.c: dense triplets in 3-D,
// CSC in 2-D) give the normal-contact LCP (entries compared with the generator's formula, solution checked
// against enumeration of all 2^n index sets); malformed / hostile files written with the suite's HDF5 are
// refused with clear messages.
#include "io/h5_append.hpp"
#include "lcp/readers.hpp"
#include "lcp/solver.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>

using namespace suite::lcp;

namespace {

std::string dataDir() {
  std::string f = __FILE__; // .../tests/unit/lcp/test_fclib_reader.cpp
  return f.substr(0, f.rfind("/unit/")) + "/lcpbench/";
}

// W of fclib_gen.c: W = A A^T + I with A_ij = ((7i + 3j) mod 5 - 2) / 4.
double genW(int i, int j) {
  double s = i == j ? 1.0 : 0.0;
  for (int k = 0; k < 9; ++k) s += (((i * 7 + k * 3) % 5 - 2) * 0.25) * (((j * 7 + k * 3) % 5 - 2) * 0.25);
  return s;
}

// Solution of a small LCP by enumeration of the 2^n complementary index sets.
Vec enumerateLcp(const Mat& M, const Vec& q) {
  const int n = static_cast<int>(q.size());
  for (int mask = 0; mask < (1 << n); ++mask) {
    std::vector<int> F;
    for (int i = 0; i < n; ++i)
      if (mask >> i & 1) F.push_back(i);
    Vec z = Vec::Zero(n);
    if (!F.empty()) {
      const Vec zf = M(F, F).partialPivLu().solve(-q(F));
      for (size_t a = 0; a < F.size(); ++a) z[F[a]] = zf[a];
    }
    const Vec w = M * z + q;
    if (z.minCoeff() >= -1e-12 && w.minCoeff() >= -1e-12) return z;
  }
  return Vec();
}

TEST(FclibReader, DenseTripletsThreeContacts) {
  const Problem p = readFclibLocal(dataDir() + "fclib_local_3contacts.hdf5");
  ASSERT_EQ(p.size(), 3);
  EXPECT_TRUE(p.isStandard());
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(p.M(a, b), genW(3 * a, 3 * b), 1e-15);
  EXPECT_EQ(p.q[0], -1.0);
  EXPECT_EQ(p.q[1], 0.5);
  EXPECT_EQ(p.q[2], -2.0);
  const Vec ref = enumerateLcp(p.M, p.q);
  ASSERT_EQ(ref.size(), 3);
  for (const char* s : {"bpp", "lemke", "keller"}) {
    const Result r = solve(*makeSolver(s), p);
    ASSERT_TRUE(r.ok()) << s;
    EXPECT_LE((r.z - ref).lpNorm<Eigen::Infinity>(), 1e-12) << s;
  }
}

// Box-friction model: all 9 unknowns of W, normal bounds [0, inf), tangential bounds +-mu_c rhat_c with rhat
// the frictionless normal solution (here by enumeration); the box LCP is then solved and its tangential
// forces respect the box, which is the Coulomb bound at the estimated normal force.
TEST(FclibReader, BoxFrictionModel) {
  const std::string file = dataDir() + "fclib_local_3contacts.hdf5";
  const Problem normal = readFclibLocal(file);
  const Vec rhat = enumerateLcp(normal.M, normal.q);
  ASSERT_EQ(rhat.size(), 3);
  const Problem p = readFclibLocal(file, FclibModel::BoxFriction);
  ASSERT_EQ(p.size(), 9);
  EXPECT_EQ(p.kind, Kind::Box);
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) EXPECT_NEAR(p.M(i, j), genW(i, j), 1e-15);
  EXPECT_EQ(p.q[0], normal.q[0]);
  EXPECT_EQ(p.q[3], normal.q[1]);
  int nonzero_bounds = 0;
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(p.l[3 * c], 0.0);
    EXPECT_EQ(p.u[3 * c], kInf);
    for (int k = 1; k < 3; ++k) {
      EXPECT_EQ(p.l[3 * c + k], -p.u[3 * c + k]);
      EXPECT_GE(p.u[3 * c + k], 0.0);
      nonzero_bounds += p.u[3 * c + k] > 0.0;
    }
  }
  EXPECT_GT(nonzero_bounds, 0) << "some contact carries a normal force: its tangential box is not empty";
  // mu_c = u / rhat_c must be the same for both tangent directions of a contact.
  for (int c = 0; c < 3; ++c) EXPECT_EQ(p.u[3 * c + 1], p.u[3 * c + 2]);
  for (const char* s : {"bpp", "lemke"}) {
    const Result r = solve(*makeSolver(s), p);
    ASSERT_TRUE(r.ok()) << s;
    EXPECT_LE(r.residual, 1e-10) << s;
    for (int i = 0; i < 9; ++i)
      EXPECT_TRUE(r.z[i] >= p.l[i] - 1e-12 && r.z[i] <= p.u[i] + 1e-12) << s << " " << i;
  }
}

TEST(FclibReader, CscTwoDimensional) {
  const Problem p = readFclibLocal(dataDir() + "fclib_local_2d_csc.hdf5");
  ASSERT_EQ(p.size(), 3); // 6 rows, spacedim 2
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const int i = 2 * a, j = 2 * b;
      EXPECT_NEAR(p.M(a, b), (i + j) % 4 != 3 ? genW(i, j) : 0.0, 1e-15);
    }
  EXPECT_EQ(p.q[0], -1.0);
  EXPECT_EQ(p.q[1], -0.1);
  EXPECT_EQ(p.q[2], 0.0);
  const Result r = solve(*makeSolver("bpp"), p);
  ASSERT_TRUE(r.ok());
  EXPECT_LE((r.z - enumerateLcp(p.M, p.q)).lpNorm<Eigen::Infinity>(), 1e-12);
}

// A scratch file of this process in the system's temporary directory (not the working directory).
std::string scratch(const std::string& name) {
  const std::string file = "unit_fclib_" + std::to_string(getpid()) + "_" + name + ".hdf5";
  return (std::filesystem::temp_directory_path() / file).string();
}

// Writes an FCLib-like local problem with the given header; returns its path.
std::string writeLocal(const std::string& name, int spacedim, int m, int nz, int nzmax, bool with_q = true,
                       int row0 = 0) {
  const std::string path = scratch(name);
  suite::H5AppendFile f;
  f.create(path);
  auto scalar = [&](const std::string& n, int v) { f.createFixed<int>(n, 1, v); };
  scalar("/fclib_local/spacedim", spacedim);
  scalar("/fclib_local/W/m", m);
  scalar("/fclib_local/W/n", m);
  scalar("/fclib_local/W/nz", nz);
  scalar("/fclib_local/W/nzmax", nzmax);
  if (nz >= 0 && nz <= 16) {
    f.createFixed<int>("/fclib_local/W/p", nz, 0);
    f.createFixed<int>("/fclib_local/W/i", nz, row0);
    if (nzmax <= 16) f.createFixed<double>("/fclib_local/W/x", nzmax, 1.0);
  }
  if (with_q && m > 0 && m <= 16) {
    f.createFixed<double>("/fclib_local/vectors/q", m, -1.0);
    f.createFixed<double>("/fclib_local/vectors/mu", m / spacedim, 0.5);
  }
  return path;
}

void expectRefused(const std::string& path, const std::string& what) {
  try {
    readFclibLocal(path);
    FAIL() << path << " accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find(path), 0u) << "message names the file: " << e.what();
  }
}

TEST(FclibReader, MalformedAndHostileFilesRefused) {
  EXPECT_EQ(readFclibLocal(writeLocal("ok", 3, 3, 1, 1)).size(), 1); // the writer itself is fine
  expectRefused(writeLocal("dim4", 4, 4, 1, 1), "spacedim = 4");
  expectRefused(writeLocal("notmult", 3, 4, 1, 1), "not a multiple of spacedim");
  expectRefused(writeLocal("badnz", 3, 3, -3, 1), "malformed or too large");
  expectRefused(writeLocal("huge", 3, 3 * 1000000, 1, 1), "exceed the dense LCP limit");
  expectRefused(writeLocal("hugennz", 3, 3, 1, 2000000000), "malformed or too large");
  expectRefused(writeLocal("badindex", 3, 3, 1, 1, true, 7), "out of range");
  expectRefused(writeLocal("noq", 3, 3, 1, 1, false), "missing dataset /fclib_local/vectors/q");
  {
    suite::H5AppendFile f;
    f.create(scratch("global"));
    f.createFixed<int>("/fclib_global/spacedim", 1, 3);
  }
  expectRefused(scratch("global"), "only local problems");
  EXPECT_TRUE(isFclibFile(scratch("global")));
  expectRefused(scratch("nofile"), "cannot open file");
  for (const char* n : {"ok", "dim4", "notmult", "badnz", "huge", "hugennz", "badindex", "noq", "global"})
    std::filesystem::remove(scratch(n));
}

} // namespace
