// The contact step solved per island (StepperOptions::islands, islands.hpp): each island's contacts, with
// their previous impulses (warm starts, scaled_box / splitting estimates), go through the same per-problem
// solve as the whole scene (Stepper::solveProblem) on the island's bodies only. The islands are run by the
// stepper's TaskRunner (on this process, or dealt over MPI ranks); each island's answer (velocities of its
// dynamic bodies, impulses of its contacts, statistics) travels as one flat vector of doubles and is put
// back by island index, so the step is the same whichever process solved which island.
#include "contact/friction_formulation.hpp"
#include "contact/islands.hpp"
#include "contact/stepper.hpp"

#include <algorithm>
#include <chrono>

namespace suite::contact {

namespace {

void putString(const std::string& s, std::vector<double>* out) {
  out->push_back((double)s.size());
  for (unsigned char c : s) out->push_back(c);
}

std::string getString(const std::vector<double>& in, size_t* at) {
  const size_t n = (size_t)in[(*at)++];
  std::string s;
  for (size_t i = 0; i < n; ++i) s += (char)(unsigned char)in[(*at)++];
  return s;
}

void putVector(const std::vector<double>& v, std::vector<double>* out) {
  out->push_back((double)v.size());
  out->insert(out->end(), v.begin(), v.end());
}

std::vector<double> getVector(const std::vector<double>& in, size_t* at) {
  const size_t n = (size_t)in[(*at)++];
  std::vector<double> v(in.begin() + *at, in.begin() + *at + n);
  *at += n;
  return v;
}

// The statistics a per-problem solve sets (see the formulations), as doubles (integers exactly).
void packStats(const StepStats& s, std::vector<double>* out) {
  out->insert(out->end(),
              {(double)s.rows, (double)s.fallbacks, (double)s.iterations, (double)s.pivots,
               (double)s.refinements, s.residual, (double)s.splitting_iterations, s.splitting_error,
               (double)s.factorizations, (double)s.budget_stop, (double)s.failed, (double)s.friction_rung,
               (double)s.auto_solves, (double)s.target_missed, (double)s.proximal_steps});
  for (const std::vector<double>* v : {&s.split_errors, &s.split_ratios, &s.problem_rungs, &s.problem_rows,
                                       &s.problem_times, &s.problem_violations})
    putVector(*v, out);
  putString(s.solver, out);
  putString(s.message, out);
}

StepStats unpackStats(const std::vector<double>& in, size_t at) {
  StepStats s;
  s.rows = (int)in[at], s.fallbacks = (int)in[at + 1], s.iterations = (int)in[at + 2];
  s.pivots = (long long)in[at + 3], s.refinements = (int)in[at + 4], s.residual = in[at + 5];
  s.splitting_iterations = (int)in[at + 6], s.splitting_error = in[at + 7];
  s.factorizations = (int)in[at + 8], s.budget_stop = in[at + 9] != 0, s.failed = in[at + 10] != 0;
  s.friction_rung = (int)in[at + 11], s.auto_solves = (int)in[at + 12], s.target_missed = (int)in[at + 13];
  s.proximal_steps = (int)in[at + 14];
  at += 15;
  for (std::vector<double>* v : {&s.split_errors, &s.split_ratios, &s.problem_rungs, &s.problem_rows,
                                 &s.problem_times, &s.problem_violations})
    *v = getVector(in, &at);
  s.solver = getString(in, &at);
  s.message = getString(in, &at);
  return s;
}

// Adds island k's statistics to the step's (islands in order; see StepStats for the rules).
void mergeStats(const StepStats& s, int k, StepStats* st) {
  st->rows += s.rows;
  st->fallbacks += s.fallbacks, st->iterations += s.iterations, st->pivots += s.pivots;
  st->refinements += s.refinements, st->factorizations += s.factorizations;
  st->proximal_steps += s.proximal_steps;
  st->residual = std::max(st->residual, s.residual);
  st->splitting_error = std::max(st->splitting_error, s.splitting_error);
  st->splitting_iterations = std::max(st->splitting_iterations, s.splitting_iterations);
  st->budget_stop = st->budget_stop || s.budget_stop;
  st->friction_rung = std::max(st->friction_rung, s.friction_rung);
  st->auto_solves += s.auto_solves, st->target_missed += s.target_missed;
  for (auto [from, to] : {std::pair{&s.problem_rungs, &st->problem_rungs},
                          {&s.problem_rows, &st->problem_rows},
                          {&s.problem_times, &st->problem_times},
                          {&s.problem_violations, &st->problem_violations}})
    to->insert(to->end(), from->begin(), from->end());
  if (st->split_errors.size() < s.split_errors.size()) st->split_errors.resize(s.split_errors.size(), 0.0);
  for (size_t p = 0; p < s.split_errors.size(); ++p)
    st->split_errors[p] = std::max(st->split_errors[p], s.split_errors[p]);
  if (k == 0) st->split_ratios = s.split_ratios, st->solver = s.solver;
  if (s.fallbacks > 0 && st->fallbacks == s.fallbacks) st->solver = s.solver; // the first with a fallback
}

// Island k's answer into the step's velocities and impulses (layout: Stepper::solveIslands).
size_t scatterIsland(const Island& isl, const std::vector<double>& r, std::vector<Vec3>* v,
                     std::vector<Vec3>* w, std::vector<Vec3>* lam) {
  size_t at = 1;
  for (std::vector<Vec3>* x : {v, w})
    for (int b : isl.bodies) (*x)[b] = Vec3(r[at], r[at + 1], r[at + 2]), at += 3;
  for (int c : isl.contacts) (*lam)[c] = Vec3(r[at], r[at + 1], r[at + 2]), at += 3;
  return at;
}

} // namespace

// Island k's answer: [1, v and w of its dynamic bodies (ascending), its contacts' impulses, stats], or
// [0, stats] when its problem was not solved.
std::vector<double> Stepper::solveIsland(const std::vector<Body>& bodies, const Island& isl,
                                         const IslandInput& in, std::vector<lcp::Problem>* problems,
                                         lcp::Vec* solution) const {
  const IslandScene s = islandScene(bodies, contacts_, isl);
  std::vector<Vec3> kv, kw, kprev, klam;
  std::vector<bool> khas;
  std::vector<int> krung;
  for (int g : s.global) kv.push_back(in.v[g]), kw.push_back(in.w[g]);
  for (int c : isl.contacts)
    kprev.push_back(in.prev[c]), khas.push_back(in.has_prev[c]), krung.push_back(in.prev_rung[c]);
  StepStats ks;
  const bool ok = solveProblem(s.bodies, {s.contacts, kprev, khas, krung, &s.global}, &kv, &kw, &klam, &ks,
                               problems, solution);
  std::vector<double> out{ok ? 1.0 : 0.0};
  for (const std::vector<Vec3>* x : {&kv, &kw})
    for (size_t i = 0; ok && i < s.global.size(); ++i)
      if (!s.bodies[i].is_static) out.insert(out.end(), {(*x)[i].x(), (*x)[i].y(), (*x)[i].z()});
  for (size_t c = 0; ok && c < klam.size(); ++c)
    out.insert(out.end(), {klam[c].x(), klam[c].y(), klam[c].z()});
  packStats(ks, &out);
  return out;
}

bool Stepper::solveIslands(const std::vector<Body>& bodies, const std::vector<Vec3>& prev,
                           const std::vector<bool>& has_prev, const std::vector<int>& prev_rung,
                           std::vector<Vec3>* v, std::vector<Vec3>* w, std::vector<Vec3>* lam,
                           StepStats* st) {
  auto t = std::chrono::steady_clock::now();
  const std::vector<Island> islands = splitIslands(bodies, contacts_, joined_);
  const int n = (int)islands.size();
  st->islands = n;
  st->largest_island_bodies = n ? (int)islands[0].bodies.size() : 0;
  st->largest_island_contacts = n ? (int)islands[0].contacts.size() : 0;
  const IslandInput in{prev, has_prev, prev_rung, *v, *w};
  std::vector<std::vector<double>> res(n);
  int solved = n;
  if (keep_problems_) { // every problem kept for dumping: the islands in order on every process
    for (int k = 0; k < solved; ++k)
      if ((res[k] = solveIsland(bodies, islands[k], in, &problems_, &solution_))[0] == 0.0) solved = k + 1;
  } else {
    lcp::Vec sol;
    std::vector<lcp::Problem> probs;
    auto one = [&](int k) {
      auto t0 = std::chrono::steady_clock::now();
      const double c0 = threadCpu();
      std::vector<double> r = solveIsland(bodies, islands[k], in, &probs, &sol);
      phases_.own_solves += lap(&t0), ++phases_.own_islands, phases_.cpu_own_solves += threadCpu() - c0;
      return r;
    };
    phases_.match += lap(&t);
    const double c0 = threadCpu();
    const std::string err = runner_(n, one, &res);
    phases_.dealing += lap(&t), phases_.islands += n, phases_.cpu_dealing += threadCpu() - c0;
    if (!err.empty()) return st->failed = true, st->message = "islands: " + err + "; ", false;
  }
  int bad = -1;
  for (int k = 0; k < solved; ++k) {
    const size_t at = res[k][0] != 0.0 ? scatterIsland(islands[k], res[k], v, w, lam) : 1;
    const StepStats ks = unpackStats(res[k], at);
    for (int c : islands[k].contacts) rungs_[c] = ks.friction_rung;
    mergeStats(ks, k, st);
    if (res[k][0] == 0.0 && bad < 0) bad = k;
  }
  if (bad >= 0) failedIsland(bodies, islands, in, bad, res[bad], st);
  phases_.unpack += lap(&t);
  return bad < 0;
}

// The first failed island k: solved again here (the same failure) unless its problem was kept, so that
// lastProblems() holds it for the dump; the message names the island.
void Stepper::failedIsland(const std::vector<Body>& bodies, const std::vector<Island>& islands,
                           const IslandInput& in, int k, const std::vector<double>& r, StepStats* st) {
  const Island& isl = islands[k];
  if (!keep_problems_) solveIsland(bodies, isl, in, &problems_, &solution_);
  st->failed = true;
  st->message = "island " + std::to_string(k + 1) + " of " + std::to_string(islands.size()) + " (" +
                std::to_string(isl.bodies.size()) + " bodies, " + std::to_string(isl.contacts.size()) +
                " contacts): " + unpackStats(r, 1).message;
}

} // namespace suite::contact
