// Lemke's complementary pivoting method (Lemke 1965; Cottle, Pang & Stone 2009, Alg. 4.4.5, covering
// vector d = e, lexicographic minimum-ratio rule) in revised form with an explicit basis inverse that is
// refactorised (LU of the basis columns) whenever the basic solution no longer satisfies B x = q to round-off
// (checked every 8 pivots) and every 64 pivots. The polyhedral friction LCP of the log heap is highly degenerate
// (q = 0 on every cone row, opposite friction directions); the dense tableau of lib/lcp's Lemke, updated
// without refactorisation, accumulated enough round-off there to end on a false secondary ray or an
// inaccurate basis in a few percent of the steps. After each refactorisation the basis must still be feasible
// (every basic value >= -1e-9 (1 + |q| + |x|)); when it is not, the pivots have lost the path (seen on a pyramid
// of base 5, 1,000 rows, where it then cycled to the pivot cap for minutes) and the method stops with a
// numerical error, so that a chain tries its next solver. This variant is the contact library's reference
// fallback ("lemke_rf"), standard LCPs only.
#pragma once

#include "core/named_choice.hpp"
#include "lcp/solver.hpp"

#include <memory>
#include <string>
#include <vector>

namespace suite::contact {

std::unique_ptr<lcp::Solver> makeLemkeRefactored();
// lib/lcp's registry plus the contact library's own solvers ("lemke_rf"); nullptr if unknown.
std::unique_ptr<lcp::Solver> makeContactSolver(const std::string& name);
// The names makeContactSolver accepts, each with its one-line description (for -help and validation).
std::vector<Choice> contactSolverChoices();

} // namespace suite::contact
