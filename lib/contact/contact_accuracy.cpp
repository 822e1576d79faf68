// The contact accuracy modes (see contact_accuracy.hpp).
#include "contact/contact_accuracy.hpp"

#include "contact/block_pgs.hpp"
#include "contact/box_lcp.hpp"
#include "contact/sparse_box_lcp.hpp"

#include <algorithm>

namespace suite::contact {

const char* accuracyName(ContactAccuracy a) {
  switch (a) {
  case ContactAccuracy::Exact:
    return "exact";
  case ContactAccuracy::Balanced:
    return "balanced";
  case ContactAccuracy::Fast:
    return "fast";
  }
  return "?";
}

bool accuracyFromName(const std::string& name, ContactAccuracy* a) {
  for (int i = 0; i < 3; ++i)
    if (name == accuracyName(ContactAccuracy(i))) {
      *a = ContactAccuracy(i);
      return true;
    }
  return false;
}

std::vector<Choice> accuracyChoices() {
  return {{"exact", "every problem solved to -lcp_tol, fallbacks; an unsolved step ends the run"},
          {"balanced",
           "block PGS sweeps (-contact_sweeps; default max(40, H^2 / 10), H the pile height) + 1 sparse "
           "factorisation; errors recorded"},
          {"fast", "block PGS sweeps (-contact_sweeps; default max(10, H^2 / 10)); errors recorded"}};
}

int pileHeight(const std::vector<Contact>& cs, const std::vector<Body>& bodies) {
  const int nb = (int)bodies.size();
  std::vector<int> start(nb + 1, 0), nbr(2 * cs.size()); // the contacts' body graph, compressed rows
  for (const Contact& c : cs) ++start[c.a + 1], ++start[c.b + 1];
  for (int i = 0; i < nb; ++i) start[i + 1] += start[i];
  std::vector<int> next(start.begin(), start.end() - 1);
  for (const Contact& c : cs) nbr[next[c.a]++] = c.b, nbr[next[c.b]++] = c.a;
  std::vector<int> layer(nb, -1), queue;
  queue.reserve(nb);
  for (int i = 0; i < nb; ++i)
    if (bodies[i].is_static && start[i + 1] > start[i]) layer[i] = 0, queue.push_back(i);
  int height = 0;
  for (size_t k = 0; k < queue.size(); ++k)
    for (int e = start[queue[k]]; e < start[queue[k] + 1]; ++e)
      if (layer[nbr[e]] < 0)
        layer[nbr[e]] = layer[queue[k]] + 1, height = layer[nbr[e]], queue.push_back(nbr[e]);
  return height;
}

int sweepBudget(const StepperOptions& o, int height) {
  if (o.contact_sweeps > 0) return o.contact_sweeps;
  const int base = o.accuracy == ContactAccuracy::Fast ? 10 : 40;
  return std::max(base, (height * height + 9) / 10);
}

namespace {
// Bounds of the rows (n[, t1, t2] per contact): splitting couples |lambda_t| <= mu lambda_n; box and
// scaled_box fix mu nu with their estimates.
void setBounds(const ContactStep& step, const StepperOptions& o, int per, SparseBoxLcp* p) {
  std::vector<double> nu = weightEstimates(step, o);
  for (size_t i = 0; i < nu.size(); ++i) {
    if (o.friction == FrictionModel::ScaledBox && step.has_prev[i]) nu[i] = step.prev[i][0];
    for (int k = 1; k < per; ++k) {
      const int r = (int)i * per + k;
      if (o.friction == FrictionModel::Splitting)
        p->link[r] = (int)i * per, p->coef[r] = o.mu;
      else
        p->l[r] = -o.mu * nu[i], p->u[r] = o.mu * nu[i];
    }
  }
}

// The bounds frozen at mu lambda_n of z (one splitting pass), at most max_fact active-set factorisations; its
// answer replaces z when it solves the frozen problem or lowers the residual on p (the coupled bounds).
void polish(const SparseBoxLcp& p, const StepperOptions& o, int max_fact, lcp::Vec* z, StepStats* st) {
  SparseBoxLcp fixed = p;
  for (size_t r = 0; r < p.link.size(); ++r)
    if (p.link[r] >= 0) {
      const double bound = p.coef[r] * std::max(0.0, (*z)[p.link[r]]);
      fixed.l[r] = -bound, fixed.u[r] = bound, fixed.link[r] = -1;
    }
  lcp::Vec cand = *z;
  SparseSolveStats ss;
  const bool solved = activeSetSolve(fixed, max_fact, o.lcp_tol, &cand, &ss, true);
  st->factorizations += ss.factorizations;
  st->pivots += ss.pivots;
  if (solved || sparseResidual(p, cand) < sparseResidual(p, *z)) *z = cand;
}
} // namespace

bool budgetImpulses(const ContactStep& step, const DelassusSystem& sys, const StepperOptions& o,
                    Impulses* out, StepStats* st, const JointCoupling* joints) {
  const int nc = (int)step.contacts.size(), n = (int)sys.rows.size(), per = nc ? n / nc : 1;
  SparseBoxLcp p = makeSparseBoxLcp(sys, lcp::Vec::Zero(n), lcp::Vec::Constant(n, lcp::kInf));
  if (per == 3) setBounds(step, o, per, &p);
  p.order = heightOrder(step.contacts, o.gravity, per);
  p.symmetric = true; // up the stack (support) and down (weight) in turn
  lcp::Vec z(n);
  for (int i = 0; i < nc; ++i)
    for (int k = 0; k < per; ++k) z[i * per + k] = o.warm_start && step.has_prev[i] ? step.prev[i][k] : 0.0;
  const int budget = sweepBudget(o, pileHeight(step.contacts, step.bodies));
  const double tol = sparseTolerance(p, o.lcp_tol);
  const lcp::Vec b0 = p.b;
  // with joints: before each sweep, b shifted by the joint block's answer to z (see contact_accuracy.hpp)
  const std::function<double(const lcp::Vec&)> shift = [&](const lcp::Vec& zk) {
    const lcp::Vec b = b0 + (*joints)(zk);
    const double change = (b - p.b).lpNorm<Eigen::Infinity>();
    p.b = b;
    return change;
  };
  const int sweeps = blockPgsSweeps(p, step.contacts, per, budget, tol, &z, joints ? &shift : nullptr);
  if (joints) shift(z); // the residual below: of the answer's coupled problem
  st->iterations += sweeps;
  st->budget_stop = sweeps >= budget;
  if (o.accuracy == ContactAccuracy::Balanced && !joints) polish(p, o, 1, &z, st);
  st->residual = sparseResidual(p, z);
  st->rows = n;
  st->solver = std::string("block_pgs_") + accuracyName(o.accuracy);
  st->splitting_iterations = 1;
  out->z = z;
  out->lambda.assign(nc, Vec3::Zero());
  for (int i = 0; i < nc; ++i)
    for (int k = 0; k < per; ++k) out->lambda[i][k] = z[i * per + k];
  return true;
}

} // namespace suite::contact
