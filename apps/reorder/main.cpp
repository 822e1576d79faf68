// reorder: applies fill/bandwidth reducing orderings (natural, cm, rcm, amd, metis, auto) to a Matrix Market
// matrix and reports bandwidth, profile (envelope), nnz(L), factor flops and ordering time.
//
// Sample runs (tests/sample_runs.py executes each line):
//   reorder -matrix ../shared/data/matrices/can_1072.mtx -ordering all -output can1072.h5
//   reorder -matrix ../shared/data/matrices/bcsstk10.mtx -ordering rcm -output b10.h5
#include "reorder_run.hpp"

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv,
                        "Orderings of a Matrix Market matrix: bandwidth, profile, nnz(L), flops, time.\n",
                        "reorder");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(reorder_app::runReorder(ctx));
}
