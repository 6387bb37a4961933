// MergePoints: two coordinate vectors merged (SOFA's Engine/Generate). By
// default position2 is appended to position1; with `mappingX2`, point i of
// position2 replaces point mappingX2[i] of position1 (injection). indices1 and
// indices2 say where each input's points are in the result.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class MergePoints final : public Engine {
 public:
  explicit MergePoints(StateType type);

  Field<FlatVec> position1;
  Field<FlatVec> position2;
  Field<std::vector<unsigned>> mapping_x2{this, "mappingX2", {},
                                          "where each point of position2 goes in position1 (injection)", "Inputs"};
  Field<std::vector<unsigned>> indices1{this, "indices1", {}, "indices of the points of the first object",
                                        "Outputs"};
  Field<std::vector<unsigned>> indices2{this, "indices2", {}, "indices of the points of the second object",
                                        "Outputs"};
  Field<FlatVec> points;
  Field<bool> no_update{this, "noUpdate", false, "compute the output once only", "Parameters"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;

 private:
  bool done_ = false;
};

}  // namespace sinew
