// Reader of the Siconos numerics text format for LCP, relay (box LCP) and MLCP problems; see readers.hpp.
#include "lcp/readers.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace suite::lcp {
namespace {

class Numbers {
public:
  Numbers(const std::string& text, std::string name) : name_(std::move(name)) {
    std::istringstream is(text);
    std::string tok;
    while (is >> tok) {
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end != '\0') break; // first non-number: the comment starts
      v_.push_back(v);
    }
  }
  double next(const char* what) {
    if (pos_ >= v_.size())
      throw std::runtime_error(name_ + ": truncated file (expected " + what + " at number " +
                               std::to_string(pos_ + 1) + ")");
    return v_[pos_++];
  }
  int nextInt(const char* what, int lo, int hi) {
    const double v = next(what);
    if (v != std::floor(v) || v < lo || v > hi) {
      std::ostringstream os;
      os << name_ << ": malformed header: " << what << " = " << v << " (expected an integer in [" << lo
         << ", " << hi << "])";
      throw std::runtime_error(os.str());
    }
    return static_cast<int>(v);
  }
  size_t remaining() const { return v_.size() - pos_; }
  // Throws "truncated" before a caller allocates room for `count` numbers the text does not hold: memory stays
  // bounded by the input size whatever the header claims.
  void need(unsigned long long count, const char* what) const {
    if (count > remaining())
      throw std::runtime_error(name_ + ": truncated file (header announces " + std::to_string(count) + " " +
                               what + ", only " + std::to_string(remaining()) + " numbers follow)");
  }
  const std::string& name() const { return name_; }

private:
  std::vector<double> v_;
  size_t pos_ = 0;
  std::string name_;
};

constexpr int kMaxN = 1 << 20;

// NumericsMatrix in dense storage: type, rows, cols, "rows cols", values column-major.
Mat readNumericsMatrix(Numbers& in, int n_expected) {
  const int type = in.nextInt("matrix storage type", 0, 2);
  if (type != 0)
    throw std::runtime_error(in.name() + ": only dense storage (type 0) is supported, got " +
                             std::to_string(type));
  const int r = in.nextInt("number of rows", 0, kMaxN), c = in.nextInt("number of columns", 0, kMaxN);
  const int r2 = in.nextInt("number of rows", 0, kMaxN), c2 = in.nextInt("number of columns", 0, kMaxN);
  if (r != r2 || c != c2) throw std::runtime_error(in.name() + ": inconsistent matrix dimensions");
  if (r != c)
    throw std::runtime_error(in.name() + ": M is not square (" + std::to_string(r) + " x " +
                             std::to_string(c) + ")");
  if (n_expected >= 0 && r != n_expected)
    throw std::runtime_error(in.name() + ": M is " + std::to_string(r) + " x " + std::to_string(c) +
                             " but the problem size is " + std::to_string(n_expected));
  in.need(static_cast<unsigned long long>(r) * static_cast<unsigned long long>(c), "matrix entries");
  Mat M(r, c);
  for (int j = 0; j < c; ++j)
    for (int i = 0; i < r; ++i) M(i, j) = in.next("a matrix entry");
  return M;
}

Vec readVec(Numbers& in, int n, const char* what) {
  in.need(static_cast<unsigned long long>(n), "vector entries");
  Vec v(n);
  for (int i = 0; i < n; ++i) v[i] = in.next(what);
  return v;
}

Mat readRowWise(Numbers& in, int r, int c, const char* what) {
  in.need(static_cast<unsigned long long>(r) * static_cast<unsigned long long>(c), "matrix entries");
  Mat A(r, c);
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < c; ++j) A(i, j) = in.next(what);
  return A;
}

std::string baseName(const std::string& path) {
  const auto s = path.find_last_of('/');
  return s == std::string::npos ? path : path.substr(s + 1);
}

} // namespace

Problem parseSiconos(const std::string& text, const std::string& name) {
  Numbers in(text, name);
  const std::string base = baseName(name);
  Problem p;
  if (base.find("mlcp") != std::string::npos) {
    const int st1 = in.nextInt("isStorageType1", 0, 1), st2 = in.nextInt("isStorageType2", 0, 1);
    const int n = in.nextInt("n (equalities)", 0, kMaxN), m = in.nextInt("m (complementarities)", 0, kMaxN);
    if (!st1 && !st2) throw std::runtime_error(name + ": MLCP with neither storage type");
    const int N = n + m;
    in.need(static_cast<unsigned long long>(N), "variables"); // every variable has at least its q entry
    std::vector<char> comp(N, 1);
    Mat M;
    Vec q;
    if (st1) {
      std::vector<int> starts;
      while (true) {
        starts.push_back(in.nextInt("a block row start", 0, N));
        if (starts.back() == N) break;
        if (starts.size() > static_cast<size_t>(N) + 1)
          throw std::runtime_error(name + ": malformed block rows");
      }
      for (size_t b = 0; b + 1 < starts.size(); ++b) {
        const int c = in.nextInt("a block complementarity flag", 0, 1);
        for (int i = starts[b]; i < starts[b + 1] && i < N; ++i) comp[i] = static_cast<char>(c);
      }
      M = readNumericsMatrix(in, N);
      q = readVec(in, N, "an entry of q");
    }
    if (st2) {
      const Mat A = readRowWise(in, n, n, "an entry of A"), B = readRowWise(in, m, m, "an entry of B");
      const Mat C = readRowWise(in, n, m, "an entry of C"), D = readRowWise(in, m, n, "an entry of D");
      const Vec a = readVec(in, n, "an entry of a"), b = readVec(in, m, "an entry of b");
      if (!st1) {
        M.resize(N, N);
        M << A, C, D, B;
        q.resize(N);
        q << a, b;
        for (int i = 0; i < n; ++i) comp[i] = 0;
      }
    }
    p = makeLcp(M, q, base);
    p.kind = Kind::MLCP;
    for (int i = 0; i < N; ++i)
      if (!comp[i]) {
        p.l[i] = -kInf;
        ++p.n_eq;
      }
    return p;
  }
  const int n = in.nextInt("problem size n", 1, kMaxN);
  Mat M = readNumericsMatrix(in, n);
  Vec q = readVec(in, n, "an entry of q");
  const bool relay = base.rfind("relay", 0) == 0;
  if (relay || (in.remaining() == static_cast<size_t>(2 * n) && base.rfind("lcp", 0) != 0)) {
    Vec l = readVec(in, n, "an entry of the lower bound"), u = readVec(in, n, "an entry of the upper bound");
    return makeBox(std::move(M), std::move(q), std::move(l), std::move(u), base);
  }
  return makeLcp(std::move(M), std::move(q), base);
}

Problem readSiconos(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot open file");
  std::stringstream ss;
  ss << f.rdbuf();
  return parseSiconos(ss.str(), path);
}

} // namespace suite::lcp
