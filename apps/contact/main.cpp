// Contact app: rigid bodies with unilateral contacts and Coulomb friction, velocity time stepping with one
// LCP / box LCP per step (lib/contact on lib/lcp). After Lacoursiere, SIGRAD 2003 (box MLCPs, splitting).
// The scene is replicated on every rank (identical deterministic computation); rank 0 writes the output.
// With -contact_islands on, each step's independent islands are solved as separate problems dealt over the
// ranks and gathered to every rank (lib/contact/islands.hpp, lib/core/task_dealer.hpp). Joints are rows of the
// same step's MLCP, solved exactly in every accuracy mode and projected (lib/contact/joint_system.hpp); their
// limits and motors are its unilateral and box rows (lib/contact/joint_actuation.hpp).
//
// Sample runs (tests/sample_runs.py executes each line):
//   contact -scene incline -theta 30 -mu 0.3 -friction splitting -steps 100 -output incline.h5
//   contact -scene incline -theta 20 -mu 0.5 -friction splitting -splitting_start infinite -steps 5 -output s.h5
//   contact -scene box_stack -stack_height 4 -steps 200 -output stack.h5
//   contact -scene pyramid -pyramid_base 4 -steps 200 -output pyramid.h5
//   mpiexec -n 2 contact -scene pile_grid -piles 6 -pyramid_base 3 -contact_islands on -steps 50 -output piles.h5
//   contact -scene log_heap -n_logs 8 -steps 60 -regularisation 1e-4 -lcp_solver lemke -output heap.h5
//   contact -scene drop -drop_body box -tilt 20 -spin 3 -steps 200 -output drop.h5
//   contact -scene file -scene_file inputs/contact/two_spheres.scene -steps 100 -output file.h5
//   contact -scene chain -links 50 -dt 0.01 -steps 200 -output chain.h5
//   contact -scene four_bar -crank_speed 40 -dt 0.001 -steps 500 -output four_bar.h5
//   contact -scene rope_bridge -links 10 -bridge_boxes 3 -steps 200 -output bridge.h5
//   contact -scene rope_bridge -bridge_boxes 3 -contact_accuracy fast -contact_islands on -steps 200 -output rb.h5
//   contact -scene file -scene_file inputs/contact/supported_plank.scene -steps 100 -output plank.h5
//   contact -scene mjcf -scene_file inputs/contact/chain25.xml -steps 100 -output mjcf.h5
//   contact -scene motor_limit -motor_torque 0.2 -steps 200 -output lever.h5
//   contact -scene double_pendulum -angle 40 -write_mjcf double_pendulum.xml
//   contact -options_file inputs/contact/default.yaml -output out/contact.h5
#include "contact_run.hpp"

static const char help[] =
    "Rigid multibody contact with dry friction (box MLCPs, operator splitting, Lemke).\n";

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, help, "contact");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(contact_app::run(ctx));
}
