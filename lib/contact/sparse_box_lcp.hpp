// The box LCP of the contact rows (box_lcp.hpp) solved on the sparse Delassus matrix (delassus_sparse.hpp):
//   w = A z + b,  l_i <= z_i <= u_i  (z_i = l_i => w_i >= 0, z_i = u_i => w_i <= 0, else w_i = 0),
// rows with l_i = u_i = 0 (zero-bound tangents) left out. Bounds may be coupled to a normal row, |z_i| <=
// coef_i z_link(i) (the Coulomb box of the sequential-impulse solvers).
//   pgs         projected Gauss-Seidel sweeps, matrix-free through J and M^-1 (O(rows) per sweep, the row's
//               bounds read from the current normal impulse when coupled): Erleben, "Velocity-based shock
//               propagation for multibody dynamics animation", ACM TOG 26 (2007); Catto, "Iterative dynamics
//               with temporal coherence", GDC 2005 (sequential impulses with warm starting).
//   activeSet   active-set Newton (block principal pivoting with a single-row backup; Judice & Pires,
//               Comput. Oper. Res. 21 (1994)) from the states read off z - 8 w / A_ii (z - w / A_ii once
//               the exchange stalls): the free rows solved with a body-space factorisation
//               (body_space_solve.hpp) when the compliance is positive and the masses are given (by
//               BodySpaceSolver when given one: its symbolic analysis and its last factorisation reused), else a sparse LDL^T of A_FF (Eigen SimplicialLDLT, AMD ordering).
// The residual is the diagonally scaled natural-map residual max_i A_ii |z_i - mid(l_i, u_i, z_i - w_i /
// A_ii)|, in velocity units like the tolerance rel_tol (1 + |b|_inf): it equals |w_i| on a free row (the dense
// chain's natural-map residual there) and does not change when every mass is scaled (lcp/problem.hpp's unscaled
// one mixes impulses and velocities: 1,000 kg bodies made it 1,000 times stricter on rows at a bound).
#pragma once

#include "contact/body_space_solve.hpp"
#include "contact/collision.hpp"
#include "contact/delassus_sparse.hpp"

namespace suite::contact {

struct SparseBoxLcp {
  const std::vector<JRow>* rows = nullptr;
  const DelassusSystem* sys = nullptr; // its sparse Delassus matrix (regularised diagonal included)
  int nbodies = 0;
  const std::vector<M6>* mass = nullptr; // body mass matrices: free rows solved in body space when given
  BodySpaceSolver* body = nullptr; // with mass: the body-space solver kept across solves (else one each)
  lcp::Vec b, l, u, reg;           // reg: the compliance part of A_ii (A_ii - (J M^-1 J^T)_ii)
  lcp::Vec diag;                   // A_ii (regularised), the scale of the residual and of the state read
  std::vector<int> link; // coupled bounds: row link[i] >= 0 gives |z_i| <= coef[i] z_link (else l, u)
  std::vector<double> coef;
  std::vector<int> order; // PGS row order (empty: 0..n-1)
  bool symmetric = false; // PGS: every other sweep in the reverse order (symmetric Gauss-Seidel)
  int size() const { return (int)b.size(); }
  bool active(int i) const { return link[i] >= 0 ? coef[i] > 0 : !(l[i] == 0 && u[i] == 0); }
  double lower(int i, const lcp::Vec& z) const { return link[i] >= 0 ? -coef[i] * z[link[i]] : l[i]; }
  double upper(int i, const lcp::Vec& z) const { return link[i] >= 0 ? coef[i] * z[link[i]] : u[i]; }
};

// The problem of the sparse system sys (its rows, b, reg and masses) with fixed bounds l, u (link -1
// everywhere).
SparseBoxLcp makeSparseBoxLcp(const DelassusSystem& sys, lcp::Vec l, lcp::Vec u);

// What a sparse solve did.
struct SparseSolveStats {
  int sweeps = 0, factorizations = 0;
  long long pivots = 0;   // state changes of the active-set iterations
  double residual = 0.0;  // natural-map residual of the returned z (active rows)
  double tolerance = 0.0; // rel_tol (1 + |b_active|_inf)
};

// The acceptance tolerance rel_tol (1 + |b|_inf over the active rows), as lcp::acceptanceTolerance.
double sparseTolerance(const SparseBoxLcp& p, double rel_tol);
// Scaled natural-map residual of z (w = A z + b matrix-free) over the active rows; w returned when asked.
double sparseResidual(const SparseBoxLcp& p, const lcp::Vec& z, lcp::Vec* w = nullptr);
// Row order of the sweeps: contact by contact (its rows together) by increasing height along -gravity, so that
// one sweep carries the support from the ground up a stack (Erleben 2007's shock propagation order).
std::vector<int> heightOrder(const std::vector<Contact>& cs, const Vec3& gravity, int per);
// Up to max_sweeps PGS sweeps from z, stopping after a sweep whose max |change| is <= tol. Returns sweeps.
int pgsSweeps(const SparseBoxLcp& p, int max_sweeps, double tol, lcp::Vec* z);
// Cold start of the active set (fixed bounds): the answer with every active row free (z = -A^-1 b on them, one
// factorisation: exact for a structure at rest with every contact pressed and sticking) replaces z when its
// residual is lower. Returns whether it did.
bool freeStart(const SparseBoxLcp& p, lcp::Vec* z, SparseSolveStats* st);
// The first state read of activeSetSolve, z - gain w / A_ii (sparse_box_lcp.cpp explains the 8).
constexpr double kJumpGain = 8.0;
// Active-set Newton from z (fixed bounds only), at most max_it factorisations; z <- the best iterate.
// true: residual <= rel_tol (1 + |b|_inf) (st: counts, residual). solve_once: at least one exact solve even
// when z already meets the tolerance (its answer then exact to round-off on the index sets of z). gain: of the
// first state read (1: each row's own Newton step, for a start whose states are nearly right).
bool activeSetSolve(const SparseBoxLcp& p, int max_it, double rel_tol, lcp::Vec* z, SparseSolveStats* st,
                    bool solve_once = false, double gain = kJumpGain);

// Proximal-point active set (Rockafellar, "Monotone operators and the proximal point algorithm", SIAM J.
// Control Optim. 14 (1976); for LCPs Cottle, Pang & Stone, "The linear complementarity problem" (1992), 5.6),
// for the narrow boxes where activeSetSolve stalls: the four contact points of a face give 8 tangent rows for 3
// in-plane degrees of freedom, their block of A held only by the tangential compliance (relative 1e-8), so the
// free impulses of an exact solve run far outside boxes of width mu lambda_n and the exchange cycles. Each
// proximal step solves (activeSetSolve, from z_k) the box LCP of A + R, b - R z_k, with R = rho diag(A_ii) on the
// rows with a finite box (fixed bounds), well posed as with a compliance of rho; its answer z_{k+1} solves the
// original problem once z_{k+1} = z_k (A z + b = -R (z_{k+1} - z_k) on a free row). The error of a mode of A_FF
// with eigenvalue s falls by rho / (rho + s) per step; a near-null mode (s ~ the compliance) keeps its error, but
// moves w by s times it, below the tolerance. Each subproblem starts from z_k with the rows' own Newton read
// (gain 1). rho starts at `rho` and is multiplied by `shrink` after each solved subproblem (down to rho_min:
// faster steps once the states have settled); a failed subproblem (its exchange stalls too) restarts from z_k
// at rho / shrink, and once a subproblem has been solved, each failure also slows the shrinking (its factor
// becomes its square root). z <- the best point; true when it meets rel_tol (1 + |b|_inf); steps counts the
// subproblems.
struct ProximalOptions {
  double rho = 1e-4, rho_min = 1e-7, shrink = 0.1;
  int max_steps = 40;          // proximal steps (subproblems)
  int max_factorizations = 20; // per subproblem
};
bool proximalSolve(const SparseBoxLcp& p, const ProximalOptions& o, double rel_tol, lcp::Vec* z,
                   SparseSolveStats* st, int* steps);

} // namespace suite::contact
