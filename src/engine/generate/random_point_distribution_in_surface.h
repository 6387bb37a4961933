// RandomPointDistributionInSurface: random points inside a closed triangle
// surface (SOFA's Engine/Generate). Points are drawn uniformly in the
// surface's bounding box with SOFA's generator (math/rand48.h); a point is
// inside when every one of `numberOfTests` rays from it (random directions
// drawn once at init) first hits a triangle whose normal (p1−p0)×(p2−p0)
// points along the ray. Inside points closer than `minDistanceBetweenPoints`
// to one kept already are rejected; rejected points go to `outPoints`. It
// stops at `numberOfInPoints` points or after n⁴ draws (SOFA's safe limit,
// 32-bit). `randomSeed` 0 seeds from the clock, as SOFA: set it for
// reproducible points. Vec3d.
#pragma once

#include "core/engine.h"
#include "core/roles.h"
#include "math/rand48.h"

namespace sinew {

class RandomPointDistributionInSurface final : public Engine {
 public:
  RandomPointDistributionInSurface();

  Field<unsigned> random_seed{this, "randomSeed", 0u, "seed of the generator (0: from the clock)", "Inputs"};
  Field<bool> is_visible{this, "isVisible", true, "draw the inside points (viewer)", "Visualization"};
  Field<bool> draw_output_points{this, "drawOutputPoints", false, "draw the rejected points (viewer)",
                                 "Visualization"};
  Field<double> min_distance{this, "minDistanceBetweenPoints", 0.1,
                             "minimal distance between two inside points (-1: none)", "Inputs", "length"};
  Field<unsigned> number_of_in_points{this, "numberOfInPoints", 10u, "number of points to place inside", "Inputs"};
  Field<unsigned> number_of_tests{this, "numberOfTests", 5u, "rays cast per point (odd; an even count gets one more)",
                                  "Inputs"};
  Field<FlatVec> vertices;
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles of the closed surface", "Inputs"};
  Field<FlatVec> in_points;
  Field<FlatVec> out_points;

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;

 private:
  Rand48 rng_;
  std::vector<Vec3> directions_;
  std::uint32_t safe_limit_ = 0;
};

}  // namespace sinew
