// SubsetMapping: out_i = in[indices[i]] (spec/mechanics.md §6.4).
// Indices come from `indices`, else the range first..last, else the nearest
// input point within `radius` of each initial output point. An index out of
// range keeps the output's rest position (only with ignoreNotFound).
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class SubsetMapping final : public MappingBase {
 public:
  SubsetMapping(StateType in, StateType out) : MappingBase(in, out) {}

  Field<std::vector<unsigned>> indices{this, "indices", {}, "input index of each output point", "Mapping"};
  Field<unsigned> first{this, "first", 4294967295u, "first input index of a contiguous range", "Mapping"};
  Field<unsigned> last{this, "last", 4294967295u, "last input index of a contiguous range", "Mapping"};
  Field<double> radius{this, "radius", 1.0e-5, "matching radius used when no indices are given", "Mapping", "length"};
  Field<bool> handle_topology_change{this, "handleTopologyChange", true, "update the indices on topology changes",
                                     "Mapping"};
  Field<bool> ignore_not_found{this, "ignoreNotFound", false,
                               "tolerate output points without an input match (no error)", "Mapping"};
  Field<bool> resize_to_model{this, "resizeToModel", false, "resize the output state to the number of indices",
                              "Mapping"};
  Link<MeshTopologyBase> topology{this, "topology", "topology used by this component (default: the node's)"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;

 protected:
  bool init_mapping() override;

 private:
  std::vector<unsigned> idx_;
  int cw_ = 3, dw_ = 3;
};

}  // namespace sinew
