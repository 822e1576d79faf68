// MJCF (MuJoCo XML) reader (mjcf.cpp) and writer (mjcf_write.cpp) for the contact library's Model: a subset of MJCF whose every element
// maps onto our bodies (one shape each, centred at the centre of mass) and maximal-coordinate joints.
// Reference: MuJoCo XML Reference, mujoco.readthedocs.io/en/stable/XMLreference.html (MuJoCo 3.x).
//
// Supported subset (any other element or attribute is an error "path:LINE: ..." naming it; nothing is ignored
// silently, except the purely visual geom rgba and the two settings marked "accepted" below):
//   <mujoco model>                      the root; its sections may come in any order, and repeat
//   <compiler angle eulerseq>           angle="degree" (MuJoCo's default) | "radian"; eulerseq default "xyz"
//   <option timestep gravity integrator>   -> Model.timestep, Model.has_gravity/gravity (integrator: accepted
//                                       and not used: our stepper has its own)
//   <worldbody>  <geom>: a static body (named by the geom's name);  <body>: a body tree
//   <body name pos quat|euler|axisangle>   the frame relative to the parent body's; exactly one <geom> each,
//                                       "body 'x' has N geoms: one per body is supported"
//   <geom type size fromto pos quat|euler|axisangle mass density friction contype conaffinity name rgba>
//       type plane|sphere|box|capsule|cylinder (default sphere); size as MuJoCo: sphere "r", capsule and
//       cylinder "r half_length" (with fromto: "r"), box half extents (with fromto: "r", the half extents
//       r r |fromto|/2), plane: ignored. fromto: the centre is the midpoint and the local z axis is along
//       from - to (MuJoCo's convention). Our Body: x = the geom centre, q = the geom frame (world).
//       Mass: mass= (> 0), else density= (default 1000) times the volume; the inertia from the shape
//       (makeBody's formulas, which equal MuJoCo's solid-geom formulas: box, sphere, capsule, cylinder).
//       friction: 1-3 numbers, the first (sliding) is Model.friction; the model has one coefficient, so every
//       geom must have the same (a geom without friction= has MuJoCo's 1); no friction= anywhere: unset (-1).
//       contype/conaffinity -> Body::contype/conaffinity (default 1, 1).
//   <inertial pos mass diaginertia>     overrides the geom's mass and inertia; pos must be the geom centre and
//                                       the inertia diagonal in the geom frame (no quat)
//   <joint type name pos axis range limited>   at most one per body; joins the body (a) to its parent body (b;
//       the world: -1); pos (default 0 0 0) and axis (default 0 0 1) in the body frame. type hinge (default) ->
//       JointType::Hinge, slide -> Slider, ball -> Ball, free -> no joint (a free body), as <freejoint/>.
//       range (hinge: in the compiler's angle unit) with limited="true" (or absent: MuJoCo's autolimits) ->
//       Joint.limited/lower/upper. Sign: MuJoCo's joint coordinate is the child's (a's) motion relative to the
//       parent (b), our Joint's limit is b's relative to a (joint.hpp): lower = -range[1], upper = -range[0].
//   no joint and no <freejoint>: welded to the parent: JointType::Fixed to the parent (named "weld_BODY",
//       anchor at the body frame's origin), or a static body when the parent is the world or static.
//       <freejoint> only in a child of <worldbody> (as in MuJoCo).
//   <equality> <connect name body1 body2 anchor> -> Ball (anchor in body1's frame; body2 default "world");
//              <weld name body1 body2 anchor>    -> Fixed (anchor, default 0 0 0, in body2's frame, as MuJoCo)
//   <actuator> <velocity name joint kv forcerange forcelimited ctrlrange ctrllimited> on a hinge or slide joint
//       -> Joint.motor, max_force = forcerange[1] (forcerange symmetric, forcelimited "true" or absent), the
//       target speed from the first <keyframe><key ctrl> (one value per actuator, in order; none: 0), clamped
//       to ctrlrange, sign as for limits: target_speed = -ctrl. kv: accepted (our motor is the hard limit of
//       MuJoCo's velocity servo: the speed reached within a step, the force bounded by max_force).
//   <keyframe> <key name ctrl>
// Not supported (errors): <default> and class=, <asset>, meshes, sites, lights, cameras, tendons, sensors,
// other joint or geom attributes (damping, condim, ...), inertial quat or fullinertia, bodies without a geom.
//
// The writer emits: <compiler angle="radian"/>, <option> (timestep when > 0, gravity when set, integrator
// "implicitfast" when there are motors), static bodies as <geom>s of <worldbody> (a static body that a joint
// references as a jointless <body> instead), dynamic bodies as a forest: each body's first hinge, slider or
// ball joint that does not close a loop is its <joint>, the body nested under the joint's b; other dynamic
// bodies get <freejoint/>; the remaining ball and fixed joints become <connect> and <weld>; a loop-closing
// hinge or slider, a distance joint, a limited or motorised ball joint or loop closure throw SceneError
// ("cannot be written as MJCF"). Each MJCF body frame is our body's pose (the geom at its origin), so joint
// pos/axis are the joint's anchor and axis in a's frame; masses as geom mass= (%.17g), so that the inertia is
// derived identically on reading; an inertia that differs from the shape's as <inertial>. Not written:
// velocities (MJCF has no initial velocity outside keyframes) and joint anchors on b's side (the joints are
// taken as assembled at the bodies' poses). Body trees deeper than the XML parser's nesting limit
// (tinyxml2 9: 95 nested bodies) throw SceneError: they could not be read back.
#pragma once

#include "contact/scenes.hpp"

#include <string>

namespace suite::contact {

// Parses MJCF text (path names the errors); throws SceneError "path:LINE: message" on any bad or unsupported
// input (malformed XML: "path:LINE: malformed XML: ..." with tinyxml2's line). Bounded by kMaxSceneBytes and
// kMaxSceneBodies (scenes.hpp).
Model parseMjcf(const std::string& text, const std::string& path = "model.xml");
// Reads the file (at most kMaxSceneBytes) and parses it.
Model readMjcfFile(const std::string& path);
// The model as MJCF that parseMjcf reads back to the same bodies and joints and that MuJoCo loads; throws
// SceneError for what MJCF cannot express (see above).
std::string writeMjcf(const Model& m, const std::string& model_name);

} // namespace suite::contact
