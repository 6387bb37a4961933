// Joint springs between two Rigid3d frames (JointSpringForceField): the
// per-spring parameters, their text form, and the force / stiffness kernels.
// Spec: mechanics.md (JointSpringForceField); SOFA's JointSpring and
// JointSpringForceField compute the same, in the same operation order.
//
// Conventions: coordinates are (x y z qx qy qz qw), derivatives
// (vx vy vz ωx ωy ωz) with ω in the world frame. Stiffnesses are per local
// axis of the first frame: force/length for translations, torque/radian for
// rotations; kd multiplies the relative velocity (world frame).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "math/quat.h"
#include "math/types.h"

namespace sinew::joints {

// What the `spring` text sets. Defaults are SOFA's: a ball joint (translations
// held by the hard stiffness, rotations free), hard stiffnesses 10000, no
// damping, no angular limits (±100000 rad).
struct JointSpring {
  unsigned m1 = 0, m2 = 0;  // frame in object1, frame in object2
  double kd = 0;
  // free[0..2]: translations along the local x, y, z; free[3..5]: rotations about them.
  std::array<bool, 6> free{false, false, false, true, true, true};
  double soft_trans = 0, hard_trans = 10000;  // stiffness on free / held translation axes
  double soft_rot = 0, hard_rot = 10000;      // stiffness on free / held rotation axes
  double bloc_rot = 100;                      // stiffness beyond an angular limit (default hard_rot/100)
  std::array<double, 6> limits{-100000, 100000, -100000, 100000, -100000, 100000};  // min max per axis (rad)
  Vec3 init_trans = Vec3::Zero();  // rest offset of the second centre from the first (world frame)
  Quat init_rot;                   // rest orientation offset, multiplied on the right of q1⁻¹·q2
  // REST_T given: bwd_init replaces init_trans and init_rot by the offsets of
  // the initial positions (SOFA's rule: the REST_T values themselves are unused).
  bool init_from_positions = false;
};

// Quantities of the last force evaluation that the stiffness reuses (SOFA
// keeps them in the spring): the first frame's orientation and the stiffness
// applied on each local axis.
struct JointWork {
  Quat ref;                      // orientation of the first frame
  Vec3 kt = Vec3::Zero();        // translation stiffness per local axis
  Vec3 kr = Vec3::Zero();        // rotation stiffness per local axis
  Vec3 torsion = Vec3::Zero();   // relative rotation, axis times angle in (−π, π]
  Vec3 lawful = Vec3::Zero();    // torsion projected into the angular limits (general case only)
  // For outfile: centre offset in the first frame's axes, relative rotation
  // (rest offsets removed), torque before rotation to the world frame, and the
  // force added on the first frame (negated on the second).
  Vec3 local = Vec3::Zero();
  Quat rel;
  Vec3 fr0 = Vec3::Zero();
  std::array<double, 6> force{};
};

// Parses SOFA's `spring` text: any number of
//   BEGIN_SPRING i j [FREE_AXIS tx ty tz rx ry rz] [KS_T soft hard] [KS_R soft hard]
//   [KS_B bloc] [KD kd] [R_LIM_X min max] [R_LIM_Y ..] [R_LIM_Z ..]
//   [REST_T x y z] [REST_R qx qy qz qw] END_SPRING
// separated by white space. As SOFA reads one spring object over and over,
// KS_T, KS_R and KD not repeated in a spring keep the previous spring's
// values; FREE_AXIS, KS_B, limits, REST_T and REST_R go back to their defaults.
// KS_B absent (or 0): hard_rot/100. A rotation axis whose two limits are
// equal is held (free = false). FREE_AXIS flags are 0 or 1.
// Returns "" on success, else what is wrong (the token and the spring number);
// `out` then holds the springs read before the error.
std::string parse_joint_springs(std::string_view text, std::vector<JointSpring>& out);

// The text SOFA writes for one spring (values equal to the defaults left out);
// parse_joint_springs reads it back to the same spring when the previous
// spring's carried-over stiffnesses are the defaults.
std::string format_joint_spring(const JointSpring& s);

// Relative rotation q as (unit axis, angle in [0, π]) (SOFA's Quat::quatToAxis):
// asin branch below 5°, axis (0, 1, 0) for no rotation.
void quat_to_axis(const Quat& q, Vec3& axis, double& angle);

// Adds the spring's force to f1[m1] and its opposite to f2[m2] (f1 and f2 may
// be the same array), and records in `w` what the stiffness needs.
// `constant`: 6 numbers added in the first frame's axes (SOFA's infile force), nullptr for zeros.
void add_joint_spring_force(const JointSpring& s, JointWork& w, const double* x1, const double* v1, double* f1,
                            const double* x2, const double* v2, double* f2, const double* constant);

// df1[m1] += k·K·(dx2[m2] − dx1[m1]), df2[m2] −= the same, with
// K = blockdiag(R·diag(kt)·Rᵀ, R·diag(kr)·Rᵀ), R the rotation of w.ref.
void add_joint_spring_dforce(const JointSpring& s, const JointWork& w, const double* dx1, double* df1,
                             const double* dx2, double* df2, double k);

// The 6×6 block K above (row-major), as the stiffness matrix holds it.
std::array<double, 36> joint_stiffness_block(const JointWork& w);

}  // namespace sinew::joints
