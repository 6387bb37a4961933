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

  Field<bool> compute_distance{this, "computeDistance", false,
                               "if 'computeDistance = true', then rest length of each element equal 0, otherwise rest "
                               "length is the initial lenght of each of them",
                               "Mapping"};
  Field<std::vector<double>> rest_lengths{this, "restLengths", {}, "Rest lengths of the connections", "Mapping"};
  Field<std::vector<int>> index_pairs{this, "indexPairs", {},
                                      "list of couples (parent index + index in the parent)", "Mapping"};
  Field<std::string> geometric_stiffness{this, "geometricStiffness", "Stabilized",
                                         "Method used to compute the geometric stiffness: None, Exact or Stabilized "
                                         "(0, 1, 2)",
                                         "Mapping"};
  Field<double> show_object_scale{this, "showObjectScale", 0.0, "Scale for object display", "Visualization"};
  Field<std::vector<double>> show_color{this, "showColor", {1, 1, 0, 1}, "Color for object display", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "link to the topology container"};

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
