// NormEngine: the l-norm of each 3d vector of `input` (SOFA's Engine/Generate):
// normType 2 Euclidean, 1 sum of magnitudes, 0 count of non-zero components,
// negative the largest magnitude, other l (Σ|xᵢ|ˡ)^(1/l).
#pragma once

#include "core/engine.h"

namespace sinew {

class NormEngine final : public Engine {
 public:
  NormEngine();

  Field<FlatVec> input;
  Field<std::vector<double>> output{this, "output", {}, "norm of each input vector", "Outputs"};
  Field<int> norm_type{this, "normType", 2, "the norm: l ≥ 0, or negative for the infinity norm", "Inputs"};

  void init() override { set_dirty(); }
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
