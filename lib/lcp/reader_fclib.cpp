// Reader of FCLib local frictional-contact problems (FCLib 2011-2020, fclib.h / fclib.c of the FCLib project;
// Debian libfclib-dev) for the LCP benchmark; see readers.hpp for what is extracted.
//
// The file is read with the suite's own HDF5 (lib/io/h5_append.hpp), not with libfclib: Debian's libfclib
// links the serial libhdf5 while the suite links Open MPI's parallel libhdf5, and both in one executable
// clash (duplicate H5* symbols, two library states). The layout read here is the one fclib_write_local
// writes (H5LT datasets):
//   /fclib_local/spacedim        int (1)          2 or 3
//   /fclib_local/W/{m,n,nz,nzmax} int (1)         nz >= 0: triplets (nz entries), -1: CSC, -2: CSR
//   /fclib_local/W/p, /W/i        int             triplet: column, row (nz each); CSC: column starts (n+1),
//                                                 row indices (nzmax); CSR: row starts (m+1), columns (nzmax)
//   /fclib_local/W/x              double (nzmax)
//   /fclib_local/vectors/q        double (m),  /vectors/mu double (m / spacedim)
//   /fclib_local/V, /R, /vectors/s  (mixed problems: refused), /fclib_global (global problems: refused)
#include "io/h5_append.hpp"
#include "lcp/readers.hpp"
#include "lcp/solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace suite::lcp {
namespace {

int readScalarInt(H5AppendFile& f, const std::string& path, const std::string& name) {
  if (!f.exists(name)) throw std::runtime_error(path + ": missing dataset " + name + " (not an FCLib file?)");
  if (f.size(name) != 1) throw std::runtime_error(path + ": " + name + " must hold one integer");
  int v = 0;
  f.read(name, 0, &v, 1);
  return v;
}

template <typename T>
std::vector<T> readVector(H5AppendFile& f, const std::string& path, const std::string& name,
                          unsigned long long expected) {
  if (!f.exists(name)) throw std::runtime_error(path + ": missing dataset " + name);
  const unsigned long long s = f.size(name);
  if (s != expected)
    throw std::runtime_error(path + ": " + name + " has " + std::to_string(s) + " entries, expected " +
                             std::to_string(expected));
  std::vector<T> v(s);
  f.read(name, 0, v.data(), s);
  return v;
}

} // namespace

// Box friction (the "box" model of Lacoursiere 2003 and the contact app): the Coulomb cone |r_t| <= mu r_n is
// replaced by the box |r_t,k| <= mu_c * rhat_c per tangent direction, rhat_c the normal force of the
// frictionless problem (solved here with bpp). The result is a box LCP over all d * nc unknowns of W.
static Problem boxFrictionProblem(const Problem& normal, const Mat& W, const std::vector<double>& q,
                                  const std::vector<double>& mu, int d, const std::string& path) {
  const auto bpp = makeSolver("bpp");
  const Result rn = solve(*bpp, normal);
  if (!rn.ok())
    throw std::runtime_error(path +
                             ": the frictionless normal problem that estimates the normal forces was not "
                             "solved (" +
                             statusName(rn.status) + ")");
  const int m = static_cast<int>(W.rows()), nc = m / d;
  Vec qq(m), l(m), u(m);
  for (int i = 0; i < m; ++i) qq[i] = q[i];
  for (int c = 0; c < nc; ++c) {
    l[d * c] = 0.0, u[d * c] = kInf;
    const double bound = mu[c] * std::max(rn.z[c], 0.0);
    for (int k = 1; k < d; ++k) l[d * c + k] = -bound, u[d * c + k] = bound;
  }
  return makeBox(W, std::move(qq), std::move(l), std::move(u), path + " (box friction)");
}

Problem readFclibLocal(const std::string& path, FclibModel model) {
  H5AppendFile f;
  f.open(path, false); // throws "cannot open file" / "not a valid HDF5 file"
  if (f.exists("/fclib_global") && !f.exists("/fclib_local"))
    throw std::runtime_error(path +
                             ": FCLib global problem (M, H, G): only local problems (W, q, mu) are read");
  if (!f.exists("/fclib_local"))
    throw std::runtime_error(path + ": no /fclib_local group (not an FCLib file?)");
  if (f.exists("/fclib_local/V") || f.exists("/fclib_local/R"))
    throw std::runtime_error(path + ": mixed FCLib local problem (V, R, s) is not supported");
  const int d = readScalarInt(f, path, "/fclib_local/spacedim");
  if (d != 2 && d != 3)
    throw std::runtime_error(path + ": spacedim = " + std::to_string(d) + " (expected 2 or 3)");
  const std::string W = "/fclib_local/W/";
  const int m = readScalarInt(f, path, W + "m"), n = readScalarInt(f, path, W + "n");
  const int nz = readScalarInt(f, path, W + "nz"), nzmax = readScalarInt(f, path, W + "nzmax");
  if (m <= 0 || m != n)
    throw std::runtime_error(path + ": W is " + std::to_string(m) + " x " + std::to_string(n) +
                             " (expected square, non-empty)");
  if (m % d != 0)
    throw std::runtime_error(path + ": W has " + std::to_string(m) + " rows, not a multiple of spacedim " +
                             std::to_string(d));
  const int nc = m / d;              // contacts = size of the normal LCP (dense)
  constexpr int kMaxContacts = 8192; // 512 MiB dense M: refuse hostile sizes before allocating
  constexpr long long kMaxEntries = 1LL << 26;
  if (nc > kMaxContacts)
    throw std::runtime_error(path + ": " + std::to_string(nc) + " contacts exceed the dense LCP limit of " +
                             std::to_string(kMaxContacts));
  if (nzmax < 0 || nzmax > kMaxEntries || (nz >= 0 && nz > nzmax) || nz < -2)
    throw std::runtime_error(path + ": W has nz = " + std::to_string(nz) +
                             ", nzmax = " + std::to_string(nzmax) + " (malformed or too large)");
  // Normal model: dense W is not formed, only the normal rows / columns (index d*c) are kept. Box friction:
  // the whole W, dense (at most kMaxBoxRows rows).
  const bool box = model == FclibModel::BoxFriction;
  constexpr int kMaxBoxRows = 6144; // 288 MiB dense W
  if (box && m > kMaxBoxRows)
    throw std::runtime_error(path + ": " + std::to_string(m) +
                             " unknowns exceed the dense box-friction limit of " +
                             std::to_string(kMaxBoxRows) + " (use the normal model)");
  Mat Mn = Mat::Zero(nc, nc), Wfull = box ? Mat::Zero(m, m) : Mat();
  auto put = [&](long long i, long long j, double x) {
    if (i < 0 || i >= m || j < 0 || j >= m)
      throw std::runtime_error(path + ": W index (" + std::to_string(i) + ", " + std::to_string(j) +
                               ") out of range");
    if (!std::isfinite(x)) throw std::runtime_error(path + ": W has a non-finite entry");
    if (i % d == 0 && j % d == 0) Mn(i / d, j / d) += x; // triplets may repeat an entry: summed
    if (box) Wfull(i, j) += x;
  };
  const std::vector<double> x = readVector<double>(f, path, W + "x", static_cast<unsigned long long>(nzmax));
  if (nz >= 0) { // triplets: p = column, i = row (fclib / CSparse convention)
    const auto p = readVector<int>(f, path, W + "p", nz), ii = readVector<int>(f, path, W + "i", nz);
    for (int k = 0; k < nz; ++k) put(ii[k], p[k], x[k]);
  } else { // compressed: p = starts (n+1 for CSC, m+1 for CSR), i = indices (nzmax)
    const auto p = readVector<int>(f, path, W + "p", static_cast<unsigned long long>(m) + 1);
    const auto ii = readVector<int>(f, path, W + "i", nzmax);
    if (p[0] != 0 || p[m] > nzmax)
      throw std::runtime_error(path + ": W pointer array p is malformed (p[0] = " + std::to_string(p[0]) +
                               ", p[last] = " + std::to_string(p[m]) + ", nzmax " + std::to_string(nzmax) +
                               ")");
    for (int a = 0; a < m; ++a) {
      if (p[a + 1] < p[a]) throw std::runtime_error(path + ": W pointer array p is not monotone");
      for (int k = p[a]; k < p[a + 1]; ++k) {
        if (nz == -1)
          put(ii[k], a, x[k]); // CSC: column a
        else
          put(a, ii[k], x[k]); // CSR: row a
      }
    }
  }
  const auto q = readVector<double>(f, path, "/fclib_local/vectors/q", m);
  const auto mu = readVector<double>(f, path, "/fclib_local/vectors/mu", nc);
  for (double v : mu)
    if (!(v >= 0.0) || !std::isfinite(v))
      throw std::runtime_error(path + ": friction coefficient mu < 0 or not finite");
  Vec qn(nc);
  for (int c = 0; c < nc; ++c) qn[c] = q[static_cast<size_t>(c) * d];
  Problem prob = makeLcp(std::move(Mn), std::move(qn), path);
  if (!box) return prob;
  return boxFrictionProblem(prob, Wfull, q, mu, d, path);
}

bool isFclibFile(const std::string& path) {
  if (!H5AppendFile::isHdf5(path)) return false;
  H5AppendFile f;
  try {
    f.open(path, false);
    return f.exists("/fclib_local") || f.exists("/fclib_global");
  } catch (const std::exception&) {
    return false;
  }
}

} // namespace suite::lcp
