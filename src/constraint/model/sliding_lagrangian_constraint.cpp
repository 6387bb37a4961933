// SlidingLagrangianConstraint (spec/interaction.md §5.6): point P
// (sliding_point of object1) stays on segment AB (axis_1, axis_2 of object2).
//
// Directions are computed from the current positions when the rows are built:
// along AB (dirAxe), from the projection of P on line AB to P (dirProj; any
// normal of AB when P is on the line) and dirProj × dirAxe. Rows:
//   0, 1  bilateral along dirProj and dirOrtho: +dir on P, −dir·(1−b) on A and
//         −dir·b on B, b the barycentric coordinate of P's projection clamped
//         to [0, 1];
//   2     unilateral +dirAxe on P, −dirAxe on A (P does not pass A);
//   3     unilateral −dirAxe on P, +dirAxe on B (P does not pass B).
// When A and B coincide: three bilateral rows e_x, e_y, e_z tying P to A.
// Violations at the free positions with the directions and b of the build.
// `force` receives Σ direction·λ after each solve.
#include "constraint/model/sliding_lagrangian_constraint.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Geometry>

#include "constraint/model/constraint_states.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {

// Component-ordered products, as SOFA's Vec computes them.
double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm3(const Vec3& a) { return std::sqrt(dot3(a, a)); }
Vec3 normalized3(const Vec3& a) {
  const double n = norm3(a);
  return n > std::numeric_limits<double>::epsilon() ? Vec3(a[0] / n, a[1] / n, a[2] / n) : a;
}

class SlidingLagrangianConstraint final : public LagrangianConstraint {
 public:
  Link<MechanicalState> object1{this, "object1", "state holding the sliding point (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "state holding the axis ends (default: the node's)"};
  Field<int> sliding_point{this, "sliding_point", 0, "index of the sliding point on object1", "Constraint"};
  Field<int> axis_1{this, "axis_1", 0, "index of one end of the sliding axis on object2", "Constraint"};
  Field<int> axis_2{this, "axis_2", 0, "index of the other end of the sliding axis on object2", "Constraint"};
  Field<Vec3> force{this, "force", Vec3::Zero(), "force (impulse) of the last solve (output)", "Constraint"};

  void init() override { resolve_pair_states(*this, object1, object2, StateType::vec3); }

  void bwd_init() override {
    if (state() != ComponentState::valid) return;
    auto bad = [&](const Field<int>& f, const MechanicalState& s) {
      if (f.value() >= 0 && static_cast<std::size_t>(f.value()) < s.size()) return false;
      msg_error(f.name() + " " + std::to_string(f.value()) + " is out of range: " + s.describe() + " has " +
                std::to_string(s.size()) + " points");
      set_state(ComponentState::invalid);
      return true;
    };
    if (!bad(sliding_point, *object1) && !bad(axis_1, *object2)) bad(axis_2, *object2);
  }

  void build_constraint_matrix(const ConstraintParams&, int& row) override {
    constraint_index.set(static_cast<unsigned>(row));
    first_ = row;
    const int m1 = sliding_point.value(), ma = axis_1.value(), mb = axis_2.value();
    const auto x1 = as_vec3(object1->read(kPosition));
    const auto x2 = as_vec3(object2->read(kPosition));
    const Vec3 P = x1[m1], A = x2[ma], B = x2[mb];
    ConstraintMatrix& c1 = object1->constraint_jacobian();
    ConstraintMatrix& c2 = object2->constraint_jacobian();

    Vec3 axis = B - A;
    const double ab = norm3(axis);
    bary_ = 0;
    if (ab < std::numeric_limits<double>::epsilon()) {
      // A = B: P is tied to A in every direction.
      ndirs_ = 3;
      for (int k = 0; k < 3; ++k) {
        dirs_[k] = Vec3::Unit(k);
        c1.add(row, m1, dirs_[k].data());
        const Vec3 m = -dirs_[k];
        c2.add(row, ma, m.data());
        ++row;
      }
      return;
    }
    axis = normalized3(axis);
    const double r = dot3(P - A, axis);
    bary_ = std::clamp(r / ab, 0.0, 1.0);
    const Vec3 proj = A + axis * r;
    Vec3 dir_proj = P - proj;
    if (norm3(dir_proj) < std::numeric_limits<double>::epsilon()) {
      // P on the line: any normal of the axis will do.
      Vec3 xv(1, 0, 0);
      if (norm3(xv.cross(axis)) < std::numeric_limits<double>::epsilon()) xv[1] = 1;
      dir_proj = xv.cross(axis);
    }
    dir_proj = normalized3(dir_proj);
    const Vec3 dir_ortho = normalized3(dir_proj.cross(axis));
    ndirs_ = 4;
    dirs_[0] = dir_proj;
    dirs_[1] = dir_ortho;
    dirs_[2] = axis;
    dirs_[3] = -axis;
    for (int i = 0; i < 2; ++i) {
      c1.add(row, m1, dirs_[i].data());
      const Vec3 on_a = -dirs_[i] * (1 - bary_);
      const Vec3 on_b = -dirs_[i] * bary_;
      c2.add(row, ma, on_a.data());
      c2.add(row, mb, on_b.data());
      ++row;
    }
    const Vec3 m2 = -dirs_[2], m3 = -dirs_[3];
    c1.add(row, m1, dirs_[2].data());
    c2.add(row, ma, m2.data());
    c1.add(row + 1, m1, dirs_[3].data());
    c2.add(row + 1, mb, m3.data());
    row += 2;
  }

  void constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) override {
    const auto x1 = as_vec3(step_vec(*object1, p.x, kPosition));
    const auto x2 = as_vec3(step_vec(*object2, p.x, kPosition));
    const Vec3 P = x1[sliding_point.value()], A = x2[axis_1.value()], B = x2[axis_2.value()];
    if (ndirs_ == 3) {
      const Vec3 d = P - A;
      for (int k = 0; k < 3; ++k) dfree[first_ + k] = d[k];
      return;
    }
    Vec3 proj;
    for (int k = 0; k < 3; ++k) proj[k] = B[k] * bary_ + A[k] * (1 - bary_);
    const Vec3 to_proj = P - proj;
    dfree[first_] = dot3(to_proj, dirs_[0]);
    dfree[first_ + 1] = dot3(to_proj, dirs_[1]);
    dfree[first_ + 2] = dot3(P - A, dirs_[2]);
    dfree[first_ + 3] = dot3(P - B, dirs_[3]);
  }

  void constraint_resolutions(const ConstraintParams&, std::vector<ConstraintBlock>& out) override {
    for (int i = 0; i < ndirs_; ++i) {
      ConstraintBlock b;
      b.kind = ndirs_ == 4 && i >= 2 ? ConstraintBlock::Kind::unilateral : ConstraintBlock::Kind::bilateral;
      b.first = first_ + i;
      b.notify = this;
      out.push_back(b);
    }
  }

  void store_lambda(int first, const double* f, int rows) override {
    for (int r = 0; r < rows; ++r) {
      const int i = first + r - first_;
      if (i == 0) sum_ = Vec3::Zero();
      sum_ += dirs_[i] * f[r];
      if (i == ndirs_ - 1) force.set(sum_);
    }
  }

  // SOFA's draw: yellow when the last build had three directions.
  bool tied() const { return ndirs_ == 3; }

 private:
  int first_ = 0;
  int ndirs_ = 0;
  double bary_ = 0;  // where P's projection sits on AB, in [0, 1]
  Vec3 dirs_[4];
  Vec3 sum_ = Vec3::Zero();
};

}  // namespace

bool sliding_picture(const Component& c, SlidingPicture& out) {
  const auto* s = dynamic_cast<const SlidingLagrangianConstraint*>(&c);
  if (!s || s->state() != ComponentState::valid || !s->object1.get() || !s->object2.get()) return false;
  const auto x1 = as_vec3(s->object1->read(kPosition));
  const auto x2 = as_vec3(s->object2->read(kPosition));
  const auto in = [](int i, std::size_t n) { return i >= 0 && static_cast<std::size_t>(i) < n; };
  const int m1 = s->sliding_point.value(), ma = s->axis_1.value(), mb = s->axis_2.value();
  if (!in(m1, x1.size()) || !in(ma, x2.size()) || !in(mb, x2.size())) return false;
  out.point = x1[m1], out.a = x2[ma], out.b = x2[mb];
  out.tied = s->tied();
  return true;
}

void register_sliding_lagrangian_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "SlidingLagrangianConstraint";
  info.category = "Constraint/Lagrangian/Model";
  info.description = "keeps a point of one state on a segment between two points of another (Lagrangian rows)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = creator<SlidingLagrangianConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
