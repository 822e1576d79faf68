// Classification of an LCP for the solver portfolio (see problem_class.hpp).
#include "lcp/problem_class.hpp"

#include "lcp/solver.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace suite::lcp {

namespace {

// The parts of a class name; problemClassNames() lists every combination in this order.
constexpr std::string_view kStructures[] = {"lcp", "box", "mlcp"};
constexpr std::string_view kMatrices[] = {"dd", "spd", "sym", "pd", "gen", "tril", "triu"};
constexpr std::string_view kSizes[] = {"small", "medium", "large"};
constexpr int kNumMatrices = sizeof kMatrices / sizeof kMatrices[0];
constexpr int kNumSizes = sizeof kSizes / sizeof kSizes[0];

// standard: p.isStandard() (every l_i = 0, u_i = inf), counted with the bounds in classify().
int structureOf(const Problem& p, bool standard) {
  if (p.n_eq > 0) return 2;
  return standard ? 0 : 1;
}

int sizeOf(int n) {
  return n <= 32 ? 0 : n <= 256 ? 1 : 2;
}

// Sets the class (names and index) from the parts' indices.
void setClass(int structure, int matrix, int size, ProblemFeatures* f) {
  f->structure = kStructures[structure];
  f->matrix = kMatrices[matrix];
  f->size = kSizes[size];
  f->class_index = (structure * kNumMatrices + matrix) * kNumSizes + size;
}

// n doubles, on the stack up to kStack (a malloc and free cost as much as classifying n = 10), else on the heap.
class Scratch {
public:
  explicit Scratch(Eigen::Index n) : heap_(n > kStack ? n : 0), n_(n) {}
  Eigen::Map<Vec> vec() { return Eigen::Map<Vec>(n_ > kStack ? heap_.data() : stack_, n_); }

private:
  static constexpr Eigen::Index kStack = 64;
  double stack_[kStack];
  Vec heap_;
  Eigen::Index n_;
};

// Column by column (contiguous, vectorised): positive diagonal, strict row diagonal dominance.
void scanColumns(const Mat& M, ProblemFeatures* f) {
  const Eigen::Index n = M.rows();
  Scratch so(n), sd(n);
  Eigen::Map<Vec> off = so.vec(), d = sd.vec(); // off: row sums of |M_ij|, j != i
  off.setZero();
  for (Eigen::Index j = 0; j < n; ++j) off += M.col(j).cwiseAbs(); // elementwise: vectorised
  d = M.diagonal();
  off -= d.cwiseAbs();
  f->diag_positive = n > 0 && d.minCoeff() > 0;
  f->diag_dominant = f->diag_positive && (off.array() < d.array()).all();
}

// Symmetric M in one pass over the columns (contiguous; a column's sums are its row's): positive
// diagonal, strict diagonal dominance, and (with_minors) every 2 x 2 principal minor > 0 (necessary for
// definiteness; else minors_ok is left false).
void scanSymmetric(const Mat& M, bool with_minors, ProblemFeatures* f) {
  const Eigen::Index n = M.rows();
  Scratch sd(n);
  Eigen::Map<Vec> d = sd.vec();
  d = M.diagonal();
  const bool pos = n > 0 && d.minCoeff() > 0;
  bool dd = pos, minors = pos && with_minors;
  for (Eigen::Index j = 0; j < n && (dd || minors); ++j) { // Eigen's reductions: vectorised
    const auto c = M.col(j).array();
    const Eigen::Index k = n - 1 - j;
    dd = dd && c.abs().sum() - std::abs(d(j)) < d(j);
    minors = minors && (k == 0 || (d(j) * d.tail(k).array() - c.tail(k).square()).minCoeff() > 0.0);
  }
  f->diag_positive = pos;
  f->diag_dominant = dd;
  f->minors_ok = minors;
}

// Every 2 x 2 principal minor of (M + M^T) / 2 > 0 (the diagonal is positive), M nonsymmetric: the transposed
// entries are read in 16 x 16 tiles.
bool minorsPositive(const Mat& M) {
  const Eigen::Index n = M.rows();
  const auto d = M.diagonal();
  constexpr Eigen::Index T = 16;
  for (Eigen::Index jb = 0; jb < n; jb += T)
    for (Eigen::Index ib = jb; ib < n; ib += T)
      for (Eigen::Index j = jb; j < std::min(n, jb + T); ++j)
        for (Eigen::Index i = std::max(ib, j + 1); i < std::min(n, ib + T); ++i) {
          const double s = 0.5 * (M(i, j) + M(j, i));
          if (!(d(i) * d(j) > s * s)) return false;
        }
  return true;
}

// 1: M lower triangular, 2: upper (every entry on that side of the diagonal exactly 0; a diagonal M is
// dd or symmetric, never asked), 0: neither. Stops at the first nonzero entry on each side (a dense matrix:
// after a few entries).
int triangularSide(const Mat& M) {
  const Eigen::Index n = M.rows();
  bool lower = true, upper = true;
  for (Eigen::Index j = 0; j < n && (lower || upper); ++j) {
    lower = lower && (M.col(j).head(j).array() == 0.0).all();
    upper = upper && (M.col(j).tail(n - 1 - j).array() == 0.0).all();
  }
  return lower ? 1 : upper ? 2 : 0;
}

constexpr int kTiny = 16; // classify()'s scalar path up to this size (scanTinyInto)

// Every pair i > j satisfies ok(M(i, j), M(j, i), i, j); stops at the first that does not.
template <class Test> bool everyPair(const Mat& M, Test ok) {
  const int n = static_cast<int>(M.rows());
  for (int j = 0; j < n; ++j)
    for (int i = j + 1; i < n; ++i)
      if (!ok(M(i, j), M(j, i), i, j)) return false;
  return true;
}

// M's strict upper triangle is zero (read column by column: contiguous, unlike everyPair's M(j, i)). A
// column's entries are tested together, without a branch per entry (vectorised): the test read Murty's
// triangle entry by entry for ~20 of classify()'s 61 ns at n = 12.
bool upperZero(const Mat& M) {
  const int n = static_cast<int>(M.rows());
  for (int i = 1; i < n; ++i) {
    const double* c = M.col(i).data();
    std::uint64_t bits = 0; // the OR of the entries' bits without the sign (-0.0 counts as zero)
    for (int j = 0; j < i; ++j) {
      std::uint64_t b;
      std::memcpy(&b, c + j, sizeof b);
      bits |= b << 1;
    }
    if (bits != 0) return false;
  }
  return true;
}

// classify()'s matrix tests for n <= kTiny by scalar loops, each stopping at its first failure (Murty's
// example at n = 8: the first pair ends the symmetry, dominance and minors tests; only the triangle is read
// through). For such sizes Eigen's vectorised reductions, the scratch vectors and whole passes cost more than
// the tests: that example (cottle_dantzig ~0.24 us) spent ~60 ns in them. Returns the triangle (1 lower,
// 2 upper, 0 none or not asked: symmetric, dominant or a diagonal entry <= 0); the flags are the general
// path's.
int scanTinyInto(const Problem& p, bool with_minors, ProblemFeatures* f) {
  const Mat& M = p.M;
  const int n = static_cast<int>(M.rows());
  bool positive = n > 0;
  for (int i = 0; i < n && positive; ++i) positive = M(i, i) > 0;
  f->symmetric =
      p.symmetric >= 0 ? p.symmetric == 1 : everyPair(M, [](double a, double b, int, int) { return a == b; });
  bool dominant = positive;
  for (int i = 0; i < n && dominant; ++i) {
    double off = 0;
    for (int k = 0; k < n; ++k) off += k == i ? 0.0 : std::abs(M(i, k));
    dominant = off < M(i, i);
  }
  f->diag_positive = positive;
  f->diag_dominant = dominant;
  f->minors_ok = with_minors && positive && (f->symmetric || !dominant) &&
                 everyPair(M, [&M](double a, double b, int i, int j) {
                   const double h = 0.5 * (a + b);
                   return M(i, i) * M(j, j) > h * h;
                 });
  if (f->symmetric || dominant || !positive) return 0;
  if (upperZero(M)) return 1;
  return everyPair(M, [](double a, double, int, int) { return a == 0.0; }) ? 2 : 0;
}

// Every l_i = 0 and u_i = +inf (Problem::isStandard()), read as bits without a branch per entry (vectorised:
// on Murty's example at n = 12 the entry-by-entry test and count took ~12 of classify()'s 61 ns).
bool standardBounds(const Problem& p) {
  constexpr std::uint64_t kInfBits = 0x7ff0000000000000ULL;
  std::uint64_t diff = 0;
  for (int i = 0; i < p.size(); ++i) {
    std::uint64_t l, u;
    std::memcpy(&l, &p.l[i], sizeof l);
    std::memcpy(&u, &p.u[i], sizeof u);
    diff |= (l << 1) | (u ^ kInfBits); // l: -0.0 is 0 as well (isStandard())
  }
  return diff == 0;
}

// f's counts of finite bounds (standard: standardBounds(p)); bounds are never NaN (validate()).
void countFiniteBounds(const Problem& p, bool standard, ProblemFeatures* f) {
  f->finite_lower = standard ? f->n : 0;
  f->finite_upper = 0;
  if (standard) return;
  for (int i = 0; i < f->n; ++i) {
    f->finite_lower += std::isfinite(p.l[i]);
    f->finite_upper += std::isfinite(p.u[i]);
  }
}

bool choleskySucceeds(const Mat& S) {
  Eigen::LLT<Mat> llt(S);
  return llt.info() == Eigen::Success && llt.matrixLLT().diagonal().allFinite() &&
         llt.matrixLLT().diagonal().minCoeff() > 0;
}

// Positive definite (symmetric part) as far as the tests of problem_class.hpp go (f->minors_ok set).
bool definite(const Problem& p, bool cholesky, ProblemFeatures* f) {
  if (!f->minors_ok || !cholesky) return f->minors_ok;
  f->cholesky_tried = true;
  f->cholesky_ok = f->symmetric ? choleskySucceeds(p.M) : choleskySucceeds(0.5 * (p.M + p.M.transpose()));
  return f->cholesky_ok;
}

} // namespace

ProblemFeatures classify(const Problem& p, bool thorough, bool defer_minors) {
  defer_minors = defer_minors && !thorough;
  ProblemFeatures f;
  f.n = p.size();
  f.kind = p.kind;
  const bool standard = standardBounds(p);
  countFiniteBounds(p, standard, &f);
  if (thorough)
    f.density = static_cast<double>((p.M.array() != 0.0).count()) / std::max(1.0, double(f.n) * f.n);
  int side = 0;
  if (f.n <= kTiny) {
    side = scanTinyInto(p, !defer_minors, &f);
  } else {
    f.symmetric = isSymmetric(p);
    if (f.symmetric) {
      scanSymmetric(p.M, !defer_minors, &f);
    } else {
      scanColumns(p.M, &f);
      if (!defer_minors) f.minors_ok = !f.diag_dominant && f.diag_positive && minorsPositive(p.M);
    }
    side = !f.symmetric && !f.diag_dominant && f.diag_positive ? triangularSide(p.M) : 0;
  }
  f.triangular = side > 0;
  int matrix = f.diag_dominant ? 0 : 4 + side; // dd, tril, triu
  if (!f.diag_dominant && !f.triangular) {
    f.minors_deferred = defer_minors && f.diag_positive; // else decided: not definite
    const bool def = f.minors_deferred || definite(p, thorough, &f);
    matrix = f.symmetric ? (def ? 1 : 2) : (def ? 3 : 4);
  }
  setClass(structureOf(p, standard), matrix, sizeOf(f.n), &f);
  return f;
}

const std::vector<std::string>& problemClassNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (std::string_view s : kStructures)
      for (std::string_view m : kMatrices)
        for (std::string_view z : kSizes)
          v.push_back(std::string(s) + "-" + std::string(m) + "-" + std::string(z));
    return v;
  }();
  return names;
}

int problemClassIndex(const std::string& name) {
  const auto& v = problemClassNames();
  const auto it = std::find(v.begin(), v.end(), name);
  return it == v.end() ? -1 : static_cast<int>(it - v.begin());
}

} // namespace suite::lcp
