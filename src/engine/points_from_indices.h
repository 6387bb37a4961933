// PointsFromIndices: the coordinates of the points whose indices are given
// (SOFA's Engine/Select). A point whose coordinates are already in the output
// is not repeated, as SOFA. Without `position`, the positions of the
// mechanical state of the context are used.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class PointsFromIndices final : public Engine {
 public:
  PointsFromIndices();

  Field<FlatVec> position;
  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the points", "Inputs"};
  Field<FlatVec> indices_position;

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
