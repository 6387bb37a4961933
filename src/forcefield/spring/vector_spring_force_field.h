// VectorSpringForceField (Vec3d): springs that pull the vector between two points
// towards a rest *vector* (not a rest length): f1 += ks·(x2 − x1 − r) + kd·(v2 − v1),
// f2 −= the same. Between object1 and object2 (both default to the node's state;
// state binding shared with SpringForceField). Used by SOFA's haptic scenes to tie a
// device proxy to a simulated instrument (spec/interaction.md §6.4).
//
// Default springs (bwd_init, SOFA's bwdInit): with useTopology and a topology, one per
// edge (e0, e1) with rest vector x0[e1] − x0[e0] (object1's rest positions); otherwise one
// spring (i, i) with a zero rest vector for every point of object1.
//
// Deliberate differences from SOFA (docs/haptics.md):
// * build_stiffness assembles the exact −ks blocks (SOFA assembles nothing);
// * potential_energy() is Σ ½·ks·|x2 − x1 − r|² (SOFA's getPotentialEnergy returns a
//   member it never accumulates: always 0);
// * `filename` (.xs3 spring files) is refused with an error: Sinew has no XSP reader yet.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class VectorSpringForceField : public ForceField {
 public:
  VectorSpringForceField();

  Link<MechanicalState> object1{this, "object1", "first state (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "second state (default: the node's)"};
  Field<double> stiffness{this, "stiffness", 1.0, "stiffness of the default springs", "Spring", "force/length"};
  Field<double> viscosity{this, "viscosity", 1.0, "damping of the default springs", "Spring",
                          "force·time/length"};
  Field<std::string> filename{this, "filename", "", "file (.xs3) with the springs (not supported yet)", "Spring"};
  Field<bool> use_topology{this, "useTopology", false, "one spring per edge of the topology", "Spring"};
  Link<MeshTopologyBase> topology{this, "topology", "topology giving the edges (default: the node's)"};
  // Output: 5 numbers per spring (ks kd rx ry rz). SOFA's Spring has no text reader, so a
  // value given in the scene is ignored (with a warning), as in SOFA.
  Field<std::vector<double>> springs{this, "springs", {}, "springs in use: ks kd rx ry rz each (output)", "Spring"};

  void init() override;
  void bwd_init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  bool is_interaction() const override { return true; }
  std::vector<MechanicalState*> states() const override;
  MechanicalState* single_state() const override { return s1_ && s1_ == s2_ ? s1_ : nullptr; }
  std::optional<double> potential_energy() const override { return energy_; }

  struct Spring {
    unsigned m1 = 0, m2 = 0;  // point of object1, point of object2
    double ks = 1, kd = 1;
    double rest[3] = {0, 0, 0};
  };
  const std::vector<Spring>& spring_list() const { return list_; }

  // Springs set by code rather than by the scene (the StickContactForceField
  // response rebuilds them at each detection): the states, then the springs,
  // then springs_set() once they are all added.
  void bind(MechanicalState& s1, MechanicalState& s2) { s1_ = &s1, s2_ = &s2; }
  void clear_springs(std::size_t reserve) {
    list_.clear();
    list_.reserve(reserve);
  }
  void add_spring(const Spring& s) { list_.push_back(s); }
  void springs_set();

 private:
  bool ready();  // state valid, springs made, sizes unchanged
  MechanicalState* s1_ = nullptr;
  MechanicalState* s2_ = nullptr;
  MeshTopologyBase* topo_ = nullptr;
  std::vector<Spring> list_;
  std::size_t n1_ = 0, n2_ = 0;
  double energy_ = 0;
};

}  // namespace sinew
