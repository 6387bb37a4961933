// Shift-drag grabs a body (SOFA's AttachBodyPerformer, spec/user-interfaces.md §3.6).
//
// start(): a picked collision element gets SOFA's "AttachedPoint", a point mapped into the
// element at the picked position (the contact mappers of the collision responses: barycentric
// on lines, triangles and tetrahedra, rigid on Rigid3d spheres); a picked particle is used as
// it is. A spring of zero rest length ("Spring-Mouse-Contact", no damping, the setting's
// stiffness) then pulls that point towards the mouse, a point on the cursor's ray at the
// picked depth that the solver does not move. stop() removes the spring and the mapped point.
//
// The graph changes only between steps: the viewer steps and draws on one thread.
#pragma once

#include <memory>
#include <string>

#include "core/roles.h"
#include "viewer/picking.h"

namespace sinew {
class ContactMapper;
}

namespace sinew::viewer {

// f = k (target − x_i) on point i of a Vec3d state; K = −k I (SOFA's spring of rest length 0).
class MouseSpring final : public ForceField {
 public:
  MouseSpring(MechanicalState& state, unsigned index, double stiffness);
  void set_target(const Vec3& t) { target_ = t; }
  const Vec3& target() const { return target_; }
  unsigned index() const { return index_; }
  double stiffness() const { return k_; }

  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  std::optional<double> potential_energy() const override;

 private:
  unsigned index_;
  double k_;
  Vec3 target_ = Vec3::Zero();
};

class MouseAttach {
 public:
  MouseAttach();
  ~MouseAttach();

  // Attaches a spring of `stiffness` at what `p` picked. False (with *why) when it cannot.
  bool start(const Pick& p, double stiffness, std::string* why);
  // Where the mouse now is: the spring's fixed end.
  void move(const Vec3& target);
  void stop();
  bool active() const { return spring_ != nullptr; }
  // The attached point, as the solver last left it.
  Vec3 attached_point() const;
  Vec3 target() const;

 private:
  std::unique_ptr<ContactMapper> mapper_;
  MouseSpring* spring_ = nullptr;  // owned by the graph while attached
  MechanicalState* state_ = nullptr;
};

}  // namespace sinew::viewer
