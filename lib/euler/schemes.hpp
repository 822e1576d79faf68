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
  bool compact;                      // rows couple neighbouring interfaces (tridiagonal solve)
  bool hybrid;                       // rows switch between smooth_row and shock_row by the ENO-Pade sensor
  bool state_riemann;                // muscl2: reconstruct primitive states, HLLC flux (no flux splitting)
  RowFunction smooth_row, shock_row; // interior rows (shock_row used everywhere unless hybrid)
  RowFunction boundary_smooth, boundary_shock; // explicit closure rows at the ends of a non-periodic line
  int order;                                   // formal order in smooth flow
  // Default flux upwinding of the flux-split schemes (-upwinding; rf_char.hpp): rf-char for CRWENO5 and WENO5,
  // Lax-Friedrichs for ENO-Pade, whose Pade rows next to rf-char shock rows shed grid-scale waves (measured:
  // Sod N = 800, fixed dt 2.5e-4, L1(rho) 1.7e-3 with rf-char against 7.2e-4 with Lax-Friedrichs).
  bool rf_char_default;
};

// nullptr when unknown.
const SchemeInfo* findScheme(const std::string& name);
// Every registered scheme, in registry order (name and description document -scheme).
std::vector<const SchemeInfo*> allSchemes();
// "enopade6, crweno5, weno5, muscl2"
std::string schemeNames();

} // namespace suite::euler
