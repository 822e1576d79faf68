// HDF5 writer/reader round trips, atomic commit, XDMF text, checkpoint header validation.
#include "../test_helpers.hpp"
#include "io/checkpoint.hpp"
#include "io/h5_input.hpp"
#include "io/h5_output.hpp"
#include "io/xdmf.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <unistd.h>

namespace {

using suite_test::fileExists;
using suite_test::quietly;

TEST(H5Output, RoundTripAttributesAndDatasets) {
  const std::string path = "unit_roundtrip.h5";
  {
    suite::H5Output out;
    ASSERT_EQ(out.open(PETSC_COMM_WORLD, path), 0);
    EXPECT_TRUE(fileExists(path + ".tmp"));
    ASSERT_EQ(out.writeAttribute("/", "name", "sod"), 0);
    ASSERT_EQ(out.writeAttribute("/", "gamma", 1.4), 0);
    ASSERT_EQ(out.writeAttribute("/group/sub", "count", 7LL), 0);
    ASSERT_EQ(out.writeAttribute("/", "vec", std::vector<double>{1.0, 2.5}), 0);
    std::vector<double> a{1, 2, 3, 4, 5, 6};
    std::vector<long long> b{-3, 9};
    ASSERT_EQ(out.writeDistributed("/final/a", a.data(), {2, 3}, {0, 0}, {2, 3}, "kg/m^3"), 0);
    ASSERT_EQ(out.writeReplicated("/final/b", b.data(), {2}, ""), 0);
    ASSERT_EQ(out.commit(nullptr), 0);
  }
  EXPECT_FALSE(fileExists(path + ".tmp"));
  suite::H5Input in;
  ASSERT_EQ(in.open(PETSC_COMM_WORLD, path), 0);
  std::string s, units;
  double g = 0;
  long long c = 0;
  std::vector<double> v, a;
  std::vector<long long> b;
  suite::Dims dims;
  ASSERT_EQ(in.readAttribute("/", "name", &s), 0);
  ASSERT_EQ(in.readAttribute("/", "gamma", &g), 0);
  ASSERT_EQ(in.readAttribute("/group/sub", "count", &c), 0);
  ASSERT_EQ(in.readAttribute("/", "vec", &v), 0);
  ASSERT_EQ(in.readAttribute("/final/a", "units", &units), 0);
  ASSERT_EQ(in.readAll("/final/a", &a, &dims), 0);
  EXPECT_EQ(s, "sod");
  EXPECT_EQ(g, 1.4);
  EXPECT_EQ(c, 7);
  EXPECT_EQ(v, (std::vector<double>{1.0, 2.5}));
  EXPECT_EQ(units, "kg/m^3");
  EXPECT_EQ(dims, (suite::Dims{2, 3}));
  EXPECT_EQ(a, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  ASSERT_EQ(in.readAll("/final/b", &b, &dims), 0);
  EXPECT_EQ(b, (std::vector<long long>{-3, 9}));
  double block[2];
  ASSERT_EQ(in.readBlock("/final/a", {1, 1}, {1, 2}, block), 0);
  EXPECT_EQ(block[0], 5.0);
  EXPECT_EQ(block[1], 6.0);
  EXPECT_NE(quietly([&] { return in.readAttribute("/", "missing", &s); }), 0);
  EXPECT_NE(quietly([&] { return in.readAll("/nope", &a, &dims); }), 0);
  EXPECT_NE(quietly([&] { return in.readBlock("/final/a", {0, 2}, {2, 2}, block); }), 0);
}

TEST(H5Output, UncommittedFileNeverAppearsUnderFinalName) {
  const std::string path = "unit_uncommitted.h5";
  std::remove(path.c_str());
  {
    suite::H5Output out;
    ASSERT_EQ(out.open(PETSC_COMM_WORLD, path), 0);
    double x = 1;
    ASSERT_EQ(out.writeReplicated("/x", &x, {1}, ""), 0);
  } // destroyed without commit (an error path)
  EXPECT_FALSE(fileExists(path));
  EXPECT_FALSE(fileExists(path + ".tmp"));
}

TEST(H5Output, UnwritableDirectoryIsRefused) {
  suite::H5Output out;
  EXPECT_NE(quietly([&] { return out.open(PETSC_COMM_WORLD, "/nonexistent_dir_xyz/a.h5"); }), 0);
  EXPECT_NE(quietly([&] { return suite::checkOutputWritable(PETSC_COMM_WORLD, "/", "output"); }), 0);
}

TEST(H5Input, NonHdf5FileIsRefused) {
  std::ofstream("unit_not_hdf5.h5") << "plain text";
  suite::H5Input in;
  EXPECT_NE(quietly([&] { return in.open(PETSC_COMM_WORLD, "unit_not_hdf5.h5"); }), 0);
  EXPECT_NE(quietly([&] { return in.open(PETSC_COMM_WORLD, "unit_missing_file.h5"); }), 0);
}

TEST(Xdmf, RectSeriesNamesDatasetsAndDims) {
  suite::XdmfRectGrid grid{{5, 9}, {0.0, 0.0}, {0.25, 0.125}};
  ASSERT_EQ(suite::writeXdmfRectSeries(PETSC_COMM_WORLD, "unit.xmf", "dir/unit.h5", grid,
                                       {{0.5, {{"rho", "/snap/rho", true}}}}),
            0);
  std::stringstream ss;
  ss << std::ifstream("unit.xmf").rdbuf();
  const std::string x = ss.str();
  EXPECT_NE(x.find("2DCoRectMesh\" Dimensions=\"5 9\""), std::string::npos);
  EXPECT_NE(x.find("Dimensions=\"4 8\">unit.h5:/snap/rho"), std::string::npos);
  EXPECT_NE(x.find("<Time Value=\"0.5\"/>"), std::string::npos);
}

TEST(Checkpoint, RoundTripAndHeaderValidation) {
  std::vector<double> u{1.5, -2.0, 3.25, 4.0}, r(4, 0.0);
  suite::CheckpointHeader h{"euler", "enopade6", 12, 0.125, 1e-3, {4}};
  ASSERT_EQ(suite::writeCheckpoint(PETSC_COMM_WORLD, "unit_ckpt.h5", h, {{"u", {4}, {0}, {4}, u.data()}}), 0);
  suite::CheckpointHeader found;
  ASSERT_EQ(
      suite::readCheckpoint(PETSC_COMM_WORLD, "unit_ckpt.h5", h, &found, {{"u", {4}, {0}, {4}, r.data()}}),
      0);
  EXPECT_EQ(r, u);
  EXPECT_EQ(found.step, 12);
  EXPECT_EQ(found.time, 0.125);
  EXPECT_EQ(found.scheme, "enopade6");
  auto bad = h;
  bad.app = "femdyn";
  EXPECT_NE(quietly([&] {
              return suite::readCheckpoint(PETSC_COMM_WORLD, "unit_ckpt.h5", bad, &found,
                                           {{"u", {4}, {0}, {4}, r.data()}});
            }),
            0);
  bad = h;
  bad.grid = {8};
  EXPECT_NE(quietly([&] {
              return suite::readCheckpoint(PETSC_COMM_WORLD, "unit_ckpt.h5", bad, &found,
                                           {{"u", {4}, {0}, {4}, r.data()}});
            }),
            0);
  bad = h;
  bad.scheme = "weno5";
  EXPECT_NE(quietly([&] {
              return suite::readCheckpoint(PETSC_COMM_WORLD, "unit_ckpt.h5", bad, &found,
                                           {{"u", {4}, {0}, {4}, r.data()}});
            }),
            0);
}

} // namespace
