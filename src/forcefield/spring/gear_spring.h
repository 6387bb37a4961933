// Gear springs between Rigid3d frames (GearSpringForceField): the per-spring
// parameters, their text form and the force kernels. SOFA's GearSpring and
// GearSpringForceField compute the same, in the same operation order.
//
// A spring couples two gears. Gear 1 is frame m1 of object1, held on its
// pivot p1 (a frame of the same state; p1 = m1: its initial position) by hard
// translational and rotational stiffnesses, except about its free axis, local
// axis `axis1` of the gear; gear 2 likewise (m2, p2, axis2 in object2). The
// rotations of the gears about their free axes relative to their pivots,
// accumulated over the steps (angle1, angle2), are tied by the ratio: the
// torque f = −ks_soft·(ratio·angle1 + angle2) turns gear 1 and f/ratio gear 2.
//
// Conventions: coordinates (x y z qx qy qz qw), derivatives (vx vy vz ωx ωy ωz)
// with ω in the world frame; stiffnesses force/length and torque/radian; kd
// multiplies the relative velocity of gear and pivot.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "math/quat.h"
#include "math/types.h"

namespace sinew::gears {

struct GearSpring {
  unsigned m1 = 0, m2 = 0;  // the gears: frame of object1, frame of object2
  unsigned p1 = 0, p2 = 0;  // their pivots (same state as the gear)
  std::array<unsigned, 2> axis{0, 0};  // free (gear) axis of gear 1 and gear 2: 0 x, 1 y, 2 z
  double hard_trans = 10000;  // stiffness holding a gear on its pivot [force/length]
  double soft_rot = 10000;    // gear coupling stiffness [torque/radian]
  double hard_rot = 10000;    // stiffness holding the other rotations [torque/radian]
  double kd = 10000;          // damping on the gear–pivot relative velocity (SOFA's default)
  double ratio = 1;           // gear ratio (not 0)
};

// What the force keeps for the next steps and for the tangent (SOFA keeps it
// in the spring): the accumulated angles and the pivots' frames.
struct GearWork {
  double previous_angle1 = 0, previous_angle2 = 0;  // angle of the last evaluation
  double angle1 = 0, angle2 = 0;                    // accumulated angle
  double x1[7] = {0, 0, 0, 0, 0, 0, 1}, x2[7] = {0, 0, 0, 0, 0, 0, 1};  // pivot frames (SOFA's ini1, ini2)
  double torque = 0;  // last 1-D coupling force f
};

// Parses SOFA's `spring` text: any number of
//   BEGIN_SPRING p1 m1 p2 m2 [AXIS a1 a2] [KS_T hard] [KS_R soft hard] [KD kd] [RATIO r] END_SPRING
// As SOFA reads one spring object over and over, AXIS goes back to (0, 0) at
// every spring while KS_T, KS_R, KD and RATIO keep the previous spring's
// values (the first spring starts from the defaults above).
// Returns "" on success, else what is wrong (the token and the spring number).
std::string parse_gear_springs(std::string_view text, std::vector<GearSpring>& out);

// SOFA's getAngleAroundAxis: the rotation of frame `b` relative to frame `a`
// about `a`'s local axis `axis`, the mean of the angles between their two
// other axes, signed by the axis [radian].
double angle_around_axis(const double* a, const double* b, unsigned axis);

// SOFA's reinit: the angles from the positions (0 for a gear that is its own
// pivot, whose initial frame is then kept as its pivot).
void init_gear_work(const GearSpring& s, const double* x1, const double* x2, GearWork& w);

// f1, f2 += the spring's forces at (x, v); updates the accumulated angles.
void add_gear_spring_force(const GearSpring& s, GearWork& w, const double* x1, const double* v1, double* f1,
                           const double* x2, const double* v2, double* f2);
// df += k·(SOFA's stiffness)·dx, with the pivot frames of the last force.
void add_gear_spring_dforce(const GearSpring& s, const GearWork& w, const double* dx1, double* df1,
                            const double* dx2, double* df2, double k);

}  // namespace sinew::gears
