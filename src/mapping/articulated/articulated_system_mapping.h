// ArticulatedSystemMapping (SOFA's ArticulatedSystemPlugin, template
// Vec1d,Rigid3d,Rigid3d): the frames of an articulated rigid system from its
// joint coordinates.
//
// Inputs: `input1` the joint coordinates (Vec1d, one scalar per Articulation),
// `input2` (optional) the frame the system hangs from; output: the frames
// (Rigid3d). Frame 0 copies input2's frame `indexInput2` (default its last).
// Each ArticulationCenter of the ArticulatedHierarchyContainer (link
// `container`, else the first found below input1's node), in order, places its
// child frame from its parent frame (articulated_hierarchy.h):
//   process 0: the child starts as the parent turned into place at the joint;
//     then each articulation in order, its axis turned by the child's current
//     orientation, rotates the child about the joint by its coordinate, or
//     moves it along the axis;
//   process 1: axes turned by the parent; the rotations and displacements are
//     accumulated by increments since the previous apply;
//   process 2: as 1 with axes turned by the child's previous orientation, the
//     displacement applied after the rotation.
// Each apply records, per articulation, its world axis and joint position; the
// velocity map (J), its transpose and the constraint rows use them with the
// output's current positions:
//   v_child = v_parent + ω_parent × (P − C) + Σ_a [axis_a·q̇_a × (A_a − C) | axis_a·q̇_a]
// The constraint rows walk each frame's chain of centres back to frame 0 (SOFA's
// getAcendantList) and put the rest on input2. No geometric stiffness (SOFA's
// applyDJT is empty). The assembled J (for direct solvers) is J column by column;
// SOFA gives none, so its direct solvers cannot run this mapping.
//
// Quirks kept from SOFA: init maps before the centres are known (only frame 0
// moves), so processes 1 and 2 take the initial coordinates as their zero;
// process 0 normalises the Articulation axes in place.
#pragma once

#include <vector>

#include "mapping/articulated/articulated_hierarchy.h"
#include "mapping/mapping_base.h"

namespace sinew {

class ArticulatedSystemMapping final : public Mapping {
 public:
  ArticulatedSystemMapping();

  StateLink input1;
  StateLink input2;
  StateLink output_link;
  Link<ArticulatedHierarchyContainer> container{this, "container",
                                                "the ArticulatedHierarchyContainer (default: found below input1)"};
  Field<unsigned> index_input2{this, "indexInput2", 0u,
                               "frame of input2 the system hangs from (default: the last)", "Mapping"};

  std::vector<MechanicalState*> inputs() const override;
  MechanicalState* output() const override { return out_; }

  void init() override;
  void bwd_init() override;
  void reset() override;
  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool apply_jt_constraints() override;

 private:
  bool resolve_links();
  // The centres to map with (none before bwd_init); checks their indices against
  // the states' sizes, with one error when they do not fit (then nothing is mapped).
  const std::vector<ArticulationCenter*>* checked_centers(std::size_t coords, std::size_t frames);

  MechanicalState* in_ = nullptr;    // input1, Vec1d
  MechanicalState* root_ = nullptr;  // input2, Rigid3d (optional)
  MechanicalState* out_ = nullptr;   // Rigid3d
  std::size_t root_index_ = 0;
  bool have_centers_ = false;        // set by bwd_init (SOFA fills its list there)
  std::vector<double> axis_;         // per coordinate: world axis at the last apply (SOFA's ArticulationAxis)
  std::vector<double> pos_;          // per coordinate: joint position at the last apply (ArticulationPos)
  std::vector<double> previous_;     // coordinates of the last apply (CoordinateBuf)
  std::vector<double> frame_force_;  // apply_jt scratch: output forces carried down the chain
  std::vector<ArticulationCenter*> chain_;  // apply_jt_constraints scratch
  std::vector<double> jac_;          // jacobian scratch: dense rows × columns
  std::vector<char> used_;           // jacobian scratch: columns each frame depends on
  bool warned_fit_ = false;
};

}  // namespace sinew
