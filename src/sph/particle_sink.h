// ParticleSink (SofaSphFluid): removes the particles that crossed a plane.
// At the beginning of each step every particle with x·normal < d1 is removed
// (in decreasing index order: through the PointSetTopologyModifier of the
// topology when there is one, so that every per-point datum follows; else
// directly from the state, last DoF moved into each freed slot). As a
// projective constraint it stops the particles below x·normal = d0: their
// indices are gathered when positions are projected, and their velocity is
// set to zero right after.
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class PointSetTopologyModifier;

class ParticleSink final : public ProjectiveConstraint {
 public:
  Field<Vec3> normal{this, "normal", Vec3(0, 1, 0), "plane normal", "Sink"};
  Field<double> d0{this, "d0", 0.0, "plane offset below which particles are stopped", "Sink", "length"};
  Field<double> d1{this, "d1", 0.0, "plane offset below which particles are removed", "Sink", "length"};
  Field<bool> show_plane{this, "showPlane", false, "draw the plane (viewer)", "Visualization"};
  Field<std::vector<unsigned>> fixed{this, "fixed", {}, "indices of the stopped particles", "Sink"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the particles belong to (default: the node's)"};

  ParticleSink() { listening.set(true); }

  void init() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }
  void project_response(int) override {}
  void project_velocity(int v, double t) override;
  void project_position(int x, double t) override;
  void project_jacobian(ConstraintMatrix&) override {}

  // Particles removed so far (tests, reports).
  std::size_t removed() const { return removed_; }

 private:
  PointSetTopologyModifier* modifier_ = nullptr;  // in the topology's node; dies with the graph
  std::vector<unsigned> remove_;
  std::size_t removed_ = 0;
  struct Follow final : TopologyHandler {
    ParticleSink* owner = nullptr;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;
  } follow_;
};

}  // namespace sinew
