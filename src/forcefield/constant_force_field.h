// ConstantForceField: a constant force on a set of points
// (spec/mechanics.md §3.8). `forces` (one per index, or one for all) wins
// over `force` (the same on every index), which wins over `totalForce`
// (divided evenly); indices default to every point of the topology (else of
// the state). No stiffness.
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class ConstantForceField final : public ForceField {
 public:
  ConstantForceField();

  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices where the forces are applied", "Load"};
  Field<bool> index_from_end{this, "indexFromEnd", false,
                             "indices are numbered from the end of the state (default=false)", "Load"};
  Field<std::vector<Vec3>> forces{this, "forces", {}, "applied forces at each point", "Load"};
  Field<Vec3> force{this, "force", Vec3::Zero(), "applied force to all points if forces attribute is not specified",
                    "Load"};
  Field<Vec3> total_force{this, "totalForce", Vec3::Zero(),
                          "total force for all points, will be distributed uniformly over points", "Load"};
  Field<double> show_arrow_size{this, "showArrowSize", 0.0, "size of the drawn arrows (viewer)", "Visualization"};
  Field<std::vector<double>> show_color{this, "showColor", {0.2, 0.9, 0.3, 1.0}, "arrow colour (viewer)",
                                        "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology giving the number of points (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams&, double) override {}
  bool build_stiffness(MatrixSink&) override { return true; }

  // Per-index forces in use after init.
  const std::vector<Vec3>& applied() const { return applied_; }

 private:
  std::vector<unsigned> idx_;
  std::vector<Vec3> applied_;
};

}  // namespace sinew
