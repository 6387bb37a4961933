// DifferenceEngine: output[i] = input[i] − substractor[i] for two vectors of
// the same size (SOFA's Engine/Transform); with sizes that differ it warns and
// leaves the output as it was. Templated on the value type (Vec1d, Vec3d).
#pragma once

#include "core/engine.h"

namespace sinew {

class DifferenceEngine final : public Engine {
 public:
  explicit DifferenceEngine(int width);

  Field<FlatVec> input;
  Field<FlatVec> substractor;
  Field<FlatVec> output;

  void init() override { set_dirty(); }
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
