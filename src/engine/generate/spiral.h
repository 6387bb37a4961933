// Spiral: rolls a straight strip into an Archimedean spiral (SOFA's
// Engine/Generate). Each rest point's x is read as an arc length l along the
// spiral r = A·t (A = curvature); t solves l = A/2 (t√(1+t²) + asinh t) by ten
// Newton steps from √|l|; the point goes to (r cos t, r sin t, z) with
// r = ±A·t (the sign of x), shifted by y along the curve's normal, whose
// y component is capped at 0.8 for −π/2 < t < π/2, as SOFA does.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class Spiral final : public Engine {
 public:
  Spiral();

  Field<std::vector<Vec3>> rest_position{this, "rest_position", {}, "points of the straight strip", "Inputs",
                                         "length"};
  Field<std::vector<Vec3>> position{this, "position", {}, "points rolled into the spiral", "Outputs", "length"};
  Field<double> curvature{this, "curvature", 0.2, "A in r = A·t", "Inputs", "length"};

  void init() override { set_dirty(); }
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
