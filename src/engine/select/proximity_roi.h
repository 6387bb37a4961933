// ProximityROI: the N points nearest to a set of spheres' centres (SOFA's
// Engine/Select). A point's distance is the smallest distance to a centre
// whose sphere contains it; points in no sphere go to indicesOut. The N
// nearest are kept in a max-heap as SOFA does (std::push_heap/pop_heap), and
// the outputs list them in heap order. SOFA's quirk is kept: when a farther
// point is evicted, indicesOut receives the index at the heap's top after the
// eviction, not the evicted one. Missing radii repeat the last one (written
// back to radii). N = 0 or no radius is an error when the engine runs.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class ProximityROI final : public Engine {
 public:
  ProximityROI();

  Field<std::vector<Vec3>> centers{this, "centers", {}, "centres of the spheres", "Inputs", "length"};
  Field<std::vector<double>> radii{this, "radii", {}, "radii of the spheres", "Inputs", "length"};
  Field<unsigned> n{this, "N", 0, "largest number of points selected", "Inputs"};
  Field<std::vector<Vec3>> position{this, "position", {},
                                    "rest positions (default: the state's rest_position, else a mesh loader's)",
                                    "Inputs", "length"};
  Field<std::vector<unsigned>> indices{this, "indices", {0}, "indices of the points selected", "Outputs"};
  Field<std::vector<Vec3>> points_in_roi{this, "pointsInROI", {}, "points selected", "Outputs", "length"};
  Field<std::vector<double>> distance{this, "distance", {}, "distance of each selected point to its centre", "Outputs",
                                      "length"};
  Field<std::vector<unsigned>> indices_out{this, "indicesOut", {}, "indices of the points not selected", "Outputs"};
  Field<bool> draw_sphere{this, "drawSphere", false, "draw the spheres (viewer)", "Visualization"};
  Field<bool> draw_points{this, "drawPoints", false, "draw the selected points (viewer)", "Visualization"};
  Field<double> draw_size{this, "drawSize", 0.0, "size of the drawn points (viewer)", "Visualization"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
