// Scenes of the contact app: incline (box on a plane of angle theta), drop (one body dropped on a plane),
// box_stack, pyramid, pile_grid (a grid of pyramids), log_heap (capsule logs dropped between walls), and a
// scene file format for arbitrary bodies (described for users in docs/contact.md). Every scene is built identically on every rank (replicated, deterministic, seeded).
//
// Scene file (one body per line, '#' starts a comment, key=value tokens, vectors comma-separated):
//   plane    name=ground normal=0,0,1 point=0,0,0
//   box      name=b half=0.5,0.5,0.5 pos=0,0,0.5 [axis_angle=ax,ay,az,deg] [density=1000 | mass=2]
//            [vel=vx,vy,vz] [omega=wx,wy,wz] [static]
//   sphere   radius=R ...;  capsule / cylinder  radius=R half_length=H ... (axis = local z)
//   joint    type=ball|hinge|slider|fixed|distance a=BODY [b=BODY|world] anchor=x,y,z [axis=x,y,z]
//            [anchor_b=x,y,z (distance)] [name=j]   (assembled at the bodies' poses; b defaults to the world)
#pragma once

#include "contact/body.hpp"
#include "contact/joint.hpp"
#include "core/named_choice.hpp"

#include <string>
#include <vector>

namespace suite::contact {

struct SceneParams {
  std::string scene = "incline";
  double theta_deg = 20.0; // incline angle
  double size = 1.0;       // box edge / sphere diameter / log length scale
  double density = 1000.0;
  double mass = 0.0;     // > 0 overrides density for the main bodies of incline / drop
  double v0 = 0.0;       // initial speed (incline: downhill; drop: along x)
  double height = 1.0;   // drop: initial gap between body and plane
  double tilt_deg = 0.0; // drop: initial rotation about x
  double spin = 0.0;     // drop: initial angular velocity about y (rad/s)
  std::string drop_body = "sphere";
  int stack_height = 5;
  int pyramid_base = 4;
  int piles = 25; // pile_grid: number of pyramids
  int n_logs = 40;
  double log_radius = 0.1, log_length = 1.0;
  unsigned seed = 1;
  std::string file; // scene file for scene "file"
  // pendulum, double_pendulum, chain: capsule links (segment -link_length between the joints at its ends,
  // radius -link_radius, mass -link_mass) hinged to the world at the origin, released at -angle degrees from
  // the downward vertical in the x-z plane; chain: -links links on -joint_type joints and an end sphere (radius
  // 2 link radii) of -end_mass_ratio times a link's mass (0: none). The links and the end sphere collide with
  // other bodies but not with each other (contype 2, conaffinity 1: a rope or chain model).
  int links = 10;
  std::string joint_type = "hinge";
  double angle_deg = 90.0;
  double end_mass_ratio = 0.0;
  double link_length = 0.1, link_radius = 0.01, link_mass = 1.0;
  // four_bar, slider_crank: capsule links (-link_radius, -link_mass each) in the x-z plane on hinges about y; the
  // crank starts at -crank_angle degrees from +x towards +z, turning at -crank_speed rad/s (the other links
  // start at rest: the first step's projection makes the velocities consistent). four_bar: ground pivots at 0
  // and (-ground_length, 0, 0), the coupler's joint with the rocker on the upper branch (fourBarJoint); a
  // Grashof crank-rocker by default. slider_crank: -crank_length, -coupler_length (the rod), a box slider on
  // the x axis.
  double crank_length = 0.1, coupler_length = 0.35, rocker_length = 0.2, ground_length = 0.3;
  double crank_angle_deg = 90.0, crank_speed = 10.0;
  // rope_bridge: -links planks (-link_length along the bridge, 4 -link_length wide, -link_mass) hinged edge to
  // edge, hanging in a V of -sag_angle degrees between two world hinges, and -bridge_boxes cubes (edge
  // -link_length / 2, -link_mass) dropped one above the other onto its lowest joint.
  int bridge_boxes = 3;
  double sag_angle_deg = 15.0;
  // wrecking_ball: the chain (-links, -joint_type, -angle, -link_*) hangs from a pivot so that its end sphere
  // (radius -ball_radius, -end_mass_ratio link masses) passes 0.1 radius above the ground, and swings into a
  // pyramid of -pyramid_base cubes (edge -ball_radius, -density) standing just past the lowest point (+x).
  double ball_radius = 0.1;
  // motor_limit: one capsule link (-link_*) on a hinge to the world about y, starting at rest at -angle
  // degrees from the downward vertical, limited to +-limit_angle degrees about that pose and driven by a
  // velocity motor of target -motor_speed rad/s (raising the link) and bound -motor_torque N m.
  double limit_angle_deg = 60.0, motor_speed = 2.0, motor_torque = 1.0;
};

// A scene as a model: its bodies, the joints among them, and the settings a model file carries (MJCF's
// <option>: time step and gravity; unset here means the app's options decide).
struct Model {
  std::vector<Body> bodies;
  std::vector<Joint> joints;
  double timestep = 0.0; // > 0: the file's time step
  bool has_gravity = false;
  Vec3 gravity = Vec3(0, 0, -9.81);
  double friction = -1.0; // >= 0: the file's friction coefficient (one for every contact; < 0: unset)
};

std::vector<std::string> sceneNames();
// The registered scenes with their one-line descriptions (the -scene choices, scenes.cpp's registry).
std::vector<Choice> sceneChoices();
// Throws SceneError with a one-line message for bad parameters or an unknown scene.
Model buildModel(const SceneParams& p);
std::vector<Body> buildScene(const SceneParams& p); // buildModel(p).bodies
Model readSceneFile(const std::string& path);
// The parser itself, MPI- and PETSc-free, on the file content (path names the errors): throws SceneError
// (a std::runtime_error) on any bad input; memory is bounded by the limits below.
constexpr long long kMaxSceneBytes = 64LL << 20;
constexpr int kMaxSceneBodies = 1000000;
Model parseSceneModel(const std::string& text, const std::string& path = "scene");
std::vector<Body> parseScene(const std::string& text, const std::string& path = "scene"); // its bodies
// Throws SceneError if two static bodies (other than planes) overlap by more than tol.
void validateScene(const std::vector<Body>& bodies, double tol);
// buildModel, validateScene, and a check that every pair of bodies has a contact generator (throws SceneError).
Model buildValidModel(const SceneParams& p, double overlap_tol);
// Closed-form kinematics of the four_bar and slider_crank scenes (x-z plane). fourBarJoint: the coupler-rocker
// joint B with |B - A| = b, |B - O4| = c on the branch left of A -> O4 (false: the links do not close).
// sliderCrankPosition: the slider's x at crank angle th (rad), a cos th + sqrt(b^2 - a^2 sin^2 th).
bool fourBarJoint(const Vec3& A, double b, const Vec3& O4, double c, Vec3* B);
double sliderCrankPosition(double a, double b, double th);
// A static plane with world normal n through point.
Body makePlane(const std::string& name, const Vec3& n, const Vec3& point);

} // namespace suite::contact
