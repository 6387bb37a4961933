// TrailRenderer (SOFA's Sofa.Component.Visual): the path of each point over its last `nbSteps`
// steps (positions stored at each AnimateEndEvent, cleared by a reset), drawn unlit by
// src/render as line strips coloured along the trail through the colour map `color`
// (evaluated at the sample's index over [0, nbSteps]). Templates Vec3d and Rigid3d (centres).
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class TrailRenderer final : public VisualComponent {
 public:
  explicit TrailRenderer(const std::string& tmpl);

  Field<FlatVec> position;
  Field<unsigned> nb_steps{this, "nbSteps", 100u, "number of steps kept in the trail", "Visualization"};
  Field<std::string> color{this, "color", "0 1 0 1", "colour map of the trail: a scheme (HSV, ...) or colours",
                           "Visualization"};
  Field<double> thickness{this, "thickness", 1.0, "thickness of the trail (pixels)", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void reset() override { trail_.clear(); }
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override;
  // Per point, its stored centres from the oldest to the newest.
  const std::vector<std::deque<Vec3>>& trail() const { return trail_; }

 private:
  std::vector<std::deque<Vec3>> trail_;
};

}  // namespace sinew
