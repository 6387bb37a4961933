// CollisionModelBase: what every collision model holds (spec/interaction.md
// §3.1–3.2): the Data SOFA gives them, the bounding tree above its elements,
// and the model-level and element-level filters.
//
// A model's elements (points, edges, triangles, spheres) index into the
// positions of the MechanicalState of its node. The concrete models
// (collision/model/) know how to bound and read their elements; the narrow
// phase reads them through the Kind, with no virtual call per element.
#pragma once

#include <cmath>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include "collision/cube_tree.h"
#include "core/roles.h"

namespace sinew {

class CollisionModelBase : public CollisionModel {
 public:
  enum class Kind { point, line, triangle, sphere, tetrahedron, obb };
  static constexpr int kKinds = 6;

  explicit CollisionModelBase(Kind kind);

  Field<bool> active{this, "active", true, "excluded from collision detection when false", "Collision"};
  Field<bool> moving{this, "moving", true, "false: bounding boxes computed once (a fixed obstacle)", "Collision"};
  Field<bool> simulated{this, "simulated", true,
                        "false: an obstacle that no contact moves; pairs of two obstacles are skipped", "Collision"};
  Field<bool> self_collision{this, "selfCollision", false, "collide with the models of the same node", "Collision"};
  Field<double> contact_distance{
      this,        "contactDistance", 0.0, "skin added to the alarm and contact distances of the pairs of this model",
      "Collision", "length"};
  Field<double> contact_stiffness{this, "contactStiffness", 10.0, "penalty stiffness factor of this model's contacts",
                                  "Collision"};
  Field<double> contact_friction{this, "contactFriction", 0.0, "friction factor (summed into the penalty mu, unused)",
                                 "Collision"};
  Field<double> contact_restitution{this, "contactRestitution", 0.0, "restitution factor (unused)", "Collision"};
  Field<std::string> contact_response{
      this, "contactResponse", "", "response for this model's contacts, overriding the contact manager's", "Collision"};
  Field<std::vector<int>> group{this, "group", {}, "models sharing a group id never collide", "Collision"};
  Field<std::string> color{this, "color", "1 0 0 1", "colour (viewer)", "Visualization"};
  Field<int> number_of_contacts{this, "numberOfContacts", 0, "output: number of contacts touching this model",
                                "Collision"};

  Kind kind() const { return kind_; }
  // Number of elements (after the last update()).
  virtual std::size_t size() const = 0;
  bool empty() const { return size() == 0; }
  // The state the elements index into (positions read at detection).
  MechanicalState* mstate() const { return mstate_; }

  bool is_active() const;
  // Brings the elements up to date (state size, topology) and computes the
  // bounding tree of `depth` split levels (refit only when nothing changed).
  virtual void compute_bounding_tree(int depth) = 0;
  const CubeTree& tree() const { return tree_; }

  // Continuous detection (CCD, spec/interaction.md §2.8): the end positions of
  // this step's motion are computed first (Inertia: x + v·dt; FreeMotion: the
  // free positions), and each element's box then bounds its start and end.
  enum class Motion { none, inertia, free_motion };
  void compute_continuous_bounding_tree(double dt, Motion motion, int depth);
  // End positions of the last continuous detection (empty otherwise), indexed like the state.
  std::span<const Vec3> end_positions() const { return x_end_; }
  void clear_end_positions() { x_end_.clear(); }

  // Builds what element tests would otherwise build on first use (topology
  // neighbourhoods; with `neighbourhoods`, LocalMinDistance's views), so that
  // several tasks can test this model's elements at once.
  virtual void prepare_for_sharing(bool neighbourhoods) const {}

  // Model-level filter (§3.2), checked both ways by the broad phase.
  bool can_collide_with(const CollisionModelBase& other) const;
  // Element-level filter for pairs of models of the same node (self collision).
  virtual bool element_can_collide(unsigned /*i*/, const CollisionModelBase& /*other*/, unsigned /*j*/) const {
    return true;
  }

  void init() override;
  // A warning given once per model (bad elements are reported once, then skipped silently).
  void warn_once(const std::string& text) const {
    if (warned_) return;
    warned_ = true;
    msg_warning(text);
  }

 protected:
  // Finds the node's state (Vec3d required) and the topology; false after msg_error.
  virtual bool init_model() = 0;
  // Continuous detection: widens `box` by the end positions of vertices `vs`, padded by `pad`.
  void widen_to_end(Aabb& box, std::initializer_list<unsigned> vs, double pad) const {
    if (x_end_.empty()) return;
    for (unsigned v : vs) {
      box.min = box.min.cwiseMin(x_end_[v] - Vec3::Constant(pad));
      box.max = box.max.cwiseMax(x_end_[v] + Vec3::Constant(pad));
    }
  }
  // Whether the model also works on a Rigid3d state (its elements are then the frames' centres).
  virtual bool accepts_rigid3() const { return false; }
  // Whether the model works on a Vec3d state (all but the oriented boxes).
  virtual bool accepts_vec3() const { return true; }
  // Positions of the state's points, read at every detection: the state itself
  // for Vec3d, the frames' centres (copied) for Rigid3d.
  std::span<const Vec3> positions() const { return points_of(kPosition, kPosition); }
  // Points of vector `vec` (role kPosition: coordinates; kVelocity: linear velocities).
  std::span<const Vec3> points_of(int vec, int role) const;

  CubeTree tree_;
  MechanicalState* mstate_ = nullptr;
  std::vector<Vec3> x_end_;

 private:
  mutable std::vector<Vec3> gathered_[3];  // Rigid3d: centres, free centres, linear velocities (points_of)
  Kind kind_;
  mutable bool warned_ = false;
};

const char* kind_name(CollisionModelBase::Kind k);

}  // namespace sinew
