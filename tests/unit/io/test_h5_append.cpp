// H5AppendFile: preallocated and extendable 1-D datasets, scattered writes, attributes, reopen, errors.
#include "io/h5_append.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

TEST(H5AppendFile, FixedDatasetFillScatteredWriteAndReopen) {
  const std::string path = "unit_h5_append_fixed.h5";
  {
    suite::H5AppendFile f;
    f.create(path);
    f.createFixed<int>("/results/a/status", 10, -1);
    f.createFixed<double>("/results/a/time", 10, 0.0, "s");
    f.createFixed<unsigned char>("/batch/done", 10, 0);
    EXPECT_EQ(f.size("/results/a/status"), 10u);
    f.select({1, 2, 3, 7});
    const std::vector<int> st{5, 6, 7, 8};
    const std::vector<double> t{0.5, 0.25, 0.125, 2.0};
    f.writeSelected("/results/a/status", st.data());
    f.writeSelected("/results/a/time", t.data());
    const std::vector<unsigned char> one(4, 1);
    f.writeSelected("/batch/done", one.data());
    f.setAttribute("/batch", "family", std::string("random_box"));
    f.setAttribute("/batch", "count", 10LL);
    f.setAttribute("/batch", "cond", 1e4);
    f.setAttribute("/batch", "walls", std::vector<double>{1.5, 2.5});
    f.flush();
    EXPECT_THROW(f.writeAt("/results/a/status", 8, st.data(), 4), std::runtime_error); // past the end
  }
  suite::H5AppendFile g;
  g.open(path, false);
  std::vector<int> st(10);
  g.read("/results/a/status", 0, st.data(), 10);
  EXPECT_EQ(st, (std::vector<int>{-1, 5, 6, 7, -1, -1, -1, 8, -1, -1})); // fill value where unwritten
  std::vector<unsigned char> done(10);
  g.read("/batch/done", 0, done.data(), 10);
  EXPECT_EQ(done, (std::vector<unsigned char>{0, 1, 1, 1, 0, 0, 0, 1, 0, 0}));
  std::vector<double> t(2);
  g.read("/results/a/time", 2, t.data(), 2);
  EXPECT_EQ(t[0], 0.25);
  EXPECT_EQ(t[1], 0.125);
  std::string fam;
  long long count = 0;
  double cond = 0.0;
  std::vector<double> walls;
  EXPECT_TRUE(g.getAttribute("/batch", "family", &fam));
  EXPECT_TRUE(g.getAttribute("/batch", "count", &count));
  EXPECT_TRUE(g.getAttribute("/batch", "cond", &cond));
  EXPECT_TRUE(g.getAttribute("/batch", "walls", &walls));
  EXPECT_EQ(fam, "random_box");
  EXPECT_EQ(count, 10);
  EXPECT_EQ(cond, 1e4);
  EXPECT_EQ(walls, (std::vector<double>{1.5, 2.5}));
  EXPECT_FALSE(g.getAttribute("/batch", "absent", &fam));
  EXPECT_FALSE(g.getAttribute("/nogroup", "family", &fam));
  EXPECT_THROW(g.getAttribute("/batch", "family", &count), std::runtime_error); // type mismatch
  EXPECT_THROW(g.read("/results/a/status", 8, st.data(), 3), std::runtime_error);
  EXPECT_THROW(g.size("/results/none"), std::runtime_error);
}

TEST(H5AppendFile, ExtendableGrowsByAppendAndWriteAt) {
  const std::string path = "unit_h5_append_ext.h5";
  {
    suite::H5AppendFile f;
    f.create(path);
    f.createExtendable<long long>("/log/k", 4, -7LL);
    EXPECT_EQ(f.size("/log/k"), 0u);
    const std::vector<long long> a{1, 2, 3, 4, 5, 6};
    f.append("/log/k", a.data(), 3);
    f.append("/log/k", a.data() + 3, 3);
    EXPECT_EQ(f.size("/log/k"), 6u);
    f.writeAt("/log/k", 9, a.data(), 1); // grows to 10; 6..8 take the fill value
    EXPECT_EQ(f.size("/log/k"), 10u);
  }
  suite::H5AppendFile g;
  g.open(path, false);
  std::vector<long long> k(10);
  g.read("/log/k", 0, k.data(), 10);
  EXPECT_EQ(k, (std::vector<long long>{1, 2, 3, 4, 5, 6, -7, -7, -7, 1}));
}

TEST(H5AppendFile, ErrorsAreClear) {
  suite::H5AppendFile f;
  try {
    f.open("unit_h5_append_missing.h5", false);
    FAIL() << "missing file accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open file"), std::string::npos) << e.what();
  }
  { std::ofstream("unit_h5_append_text.h5") << "not hdf5\n"; }
  EXPECT_FALSE(suite::H5AppendFile::isHdf5("unit_h5_append_text.h5"));
  try {
    f.open("unit_h5_append_text.h5", false);
    FAIL() << "text file accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not a valid HDF5 file"), std::string::npos) << e.what();
  }
  EXPECT_THROW(f.create("/no/such/dir/x.h5"), std::runtime_error);
  EXPECT_THROW(f.select({3, 2}), std::runtime_error);
}

} // namespace
