// ContactMapper: where the contact points of one side of a contact live
// (spec/interaction.md §4.3).
// - Points and Vec3d spheres: the collision model's own state; a contact
//   point is the element's point itself (SOFA's identity mapper).
// - Rigid3d spheres and oriented boxes: a child node holding a Vec3d state
//   mapped from the frames by a RigidMapping, the point stored in its frame
//   (SOFA's RigidContactMapper).
// - Lines and triangles: a child node of the model's node holding a Vec3d
//   state mapped from the model's state by a ContactMapping, created on
//   first use and removed with the contact (SOFA's barycentric mapper).
#pragma once

#include <string>

#include "collision/collision_model.h"
#include "collision/response/contact_mapping.h"

namespace sinew {
class RigidMapping;
}

namespace sinew {

class ContactMapper {
 public:
  ContactMapper(CollisionModelBase& model, std::string name) : model_(&model), name_(std::move(name)) {}
  ~ContactMapper();
  ContactMapper(const ContactMapper&) = delete;
  ContactMapper& operator=(const ContactMapper&) = delete;

  // The state the contact points are indices of (created on first use for lines and triangles).
  MechanicalState* state();
  // Empties the contact points and sizes the mapped state for n of them.
  void resize(std::size_t n);
  // A contact point at P on element `elem`: its index in state(); r receives the sphere radius (else 0).
  unsigned add_point(const Vec3& P, unsigned elem, double& r);
  // Maps positions and velocities of the contact points from the model's state.
  void update();
  // Same for the free positions and velocities (constraint responses, SOFA's updateXfree).
  void update_xfree();
  // Removes the mapped child node (the contact is gone).
  void cleanup();

 private:
  bool identity() const;
  CollisionModelBase* model_;
  std::string name_;
  Node* child_ = nullptr;
  MechanicalState* mapped_ = nullptr;
  Mapping* map_ = nullptr;                   // the one below that exists
  ContactMapping* mapping_ = nullptr;        // lines, triangles, tetrahedra
  RigidMapping* rigid_mapping_ = nullptr;    // Rigid3d spheres, oriented boxes
};

}  // namespace sinew
