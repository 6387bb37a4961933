// IndexValueMapper: a per-index value list: `inputValues` copied, then
// `value` written at each of `indices`, the list grown with `defaultValue`
// when an index lies beyond its end (SOFA's Engine/Transform; e.g. per-element
// Young's moduli for TetrahedronFEMForceField).
#pragma once

#include "core/engine.h"

namespace sinew {

class IndexValueMapper final : public Engine {
 public:
  IndexValueMapper();

  Field<std::vector<double>> input_values{this, "inputValues", {}, "existing values (may be empty)", "Inputs"};
  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices where `value` is written", "Inputs"};
  Field<double> value{this, "value", 0.0, "value written at the indices", "Inputs"};
  Field<std::vector<double>> output_values{this, "outputValues", {}, "the values per index", "Outputs"};
  Field<double> default_value{this, "defaultValue", 1.0, "value of the indices that receive none",
                              "Parameters"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
