// 1D Euler equations: ENO-Pade (default), CRWENO5, WENO5-Z or MUSCL2 in space, PETSc TS in time, MPI via
// DMDA.
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
#include "core/run_context.hpp"
#include "euler_run.hpp"

static const char help[] = "1D Euler equations (ENO-Pade and comparators) with PETSc TS.\n";

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, help, "euler");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(euler_app::runEuler(ctx));
}
