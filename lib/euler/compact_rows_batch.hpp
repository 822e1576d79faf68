// Compact rows of many stencils at once: the rows of a RowFunction over n stencils held as structure of arrays,
// in loops the compiler vectorises (kernel_clones.hpp: AVX2 where the CPU has it). Bitwise the rows of the
// scalar functions (both call compact_row_kernels.hpp). Used for the ENO-Pade / CRWENO rows of the block lines
// (direction_sweep.cpp): there the weights' divisions, computed one stencil at a time by the scalar functions,
// are a third to a half of a shocked line's cost.
#pragma once

#include "euler/row.hpp"

namespace suite::euler {

// v[m * n + i]: value m (0 .. 5) of stencil i, f_{j-2} .. f_{j+3}; out[j * n + i]: a, b, c, r (j = 0 .. 3) of
// its row.
using RowsFunction = void (*)(int n, const double* v, double* out);

void crweno5Rows(int n, const double* v, double* out);       // crweno5Row (crweno5.hpp)
void crweno5MappedRows(int n, const double* v, double* out); // crweno5MappedRow (crweno5.hpp)
void enoPadeBlendRows(int n, const double* v, double* out);  // enoPadeBlendRow (crweno_cu6.hpp)

// The batched form of fn, or nullptr when it has none.
RowsFunction batchedRows(RowFunction fn);

} // namespace suite::euler
