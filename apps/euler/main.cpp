// Euler equations in 1D, 2D and 3D (-dim): ENO-Pade (default), CRWENO5, WENO5-Z or MUSCL2 in space (direction by
// direction in 2D/3D), PETSc TS in time, MPI via DMDA.
//
// Sample runs (tests/sample_runs.py executes each line):
//   mpiexec -n 4 euler -problem sod -nx 400 -t_final 0.2 -scheme enopade6 -output out.h5 -error
//   euler -problem shu_osher -nx 400 -output so.h5
//   euler -problem density_wave -nx 80 -time rk4 -error
//   euler -problem blast -nx 800 -scheme weno5 -output blast.h5
//   euler -problem pulse -output pulse.h5          # 560 cells, 2000 steps, space-time density in /spacetime/rho
//   euler -problem sod -scheme muscl2 -time bdf2 -cfl 2 -error    # implicit (BDF2, JFNK)
//   euler -problem sod -nx 100 -time bdf2 -cfl 1 -error                 # implicit ENO-Pade: Newton retries
//   mpiexec -n 2 euler -problem shu_osher -nx 400 -checkpoint_dir ck -checkpoint_every 100 -max_steps 250
//   mpiexec -n 3 euler -problem shu_osher -nx 400 -checkpoint_dir ck -restart latest -output so3.h5
//   euler -scheme enopade6 -scheme_spectrum 64 -output spectrum.h5       # modified wavenumber, no flow
//   euler -options_file inputs/euler/sod.yaml
//   mpiexec -n 2 euler -dim 2 -problem isentropic_vortex -nx 32 -ny 32 -t_final 1 -error -output vortex.h5
//   mpiexec -n 2 euler -dim 2 -problem lax_liu_6 -nx 64 -ny 64 -t_final 0.05 -output ll6.h5 -snapshot_every 10
//   mpiexec -n 2 euler -dim 3 -problem explosion -nx 24 -ny 24 -nz 24 -t_final 0.02 -output ex.h5 -log_view
//   euler -dim 3 -problem taylor_green -nx 16 -ny 16 -nz 16 -t_final 0.5 -spectrum -output tg.h5
//   euler -dim 3 -problem sod -axis z -dt 5e-4 -t_final 0.05   # planar Sod along z of a 6 x 6 x 200 grid
//   mpiexec -n 2 euler -dim 2 -problem double_mach -nx 120 -ny 30 -t_final 0.02 -da_processors_x 2
//   mpiexec -n 2 euler -dim 3 -problem explosion -nx 24 -ny 24 -nz 24 -max_steps 5 -line_solve substructured
#include "core/run_context.hpp"
#include "euler_run.hpp"

static const char help[] = "Euler equations in 1D/2D/3D (ENO-Pade and comparators) with PETSc TS and DMDA.\n";

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, help, "euler");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(euler_app::runEuler(ctx));
}
