// Registry of the spatial schemes selectable with -scheme: one entry per reconstruction (added in one file
// plus one line in schemes.cpp). Flux-split schemes give rows (row.hpp) for the smooth and the shock case;
// muscl2 is a state-reconstruction + HLLC scheme.
#pragma once

#include "euler/row.hpp"

#include <string>
#include <vector>

namespace suite::euler {

struct SchemeInfo {
  const char* name;
  const char* description;
  bool compact; // rows couple neighbouring interfaces (tridiagonal solve)
  bool hybrid;  // lines switch between smooth_row and shock_row rows by the ENO-Pade sensor (direction_sweep)
  bool state_riemann;                // muscl2: reconstruct primitive states, HLLC flux (no flux splitting)
  RowFunction smooth_row, shock_row; // interior rows (shock_row used everywhere unless hybrid)
  RowFunction boundary_smooth, boundary_shock; // explicit closure rows at the ends of a non-periodic line
  int order;                                   // formal order in smooth flow
  // Default flux upwinding of the flux-split schemes (-upwinding; rf_char.hpp): rf-char for every one (with its
  // rows of a shocked line all ENO-Pade rows, enopade6 gains from rf-char as CRWENO5 does).
  bool rf_char_default;
};

// nullptr when unknown.
const SchemeInfo* findScheme(const std::string& name);
// Every registered scheme, in registry order (name and description document -scheme).
std::vector<const SchemeInfo*> allSchemes();
// "enopade6, crweno5, weno5, muscl2"
std::string schemeNames();

} // namespace suite::euler
