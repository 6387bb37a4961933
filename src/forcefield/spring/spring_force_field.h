// SpringForceField: linear springs between the points of two states
// (object1, object2; both default to the node's state). StiffSpringForceField
// is SOFA's old name for it (renamed-components table).
// Spec: mechanics.md §3.1; kernel in forcefield/spring_kernel.h.
//
// Also the base of the force fields that generate their springs at init
// (MeshSpringForceField, RegularGridSpringForceField, QuadBendingSprings):
// they fill `springs_` (and `grid_springs_`) before SpringForceField::init().
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"
#include "forcefield/spring/spring_kernel.h"

namespace sinew {

// The two states of an interaction force field: object1/object2, each defaulting
// to the node's state; `self.mstate` is set to the first when unset. False (with an
// error naming the component, and the component invalid) when one is missing or the
// two differ in type. Shared by SpringForceField and VectorSpringForceField.
bool bind_interaction_states(ForceField& self, Link<MechanicalState>& object1, Link<MechanicalState>& object2,
                             MechanicalState*& s1, MechanicalState*& s2);

// The vectors an interaction force field between states a and b reads and writes
// (the MechParams ids, falling back to the standard vectors on mapped states).
// Fetched in the order x1, v1, f1, x2, v2, f2 (as the force fields always did).
struct PairForceVectors {
  const double *x1, *v1;
  double* f1;
  const double *x2, *v2;
  double* f2;
};
PairForceVectors pair_force_vectors(MechanicalState& a, MechanicalState& b, const MechParams& p);
struct PairDforceVectors {
  const double* dx1;
  double* df1;
  const double* dx2;
  double* df2;
};
PairDforceVectors pair_dforce_vectors(MechanicalState& a, MechanicalState& b, const MechParams& p);

class SpringForceField : public ForceField {
 public:
  SpringForceField();

  Link<MechanicalState> object1{this, "object1", "first state (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "second state (default: the node's)"};
  Field<std::vector<double>> stiffness{this, "stiffness", {100.0}, "stiffness shared by all springs", "Spring", "force/length"};
  Field<std::vector<double>> damping{this, "damping", {5.0}, "damping shared by all springs", "Spring", "force·time/length"};
  Field<std::vector<double>> spring{this, "spring", {},
                                    "springs, 5 numbers each: index1 index2 stiffness damping restLength", "Spring"};
  Field<std::vector<unsigned>> springs_indices1{this, "springsIndices1", {}, "first extremity of each spring",
                                                "Spring"};
  Field<std::vector<unsigned>> springs_indices2{this, "springsIndices2", {}, "second extremity of each spring",
                                                "Spring"};
  Field<std::vector<double>> lengths{this, "lengths", {},
                                     "rest lengths (one per spring, or one for all; empty: 0)", "Spring"};
  Field<std::vector<int>> elongation_only{this, "elongationOnly", {0},
                                          "per spring: only resist elongation (one for all allowed)", "Spring"};
  Field<std::vector<int>> enabled{this, "enabled", {1}, "per spring: enabled (one for all allowed)", "Spring"};
  Field<std::string> file_springs{this, "filename", "", "file (.xs3) with the springs", "Spring"};
  Field<float> show_arrow_size{this, "showArrowSize", 0.01f, "arrow or cylinder size (viewer)", "Visualization"};
  Field<int> draw_mode{this, "drawMode", 0, "how springs are drawn: 0 line, 1 cylinder, 2 arrow", "Visualization"};

  void init() override;
  void bwd_init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool is_interaction() const override { return true; }
  std::vector<MechanicalState*> states() const override;
  MechanicalState* single_state() const override { return s1_ && s1_ == s2_ ? s1_ : nullptr; }
  bool build_stiffness(MatrixSink& K) override;

  // The springs in use after init (explicit list, then generated grid springs).
  const std::vector<springs::LinearSpring>& spring_list() const { return springs_; }
  const std::vector<springs::LinearSpring>& grid_springs() const { return grid_springs_; }
  // Replaces the spring list (SofaPython3's addSpring/removeSpring/clear): used from the
  // next force computation on, and written back into the per-spring Data (indices1,
  // indices2, lengths, stiffness, damping, elongationOnly, enabled; `spring` when it was
  // given) as SOFA's updateTopologyIndicesFromSprings does, so the Data show the springs
  // in use and a reinit keeps them. Returns why the list is refused (an end beyond its
  // state), "" when accepted.
  std::string set_springs(std::vector<springs::LinearSpring> list);
  // Σ ½·ks·(d − L0)² over the springs active in the last add_force (SOFA's addForce
  // sum; its getPotentialEnergy also counts disabled and slack elongation-only springs).
  std::optional<double> potential_energy() const override { return energy_; }

 protected:
  // Binds object1/object2 (default: the node's state); false (component
  // invalid) when a state is missing or not a Vec1/Vec2/Vec3 state.
  bool bind_states();
  // Springs generated by a subclass: when true, init() keeps springs_ as is.
  bool generated_ = false;
  std::vector<springs::LinearSpring> springs_;
  std::vector<springs::LinearSpring> grid_springs_;  // processed after springs_ (RegularGrid)
  MechanicalState* s1_ = nullptr;
  MechanicalState* s2_ = nullptr;
  int dim_ = 3;

 private:
  template <int N, int CS, int DS>  // dimension, coordinate and derivative strides
  void add_force_n(const MechParams& p);
  template <int N, int DS>
  void add_dforce_n(const MechParams& p, double kfactor);
  // False (component invalid, springs dropped) when a resized state no longer holds every spring end.
  bool sizes_ok();
  // Point removals of each state's topology (SOFA's springsIndices handlers, side 0 = object1):
  // springs using a removed point are erased (order kept), then the ones using the topology's
  // last point are renumbered to the slot (its swap-with-last).
  struct Follow final : TopologyHandler {
    SpringForceField* owner = nullptr;
    int side = 0;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;
  } follow_[2];
  std::vector<springs::Block> dfdx_;
  std::size_t n1_ = 0, n2_ = 0;
  double energy_ = 0;
};

}  // namespace sinew
