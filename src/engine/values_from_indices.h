// ValuesFromIndices: the values of `in` at the given indices, in the order of
// the indices, repeats kept (SOFA's Engine/Select). Templated on the value
// type; values are held flat, `width` scalars each.
#pragma once

#include "core/engine.h"

namespace sinew {

class ValuesFromIndices final : public Engine {
 public:
  explicit ValuesFromIndices(int width);

  Field<FlatVec> in;
  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the values", "Inputs"};
  Field<FlatVec> out;
  Field<std::string> out_str{this, "outStr", "", "the output values as text", "Outputs"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
