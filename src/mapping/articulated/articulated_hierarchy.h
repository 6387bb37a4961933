// The articulated-system description of SOFA's ArticulatedSystemPlugin: plain
// data components read by ArticulatedSystemMapping.
//
// - Articulation: one joint coordinate, the scalar `articulationIndex` of the
//   mapping's Vec1d input, moving along or about `axis` (alias rotationAxis).
// - ArticulationCenter: a joint between two frames of the mapping's Rigid3d
//   output (parentIndex → childIndex), at posOnParent in the parent's frame and
//   posOnChild in the child's. Its articulations are those found below the
//   child nodes of the centre's node (not in its own node), in graph order.
//   articulationProcess says how they compose (articulated_system_mapping.h).
// - ArticulatedHierarchyContainer: every ArticulationCenter of its node's
//   subtree, in graph order (parents must come before their children there).
//   Gathered at init and again after the graph changes shape.
//
// SOFA's container can also build the hierarchy and its motion from a BVH file
// (`filename`); that mode is not supported here and is refused.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/component.h"
#include "math/quat.h"
#include "math/types.h"

namespace sinew {

class Articulation final : public Component {
 public:
  Articulation() { axis.add_alias("rotationAxis"); }

  Field<Vec3> axis{this, "axis", Vec3(1, 0, 0), "axis of the rotation or direction of the translation", "Articulation"};
  Field<bool> rotation{this, "rotation", false, "the coordinate is an angle about the axis (radians)", "Articulation"};
  Field<bool> translation{this, "translation", false, "the coordinate is a displacement along the axis",
                          "Articulation"};
  Field<int> articulation_index{this, "articulationIndex", 0, "index of the coordinate in the Vec1d input",
                                "Articulation"};
};

class ArticulationCenter final : public Component {
 public:
  Field<int> parent_index{this, "parentIndex", 0, "parent frame (index in the Rigid3d output)", "Articulation"};
  Field<int> child_index{this, "childIndex", 0, "child frame (index in the Rigid3d output)", "Articulation"};
  Field<Vec3> global_position{this, "globalPosition", Vec3::Zero(),
                              "world position of the joint (output, written by the mapping)", "Articulation"};
  Field<Vec3> pos_on_parent{this, "posOnParent", Vec3::Zero(), "joint position in the parent frame",
                            "Articulation"};
  Field<Vec3> pos_on_child{this, "posOnChild", Vec3::Zero(), "joint position in the child frame", "Articulation"};
  Field<int> articulation_process{
      this, "articulationProcess", 0,
      "0: articulations one after the other, each axis turned by the previous rotations (Euler angles); "
      "1: axes fixed on the parent, rotations by increments; 2: axes fixed on the child, rotations by increments",
      "Articulation"};

  // Filled by the container: the articulations below the centre's child nodes.
  std::vector<Articulation*> articulations;
  // Accumulated rotation and displacement of processes 1 and 2 (SOFA's
  // OrientationArticulationCenter, DisplacementArticulationCenter), reset by
  // the mapping's bwd_init.
  Quat orientation;
  Vec3 displacement = Vec3::Zero();
};

class ArticulatedHierarchyContainer final : public Component {
 public:
  Field<std::string> filename{this, "filename", "", "BVH file of the hierarchy and its motion (not supported)",
                              "Articulation"};

  void init() override;
  // The centres, gathered again when the graph changed shape since the last call.
  const std::vector<ArticulationCenter*>& centers();
  // The centres from the one whose child is `index` up to the root frame (index
  // 0), SOFA's getAcendantList. A frame on the way that is nobody's child ends
  // the list there, with an error (SOFA's); so does a loop.
  void ancestors(int index, std::vector<ArticulationCenter*>& out);

 private:
  void gather();
  std::vector<ArticulationCenter*> centers_;
  std::uint64_t gathered_version_ = 0;
  bool warned_ancestors_ = false;
};

}  // namespace sinew
