// SubsetMultiMapping: one output state gathering points of several input states.
// `indexPairs` lists (input number, point index) pairs, one per output point, in output
// order; the output is resized to that count at init. Linear: out_i = in_{s_i}[p_i]
// (Rigid3d→Vec3d takes the centre, and the linear part of derivatives).
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class SubsetMultiMapping final : public MappingBase {
 public:
  SubsetMultiMapping(StateType in, StateType out) : MappingBase(in, out, /*multi_input=*/true) {}

  Field<std::vector<int>> index_pairs{
      this, "indexPairs", {}, "list of couples (parent index + index in the parent)", "Mapping"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;

 protected:
  bool init_mapping() override;

 private:
  struct Source {
    unsigned input, point;
  };
  std::vector<Source> src_;  // per output point
  std::vector<const std::vector<double>*> in_ptr_;  // per-call scratch, sized at init
  int cwi_ = 3, dwi_ = 3, cwo_ = 3, dwo_ = 3;
};

}  // namespace sinew
