// ParticleSource (SofaSphFluid): emits a layer of particles, one per
// `center` (scaled, translated, offset by `radius`, or by a random fraction of
// it with `addNoise`), every `delay` seconds between `start` and `stop`, with
// initial velocity `velocity`. New particles are appended at the beginning of
// a step (AnimateBeginEvent): through the node's PointSetTopologyModifier when
// there is one (a points-added event: states, masses and other per-point data
// follow), else by resizing the state. As a projective constraint it then
// drives the two most recent layers along their initial motion (positions
// replayed from the emission point, velocity fixed, response zeroed) so that
// they leave the nozzle undisturbed.
//
// SOFA's quirks kept: a state holding a single DoF counts as empty (a
// MechanicalObject always starts with one), and the list of the recent
// particles follows point removals as a TopologySubsetIndices (with the
// positions list updated by swap-with-last).
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class ParticleSource final : public ProjectiveConstraint {
 public:
  Field<Vec3> translation{this, "translation", Vec3(0, 0, 0), "translation applied to the centres", "Source",
                          "length"};
  Field<double> scale{this, "scale", 1.0, "scale applied to the centres", "Source"};
  Field<std::vector<Vec3>> center{this, "center", {Vec3(0, 0, 0)}, "emission points, one particle each per layer",
                                  "Source", "length"};
  Field<Vec3> radius{this, "radius", Vec3(0, 0, 0), "offset (or noise amplitude) added to each emission point",
                     "Source", "length"};
  Field<Vec3> velocity{this, "velocity", Vec3(0, 0, 0), "initial velocity of the particles", "Source",
                       "length/time"};
  Field<double> delay{this, "delay", 0.01, "time between two layers", "Source", "time"};
  Field<double> start{this, "start", 0.0, "time of the first layer", "Source", "time"};
  Field<double> stop{this, "stop", 1e10, "time after which no layer is emitted", "Source", "time"};
  Field<bool> add_noise{this, "addNoise", true, "add a random fraction of `radius` (C rand()) instead of `radius`",
                        "Source"};
  Field<std::vector<unsigned>> last_particles{this, "lastparticles", {}, "indices of the particles still driven",
                                              "Source"};

  ParticleSource() { listening.set(true); }

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void reset() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }
  void project_response(int dx) override;
  void project_velocity(int v, double t) override;
  void project_position(int x, double t) override;
  void project_jacobian(ConstraintMatrix&) override {}

  // Particles emitted so far by this source (tests, reports).
  std::size_t emitted() const { return emitted_; }

 private:
  void animate_begin(double time);
  bool active_at(double time) const { return !(time < start.value() || time > stop.value()); }

  std::size_t number_ = 0;   // particles per layer
  double last_time_ = 0;     // emission time of the last layer
  double max_dist_ = 0;
  std::vector<Vec3> last_pos_;  // emission points of the driven particles (parallel to lastparticles)
  std::vector<Vec3> new_x_, new_v_;
  std::size_t emitted_ = 0;
  bool warned_growth_ = false;
  struct Follow final : TopologyHandler {
    ParticleSource* owner = nullptr;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;
  } follow_;
};

}  // namespace sinew
