// Sparse FEM elastodynamics on tetrahedral meshes: P1/P2, linear / St. Venant-Kirchhoff / corotational
// material, Newmark + Newton, orderings natural|cm|rcm|amd|metis|auto, skyline or CHOLMOD Cholesky (after
// Nilsson & Dieckmann, SIGRAD 2003). The computation is serial; at several ranks every rank runs it
// identically and rank 0 writes.
//
// Sample runs (tests/sample_runs.py executes each line):
//   femdyn -static -tip_load 1 -beam_cells 20,2,2 -order 2 -output cant.h5       # tip_deflection attribute
//   femdyn -material stvk -beam_cells 20,3,3 -dt 0.01 -steps 50 -tip_load 1 -output dyn.h5
//   femdyn -material linear -ordering rcm -solver skyline -gravity 0,-1,0 -steps 100 -output lin.h5
//   femdyn -static -material stvk -tip_load 25 -load_steps 10 -output elastica.h5
//   femdyn -options_file inputs/femdyn/default.yaml -output out/femdyn.h5
#include "core/run_context.hpp"
#include "femdyn_run.hpp"

static const char help[] = "FEM elastodynamics (Newmark + Newton) with RCM/AMD/METIS orderings.\n";

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, help, "femdyn");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(femdyn_app::runFemdyn(ctx));
}
