// One row of a (possibly compact) interface-flux reconstruction at x_{j+1/2}:
//     a * h_{j-1/2} + b * h_{j+1/2} + c * h_{j+3/2} = r,
// built from the six point values v[0..5] = f_{j-2} .. f_{j+3}. Explicit schemes have a = c = 0, b = 1.
// Rows are left-biased (upwind for the f+ part of a flux splitting); mirrorRow gives the right-biased row for
// f-.
#pragma once

namespace suite::euler {

struct Row {
  double a, b, c, r;
};

using RowFunction = Row (*)(const double* v);

// Right-biased row at x_{j+1/2} for f-: the left-biased rule applied to the mirrored stencil (f_{j+3} ..
// f_{j-2}), with the roles of h_{j-1/2} and h_{j+3/2} exchanged.
inline Row mirrorRow(RowFunction fn, const double* v) {
  const double w[6] = {v[5], v[4], v[3], v[2], v[1], v[0]};
  Row row = fn(w);
  const double a = row.a;
  row.a = row.c;
  row.c = a;
  return row;
}

} // namespace suite::euler
