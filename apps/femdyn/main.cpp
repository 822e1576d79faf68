// Sparse FEM elastodynamics on tetrahedral meshes: P1/P2, linear / St. Venant-Kirchhoff / corotational
// material (-material auto: linear while its estimated error is below -target_error, else StVK; -dt_adapt:
// the time step from the Zienkiewicz-Xie estimate with step rejection),
// Newmark or generalized-alpha + Newton, orderings natural|cm|rcm|amd|metis|auto, skyline, banded,
// CHOLMOD or the distributed PETSc path (after Nilsson & Dieckmann, SIGRAD 2003). With
// skyline/banded/cholmod the computation is serial and replicated on every rank; with -solver petsc each
// rank assembles its elements of a METIS partition of the nodes into an MPIAIJ matrix solved with KSP
// (time-stepping state replicated). With -backend plex the beam, the state, the assembly and the output are
// distributed (a DMPlex repartitioned by PT-Scotch; femdyn_plex.hpp).
// Checkpoints (-checkpoint_dir, -checkpoint_every, -restart latest) and stop requests (SIGTERM/SIGUSR1,
// -max_walltime).
//
// Sample runs (tests/sample_runs.py executes each line):
//   femdyn -static -tip_load 1 -beam_cells 20,2,2 -order 2 -output cant.h5       # tip_deflection attribute
//   femdyn -material stvk -beam_cells 20,3,3 -dt 0.01 -steps 50 -tip_load 1 -output dyn.h5
//   femdyn -material linear -ordering rcm -solver skyline -gravity 0,-1,0 -steps 100 -output lin.h5
//   femdyn -static -material stvk -tip_load 25 -load_steps 10 -output elastica.h5
//   femdyn -options_file inputs/femdyn/default.yaml -output out/femdyn.h5
//   femdyn -material stvk -time_scheme generalized_alpha -rho_inf 0.5 -steps 50 -tip_load 1 -output ga.h5
//   mpiexec -n 2 femdyn -static -tip_load 1 -beam_cells 20,2,2 -solver petsc -ksp_type cg -pc_type gamg -output p.h5
//   femdyn -material stvk -steps 200 -tip_load 1 -checkpoint_dir ckpt -checkpoint_every 50 -output c.h5
//   femdyn -material auto -target_error 1e-2 -tip_load 1 -beam_cells 20,2,2 -dt 0.2 -steps 100 -output auto.h5
//   femdyn -material stvk -dt_adapt -target_error 1e-2 -tip_load 0.1 -beam_cells 10,1,1 -dt 0.2 -steps 25 -output adapt.h5
//   mpiexec -n 2 femdyn -backend plex -material stvk -beam_cells 40,4,4 -tip_load 1 -steps 20 -output plex.h5
#include "femdyn_run.hpp"

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, "FEM elastodynamics (Newmark + Newton) with RCM/AMD/METIS orderings.\n",
                        "femdyn");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(femdyn_app::runFemdyn(ctx));
}
