// PatchTestMovementProjectiveConstraint: moves the border points of a box-shaped mesh for a
// patch test. The displacements of the 4 corners (8 for a 3-D mesh) are given; every listed
// point gets their bilinear (trilinear) interpolation at its place in the box, and travels
// there linearly in time as AffineMovementProjectiveConstraint's points do
// (MovementToFinalPositions).
//
// The corners are found among `constrainedPoints` at init with SOFA's comparisons (which
// pick, in list order, the first point beating the current corner on any axis) and appended
// to `cornerPoints`. alpha = |x − c0.x| / |c1.x − c0.x|, beta along y to c3, gamma along z
// to c4. Without 4 or 8 corners the points do not move. Vec3d only (SOFA also has Rigid3d,
// which no example uses).
#include <cmath>
#include <string>

#include "core/registry.h"
#include "core/state_creator.h"
#include "projective/movement_to_final_positions.h"

namespace sinew {

namespace {

class PatchTestMovementProjectiveConstraint final : public MovementToFinalPositions {
 public:
  explicit PatchTestMovementProjectiveConstraint(StateType t) : MovementToFinalPositions(t) {}

  Field<std::vector<Vec3>> constrained_points{
      this, "constrainedPoints", {}, "coordinates of the constrained points (the corners are found among them)",
      "Constraint", "length"};
  Field<std::vector<Vec3>> corner_movements{
      this, "cornerMovements", {}, "displacements of the corners of the grid (4, or 8 in 3-D)", "Constraint",
      "length"};
  Field<std::vector<Vec3>> corner_points{this, "cornerPoints", {}, "corner points (found at init)", "Constraint",
                                         "length"};

  void init() override {
    MovementToFinalPositions::init();
    if (state() != ComponentState::valid) return;
    find_corners();
    const std::size_t nc = corner_points.get().size();
    if (nc != 4 && nc != 8) {
      msg_warning("found " + std::to_string(nc) +
                  " corner points (4 or 8 expected, from constrainedPoints): the points do not move");
    } else if (corner_movements.get().size() < nc) {
      msg_warning("cornerMovements has " + std::to_string(corner_movements.get().size()) + " displacements for " +
                  std::to_string(nc) + " corners: the missing ones are taken as zero");
    }
  }

 protected:
  void final_of(const std::vector<unsigned>& idx, const std::vector<double>& x, const std::vector<double>& x0,
                std::vector<double>& xf) const override {
    const std::size_t n = std::min({x.size(), x0.size(), xf.size()}) / 3;
    for (unsigned i : idx) {
      if (i >= n) continue;
      const Vec3 d = displacement(Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]));
      for (int c = 0; c < 3; ++c) xf[3 * i + c] = x0[3 * i + c] + d[c];
    }
  }

 private:
  // SOFA's corner search, comparisons and update order included.
  void find_corners() {
    const std::vector<Vec3>& p = constrained_points.get();
    if (p.empty()) return;
    bool in3d = false;
    for (const Vec3& q : p)
      if (q[2] != p[0][2]) in3d = true;
    Vec3 c[8];
    for (Vec3& v : c) v = p[0];
    for (const Vec3& q : p) {
      if (q[0] < c[0][0] || q[1] < c[0][1] || q[2] < c[0][2]) c[0] = q;
      if (q[0] > c[2][0] || q[1] > c[2][1] || q[2] < c[2][2]) c[2] = q;
      if (q[1] < c[1][1] || q[0] > c[1][0] || q[2] < c[1][2]) c[1] = q;
      if (q[0] < c[3][0] || q[1] > c[3][1] || q[2] < c[3][2]) c[3] = q;
      if (in3d && (q[0] < c[4][0] || q[1] < c[4][1] || q[2] > c[0][2])) c[4] = q;
      if (in3d && (q[0] > c[6][0] || q[1] > c[6][1] || q[2] > c[2][2])) c[6] = q;
      if (in3d && (q[1] < c[5][1] || q[0] > c[5][0] || q[2] > c[5][2])) c[5] = q;
      else if (in3d && (q[0] < c[7][0] || q[1] > c[7][1] || q[2] > c[7][2])) c[7] = q;
    }
    std::vector<Vec3> corners = corner_points.get();
    for (int k = 0; k < (in3d ? 8 : 4); ++k) corners.push_back(c[k]);
    corner_points.set(std::move(corners));
  }

  Vec3 movement(std::size_t k) const {
    const std::vector<Vec3>& m = corner_movements.get();
    return k < m.size() ? m[k] : Vec3::Zero();
  }

  Vec3 displacement(const Vec3& p) const {
    const std::vector<Vec3>& c = corner_points.get();
    if (c.size() != 4 && c.size() != 8) return Vec3::Zero();
    const double alpha = std::abs(p[0] - c[0][0]) / std::abs(c[1][0] - c[0][0]);
    const double beta = std::abs(p[1] - c[0][1]) / std::abs(c[3][1] - c[0][1]);
    // SOFA's expression order, component by component: each corner's vector times its
    // first weight, then its second, the four terms summed left to right.
    auto face = [&](std::size_t o) {
      const Vec3 m0 = movement(o), m1 = movement(o + 1), m2 = movement(o + 2), m3 = movement(o + 3);
      Vec3 d;
      for (int k = 0; k < 3; ++k)
        d[k] = m0[k] * (1 - alpha) * (1 - beta) + m1[k] * alpha * (1 - beta) + m2[k] * alpha * beta +
               m3[k] * (1 - alpha) * beta;
      return d;
    };
    if (c.size() == 4) return face(0);
    const double gamma = std::abs(p[2] - c[0][2]) / std::abs(c[4][2] - c[0][2]);
    const Vec3 lo = face(0), hi = face(4);
    Vec3 d;
    for (int k = 0; k < 3; ++k) d[k] = lo[k] * (1 - gamma) + hi[k] * gamma;
    return d;
  }
};

}  // namespace

void register_patch_test_movement_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "PatchTestMovementProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "moves the border points of a box to the interpolation of given corner displacements";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = state_creator<PatchTestMovementProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
