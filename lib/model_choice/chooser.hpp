// The chooser of an accuracy-target run: given candidate families (configurations as option values, see
// candidate.hpp) and a target, it
//   1. runs three pilots per family at n0, 2 n0, 4 n0 (their differences: the observed order and error
//      constant, observed_order.hpp; an order between 1 and kJumpOrderBound, a flow with jumps, is refitted at
//      order 1, atMostFirstOrderWithJumps; an order below kAsymptoticOrder adds pilot levels 8 n0, 16 n0,
//      refitting each time) and, unless a cost model was loaded, short timing runs (kTimingSteps steps) at
//      8 n0 and 32 n0 (at most n_max; a timing run predicted to cost more than the family's pilots is left
//      out): with the pilots' timings, the cost model (cost_model.hpp). Families go cheapest first, by a probe
//      (a timing run at n0) or the loaded cost model, one family's pilots after the other's; with an error
//      target, a family whose pilots still needed for its fit (from n0 on) are predicted to cost more than a
//      candidate already known to meet the target is left out (it cannot lower the whole cost); on a flow with
//      jumps, before its third pilot, together with its own candidate by the fit of its first two
//      (provisionalCandidateSeconds),
//   2. tabulates every candidate (family x resolution ladderN(n0, per_octave, k) up to n_max) with its
//      predicted cost and predicted error,
//   3. picks the cheapest candidate predicted to meet target_error / safety (or, with target_walltime alone,
//      the most accurate one predicted to finish within the time left; with an error target, after timing runs
//      at the candidates near its cost that lie beyond their family's timed runs, timeNearChoice), runs it
//      through the caller's runner,
//   4. checks its own estimate: the final run at n against the finest earlier run b <= n/2 of its family and
//      the finest run a <= b/2: the order observed again from a, b, n (fitObservedOrder, at most 1 as above),
//      or without a the pair estimate with the order so far (ratios of 2 or more: closer runs of a flow with
//      discontinuities differ mostly by the sub-cell placement of the jumps). When that estimate misses the
//      target and the final run is above the earlier runs (whose order may be pre-asymptotic there), check
//      runs at n/4 and n/2 (no output; 5/16 of the final's cost in 1D, 9/64 in 2D; each unless an earlier run
//      lies within a factor kCheckGap / 2 below it) become a and b, and the estimate is made again from them
//      before escalating (the order of that fit at most 1 when the family's is below 2: see runFinal). A
//      lower order observed this way caps every family's order (the problem's regularity bounds them all).
//      When the estimate misses the target the family's fit is replaced by what the final run showed and the
//      next candidate is run (at most max_escalations times): one predicted to cost at most kEscalationGrowth
//      times the missed run when one is predicted to meet the target or, of the missed family, to improve on
//      it (escalationCandidate), else the cheapest predicted to meet the target at any cost, the families
//      without a final run judged by their pilots' fits raised by the worst miss of a final run so far
//      (fallbackCandidate).
// With a loaded cost model (-cost_model FILE), a family without complete runs there at two resolutions (the run
// that wrote FILE left it out) is left out and named in the summary; none covered is an error.
// A run that fails (RunResult::failed: a non-physical state, a failed step) leaves its family out: its pilots
// stop, a failed final run is followed by the next candidate (an escalation), and the output records the
// failure; only when every family fails is it an error. A target run thus never picks a scheme that fails on
// the problem. A target no candidate can reach is a collective error naming the best reachable error. Every
// rank takes the same decisions: the runner must return the same density field and the same seconds (e.g. the
// maximum over the ranks) on every rank.
#pragma once

#include "model_choice/candidate.hpp"
#include "model_choice/cost_model.hpp"
#include "model_choice/grid_distance.hpp"
#include "model_choice/observed_order.hpp"

#include <petscsys.h>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace suite::model_choice {

struct ChooserSettings {
  double target_error = 0.0;    // 0: none (then target_walltime must be set)
  double target_walltime = 0.0; // seconds for the whole run, pilots included; 0: none
  double safety = 2.0;          // a candidate must be predicted to reach target_error / safety
  int max_escalations = 4;
  long long n0 = 25, n_max = 3200;
  int per_octave = 4;
};

constexpr int kTimingSteps = 3;    // steps of a timing run
constexpr int kMaxPilotLevels = 5; // pilots at n0 .. 16 n0 at most
// An observed order below this from pilots at n0, 2n0, 4n0: not yet asymptotic (e.g. Shu-Osher's entropy waves
// unresolved at 32..128 cells); a further pilot level (8 n0, then 16 n0) refits the order from the last three.
constexpr double kAsymptoticOrder = 0.5;

// A check run at h = n/2 or n/4 when the final run's family has no run between 2 h / kCheckGap and h (error
// target only).
constexpr double kCheckGap = 2.1;

// An escalation runs a candidate predicted to cost at most this times the missed final run when one there is
// predicted to meet the target or, of the missed family, to improve on it (escalationCandidate): a ladder whose
// runs together cost at most 4/3 of its last one.
constexpr double kEscalationGrowth = 4.0;

// Before a family's third pilot on a flow with jumps: its own candidate is judged by the provisional fit of its
// first two pilots (order 1 through their distance) at this times the target / safety (the benefit of the
// doubt; see ModelChooser::provisionalCandidateSeconds).
constexpr double kProvisionalSlack = 2.0;

// Before a final run, a family whose best candidate is predicted within this factor of the choice's cost and
// lies above the family's finest timed run is timed at that candidate (timeNearChoice): its cost there is
// measured instead of extrapolated.
constexpr double kNearCost = 1.5;

enum class RunKind { pilot, timing, check, final };
struct RunResult {
  GridField density; // the final density on the whole grid, the same on every rank (not for timing runs)
  double seconds = 0.0;
  long long steps = 0;
  bool failed = false; // the run stopped on a non-physical state or a failed step (on every rank)
  std::string failure; // then: why
};
// Runs family f at resolution n: a pilot or a check run (to t_final, no output), a timing run (kTimingSteps
// steps, no output; seconds and steps of steady stepping: a runner may leave out a first step that warms the
// work arrays, as the Euler runner does) or a final run (to t_final, with the run's output).
using Runner = std::function<PetscErrorCode(const Family& f, long long n, RunKind kind, RunResult* r)>;

struct CandidateRow {
  int family = 0;
  long long n = 0;
  double cost = 0.0, error = 0.0; // predicted seconds, predicted L1 error
};
struct RunRecord {
  int family = 0;
  long long n = 0;
  double seconds = 0.0;
  long long steps = 0;
  double difference =
      NAN;               // L1 distance to the previous run of the family (pilots) / to the reference (final)
  double estimate = NAN; // finals: the estimated error; pilots: the fit's error at n
  bool failed = false;   // the run failed (RunResult::failed): its family is left out
};

// Resolution k of the candidates' ladder: round(n0 2^(j / per_octave)) 2^o for k = o per_octave + j, so that
// halving a candidate (its check runs, its earlier runs at ratio 2) lands on exact integers and the two runs
// are compared by restriction rather than interpolation (ladderN(32, 4, 19) = 864 = 2 x 432, where
// round(32 2^(19/4)) = 861 and 861 / 2 = 430.5 found no run at 431 and compared 861 with 215 instead).
long long ladderN(long long n0, int per_octave, int k);

// The candidate after a final run of missed_family that missed the error target (its seconds and estimate):
// among the rows not yet run (done[i] false) and predicted to cost at most kEscalationGrowth x missed_seconds,
// the cheapest feasible one; without one, the most accurate of missed_family's when predicted below
// missed_estimate; else none (n = 0: the caller takes the cheapest feasible row at any cost).
CandidateRow escalationCandidate(const std::vector<CandidateRow>& table, const std::vector<bool>& done,
                                 const std::function<bool(const CandidateRow&)>& feasible, int missed_family,
                                 double missed_seconds, double missed_estimate);

// The candidate at any cost after a miss that escalationCandidate found nothing for: the cheapest row not yet
// run (ties: the more accurate) that is feasible once the predicted error of every family without a final run
// of its own (has_final[family] false) is multiplied by miss (>= 1: the largest ratio of a final run's
// estimate to its prediction so far). Those families' fits come from the same pilots as the fit that missed;
// at the cost this fallback may reach, the miss is the only evidence on them at resolutions above their
// pilots. n = 0: none.
CandidateRow fallbackCandidate(const std::vector<CandidateRow>& table, const std::vector<bool>& done,
                               const std::function<bool(const CandidateRow&)>& feasible,
                               const std::vector<bool>& has_final, double miss);

class ModelChooser {
public:
  ModelChooser(MPI_Comm comm, std::vector<Family> families, const ChooserSettings& s, const CostModel& loaded)
      : comm_(comm), families_(std::move(families)), set_(s), cost_(loaded) {}
  PetscErrorCode run(const Runner& runner);

  const std::vector<Family>& families() const { return families_; }
  const ChooserSettings& settings() const { return set_; }
  const CostModel& costModel() const { return cost_; }
  const std::vector<ObservedOrder>& orders() const { return orders_; }
  const std::vector<CandidateRow>& table() const { return table_; }
  const std::vector<RunRecord>& pilots() const { return pilots_; }
  const std::vector<RunRecord>& finals() const { return finals_; }
  const std::vector<RunRecord>& timings() const { return timings_; }
  const std::vector<RunRecord>& checks() const { return checks_; } // difference: to the final run
  // Per family: why its run failed ("" when none did); a failed family is left out of the choice.
  const std::vector<std::string>& failures() const { return failures_; }
  const CandidateRow& chosen() const { return chosen_; } // the last candidate run
  const CandidateRow& mostAccurate() const { return most_accurate_; }
  bool met() const { return met_; } // the final estimate is within the target (or no error target)
  double pilotSeconds() const;
  double finalSeconds() const;
  double checkSeconds() const;
  std::string label(int family, long long n) const;
  std::string summary() const; // one line

private:
  PetscErrorCode runPilots(const Runner& runner);
  PetscErrorCode runPilot(const Runner& runner, size_t f, int k);
  PetscErrorCode runProbe(const Runner& runner, size_t f);
  double probePerStep(size_t f) const;
  bool uncosted(size_t f) const;
  std::string uncostedWhy(size_t f) const;
  bool allFailed() const; // every family has failed
  bool pilotTooDear(size_t f, int k, const std::vector<size_t>& completed);
  double firstPilotSeconds(size_t f, const std::vector<size_t>& completed) const;
  double pilotRatio(size_t f, int j, int k, const std::vector<size_t>& completed) const;
  double provisionalCandidateSeconds(size_t f, const std::vector<size_t>& completed) const;
  bool preAsymptotic(size_t f, int k) const;
  bool timingTooDear(size_t f, long long n) const;
  PetscErrorCode runTimings(const Runner& runner, size_t f);
  PetscErrorCode timeNearChoice(const Runner& runner, const std::vector<bool>& done, CandidateRow* c);
  PetscErrorCode timeAt(const Runner& runner, size_t f, long long n);
  long long finestTimed(size_t f) const;
  bool recordFailure(size_t f, long long n, const RunResult& r, std::vector<RunRecord>* into);
  PetscErrorCode explainAllFailed() const;
  void buildTable();
  bool feasible(const CandidateRow& r) const;
  bool better(const CandidateRow& a, const CandidateRow& b) const;
  PetscErrorCode choose(const std::vector<bool>& done, CandidateRow* out) const;
  PetscErrorCode chooseEscalation(const std::vector<bool>& done, CandidateRow* out) const;
  PetscErrorCode explainUnreachable() const;
  PetscErrorCode runFinal(const Runner& runner, const CandidateRow& c);
  PetscErrorCode runChecks(const Runner& runner, size_t f, long long n, bool* ran);
  PetscErrorCode recheck(const Runner& runner, size_t f, long long n, const GridField& u, RunRecord* rec,
                         ObservedOrder* refit);
  void capOrders(double p);
  double checkEstimate(size_t f, long long n, const GridField& u, RunRecord* rec, ObservedOrder* refit);

  MPI_Comm comm_;
  std::vector<Family> families_;
  ChooserSettings set_;
  CostModel cost_;
  std::vector<ObservedOrder> orders_;
  std::vector<std::map<long long, GridField>> runs_; // per family: the density of every run so far, by n
  std::vector<std::array<double, kMaxPilotLevels>> pilot_seconds_; // per family: its pilots' seconds by level
  std::vector<CandidateRow> table_;
  std::vector<RunRecord> pilots_, finals_, timings_, checks_;
  std::vector<std::string> failures_;
  CandidateRow chosen_, most_accurate_;
  bool met_ = false;
  double worst_miss_ = 1.0; // the largest ratio of a final run's estimate to its predicted error (>= 1)
};

} // namespace suite::model_choice
