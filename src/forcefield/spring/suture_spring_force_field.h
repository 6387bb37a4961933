// SutureSpringForceField (Sinew's own; SOFA has no counterpart): the thread a
// suture needle draws through a soft body (the skin-suture trainer, issue 16).
//
// It acts on the body's Vec3d state and watches a needle given by two points of
// another Vec3d state (`needle`, usually mapped from the needle's rigid frame):
// * the front point (`frontIndex`) pierces: at the end of every step each body
//   vertex within `captureDistance` of it is marked pierced;
// * the back point (`backIndex`) draws the thread: at the end of a step where it
//   lies within `captureDistance` of pierced vertices not linked yet, the closest
//   of them is linked to it by a spring (one per step, at most `maxSprings`).
// A spring is a thread, not a rod: its rest length is the distance at creation
// (so it starts without force: no jump in the force the device feels) and it
// pulls only when stretched beyond it, f = k·(l − L)·u on the vertex (u towards
// the back point), never pushes. Only the body feels it: the needle is held by
// its device coupling and the thread's pull on the needle is not modelled.
//
// `springs` (vertex, rest length pairs) is both the output and an input (a
// scene may start with springs). Point removals of the body's topology are
// followed (a spring on a removed vertex goes; the renumbered one follows).
#pragma once

#include <vector>

#include "core/roles.h"
#include "core/topology_change.h"

namespace sinew {

class SutureSpringForceField : public ForceField {
 public:
  Link<MechanicalState> needle{this, "needle", "state holding the needle's front and back points (Vec3d)"};
  Field<int> front_index{this, "frontIndex", 0, "index of the piercing point in the needle state", "Suture"};
  Field<int> back_index{this, "backIndex", 1, "index of the point that draws the thread", "Suture"};
  Field<double> capture_distance{this, "captureDistance", 0.5,
                                 "distance within which the front pierces a vertex and the back links it", "Suture",
                                 "length"};
  Field<double> stiffness{this, "stiffness", 10.0, "stiffness of a thread spring", "Suture", "force/length"};
  Field<int> max_springs{this, "maxSprings", 0, "most springs created (0: no limit)", "Suture"};
  Field<std::vector<double>> springs{this, "springs", {}, "springs: body vertex, rest length (input and output)",
                                     "Suture"};
  Field<int> pierced_count{this, "piercedCount", 0, "vertices pierced so far (output)", "Suture"};

  SutureSpringForceField();
  void init() override;
  void bwd_init() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  std::optional<double> potential_energy() const override;

  struct Spring {
    unsigned vertex = 0;
    double rest = 0;
  };
  const std::vector<Spring>& spring_list() const { return list_; }

 private:
  bool ready() const;
  Vec3 needle_point(int index) const;
  void update_springs();  // end of a step: pierce, then link
  void publish();         // springs Data from list_

  struct Follow final : TopologyHandler {
    SutureSpringForceField* owner = nullptr;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;
  };
  Follow follow_;
  std::vector<Spring> list_;
  std::vector<char> pierced_, linked_;  // per body vertex
};

}  // namespace sinew
