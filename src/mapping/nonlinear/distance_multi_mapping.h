// DistanceMultiMapping: distances between points taken from several input
// states (spec/mechanics.md §6.6). `indexPairs` lists (input number, point
// index) pairs; the topology's edges index into that list. One Vec1d output
// per edge: |p1 − p0| − L0. restLengths: if its size differs from the edge
// count it is recomputed from the initial positions (0 with computeDistance).
// J is split by input; geometric stiffness as DistanceMapping.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class DistanceMultiMapping final : public MappingBase {
 public:
  explicit DistanceMultiMapping(StateType in) : MappingBase(in, StateType::vec1, /*multi_input=*/true) {}

  Field<bool> compute_distance{
      this, "computeDistance", false,
      "output the distance itself (rest length 0) instead of the elongation from the initial length", "Mapping"};
  Field<std::vector<double>> rest_lengths{
      this,
      "restLengths",
      {},
      "rest length of each edge (default: initial lengths, or 0 with computeDistance)",
      "Mapping"};
  Field<std::vector<int>> index_pairs{
      this, "indexPairs", {}, "input points as (parent state index, point index) pairs", "Mapping"};
  Field<std::string> geometric_stiffness{this, "geometricStiffness", "Stabilized",
                                         "geometric stiffness: None, Exact or Stabilized (0, 1, 2)", "Mapping"};
  Field<double> show_object_scale{this, "showObjectScale", 0.0, "drawing scale (viewer)", "Visualization"};
  Field<std::vector<double>> show_color{this, "showColor", {1, 1, 0, 1}, "drawing colour (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology used by this component (default: the node's)"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  void apply_djt(int df, int dx, double k) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool build_geometric_stiffness(MatrixSink& K) override;

 protected:
  bool init_mapping() override;

 private:
  struct End {
    unsigned input, point;
  };
  std::vector<std::array<End, 2>> ends_;  // per edge
  std::vector<double> rest_;
  std::vector<double> dir_, invlen_;
  std::vector<const std::vector<double>*> in_ptr_;  // per-call scratch, sized at init
  std::vector<std::vector<double>*> inw_ptr_;
  int gs_ = 2;
  int cw_ = 3, dw_ = 3;
};

}  // namespace sinew
