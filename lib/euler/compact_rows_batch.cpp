// Batched compact rows (see compact_rows_batch.hpp): loops over the stencils on the generic arithmetic of
// compact_row_kernels.hpp, vectorised by GCC (CRWENO5-Z) or four stencils at a time in Lanes (ENO-Pade).
#include "euler/compact_rows_batch.hpp"

#include "euler/compact_row_kernels.hpp"
#include "euler/crweno5.hpp"
#include "euler/crweno_cu6.hpp"
#include "core/kernel_clones.hpp"

#include <cstring>

namespace suite::euler {

namespace {
using kernels::Lanes;
using kernels::RowOf;

struct Crweno5 {
  template <class T> static SUITE_ROW_INLINE RowOf<T> row(const T* v) { return kernels::crweno5Row(v); }
};
struct Crweno5Mapped {
  template <class T> static SUITE_ROW_INLINE RowOf<T> row(const T* v) { return kernels::crweno5MappedRow(v); }
};
struct EnoPadeBlend {
  template <class T> static SUITE_ROW_INLINE RowOf<T> row(const T* v) { return kernels::enoPadeBlendRow(v); }
};

// The rows of K on stencils [i0, n) of v into out (layouts as RowsFunction), one stencil per iteration: GCC
// vectorises this loop itself for the CRWENO5-Z row (measured: Sod N = 2048 3.5 s against 4.05 s with Lanes),
// not for the ENO-Pade row (its select on theta = 1 becomes a branch around trapping arithmetic).
template <class K>
SUITE_ROW_INLINE void scalarRowsLoop(int i0, int n, const double* __restrict v, double* __restrict out) {
  for (int i = i0; i < n; ++i) {
    double s[6];
    for (int m = 0; m < 6; ++m) s[m] = v[(size_t)m * n + i];
    const RowOf<double> r = K::row(s);
    out[i] = r.a;
    out[n + i] = r.b;
    out[2 * n + i] = r.c;
    out[3 * n + i] = r.r;
  }
}

// The same four stencils at a time in Lanes.
template <class K>
SUITE_ROW_INLINE void lanesRowsLoop(int n, const double* __restrict v, double* __restrict out) {
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    Lanes s[6];
    for (int m = 0; m < 6; ++m) std::memcpy(&s[m], v + (size_t)m * n + i, sizeof(Lanes));
    const RowOf<Lanes> r = K::row(s);
    std::memcpy(out + i, &r.a, sizeof(Lanes));
    std::memcpy(out + (size_t)n + i, &r.b, sizeof(Lanes));
    std::memcpy(out + 2 * (size_t)n + i, &r.c, sizeof(Lanes));
    std::memcpy(out + 3 * (size_t)n + i, &r.r, sizeof(Lanes));
  }
  scalarRowsLoop<K>(i, n, v, out);
}
} // namespace

SUITE_KERNEL void crweno5Rows(int n, const double* __restrict v, double* __restrict out) {
  scalarRowsLoop<Crweno5>(0, n, v, out);
}

SUITE_KERNEL void crweno5MappedRows(int n, const double* __restrict v, double* __restrict out) {
  scalarRowsLoop<Crweno5Mapped>(0, n, v, out);
}

SUITE_KERNEL void enoPadeBlendRows(int n, const double* __restrict v, double* __restrict out) {
  lanesRowsLoop<EnoPadeBlend>(n, v, out);
}

RowsFunction batchedRows(RowFunction fn) {
  if (fn == crweno5Row) return crweno5Rows;
  if (fn == crweno5MappedRow) return crweno5MappedRows;
  if (fn == enoPadeBlendRow) return enoPadeBlendRows;
  return nullptr;
}

} // namespace suite::euler
