// GatherMultiMapping: one output state whose point i is point p_i of input s_i (linear:
// out_i = in_{s_i}[p_i]; Rigid3d→Vec3d takes the centre, and the linear part of
// derivatives). Two components fill the (s_i, p_i) list at init:
// - SubsetMultiMapping: `indexPairs` lists (input number, point index) pairs, one per
//   output point, in output order;
// - IdentityMultiMapping (identity_multi_mapping.cpp): every point of every input, inputs in
//   order.
// The output is resized to the list's length at init.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class GatherMultiMapping : public MappingBase {
 public:
  GatherMultiMapping(StateType in, StateType out) : MappingBase(in, out, /*multi_input=*/true) {}

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;

 protected:
  struct Source {
    unsigned input, point;
  };
  // Fills `src` (one entry per output point, checked against the inputs); false after
  // msg_error naming the problem.
  virtual bool sources(std::vector<Source>& src) = 0;
  bool init_mapping() final;

 private:
  std::vector<Source> src_;  // per output point
  std::vector<const std::vector<double>*> in_ptr_;  // per-call scratch, sized at init
  int cwi_ = 3, dwi_ = 3, cwo_ = 3, dwo_ = 3;
};

class SubsetMultiMapping final : public GatherMultiMapping {
 public:
  using GatherMultiMapping::GatherMultiMapping;

  Field<std::vector<int>> index_pairs{
      this, "indexPairs", {}, "list of couples (parent index + index in the parent)", "Mapping"};

 protected:
  bool sources(std::vector<Source>& src) override;
};

}  // namespace sinew
