// NearestPointROI: pairs the points of two mechanical states (SOFA's
// Engine/Select). For each point i2 of object2 (in inputIndices2, all when
// empty), the nearest point i1 of object1 (among inputIndices1, all when
// empty; the first one on ties) is paired with it when their distance is
// below radius. Positions are the states' rest positions
// (useRestPosition, default) or current positions.
// Outputs per pair: indices1, indices2, an edge (2·i2, 2·i2+1), four
// indexPairs entries (0 i1 1 i2, SubsetMultiMapping's format) and the
// distance. Vec templates (Vec1d, Vec2d, Vec3d, Vec6d).
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class NearestPointROI final : public Engine {
 public:
  NearestPointROI();

  Link<MechanicalState> object1{this, "object1", "first state (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "second state (default: the node's)"};
  Field<std::vector<unsigned>> input_indices1{this, "inputIndices1", {}, "points of object1 to consider (all when empty)",
                                              "Inputs"};
  Field<std::vector<unsigned>> input_indices2{this, "inputIndices2", {}, "points of object2 to consider (all when empty)",
                                              "Inputs"};
  Field<double> radius{this, "radius", 1.0, "largest distance of a pair", "Inputs", "length"};
  Field<bool> use_rest_position{this, "useRestPosition", true, "pair the rest positions (else the current ones)",
                                "Inputs"};
  Field<std::vector<unsigned>> indices1{this, "indices1", {}, "object1's point of each pair", "Outputs"};
  Field<std::vector<unsigned>> indices2{this, "indices2", {}, "object2's point of each pair", "Outputs"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "(2·i2, 2·i2+1) per pair", "Outputs"};
  Field<std::vector<unsigned>> index_pairs{this, "indexPairs", {}, "0 i1 1 i2 per pair (parent, index in parent)",
                                           "Outputs"};
  Field<std::vector<double>> distances{this, "distances", {}, "distance of each pair", "Outputs", "length"};
  Field<bool> draw_pairs{this, "drawPairs", false, "draw the pairs (viewer)", "Visualization"};

  void init() override;
  void reinit() override;

 protected:
  void do_update() override;

 private:
  BaseField* x1_ = nullptr;
  BaseField* x2_ = nullptr;
};

}  // namespace sinew
