// MergeVectors (SOFA's Engine/Generate): concatenates `nbInputs` vectors
// `input1..N` into `output`, in input order.
#pragma once

#include "core/engine.h"
#include "engine/numbered_fields.h"

namespace sinew {

template <class T>
class MergeVectors final : public Engine {
 public:
  MergeVectors();

  Field<unsigned> nb_inputs{this, "nbInputs", 2, "number of input vectors", "Inputs"};
  NumberedFields<T> inputs{"input", "input vector "};
  Field<T> output{this, "output", {}, "the input vectors one after the other", "Outputs"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
