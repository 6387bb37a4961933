// ConstantForceField: a constant force on a set of points
// (spec/mechanics.md §3.8). `forces` (one per index, or one for all) wins
// over `force` (the same on every index), which wins over `totalForce`
// (divided evenly); indices default to every point of the topology (else of
// the state). No stiffness. Every state template: a force has the state's
// derivative width (Vec3d: 3; Rigid3d: force then torque, 6; Rigid2d: 3).
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class ConstantForceField final : public ForceField {
 public:
  ConstantForceField();

  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the loaded points", "Load"};
  Field<bool> index_from_end{this, "indexFromEnd", false, "count the indices from the last point of the state", "Load"};
  Field<std::vector<double>> forces{this, "forces", {}, "force on each loaded point (the state's derivative layout)",
                                    "Load", "force"};
  Field<std::vector<double>> force{this, "force", {}, "force on every loaded point when 'forces' is empty", "Load",
                                   "force"};
  Field<std::vector<double>> total_force{this, "totalForce", {},
                                         "total force, split evenly among the loaded points", "Load", "force"};
  Field<double> show_arrow_size{this, "showArrowSize", 0.0, "size of the drawn arrows (viewer)", "Visualization"};
  Field<std::vector<double>> show_color{this, "showColor", {0.2, 0.9, 0.3, 1.0}, "arrow colour (viewer)",
                                        "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology giving the number of points (default: the node's)"};

  void init() override;
  void bwd_init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams&, double) override {}
  bool build_stiffness(MatrixSink&) override { return true; }
  // SOFA's getPotentialEnergy: −Σ f_i·x_i over the loaded points.
  std::optional<double> potential_energy() const override;

  // Per-index forces in use after init, `width()` scalars each.
  const std::vector<double>& applied() const { return applied_; }
  int width() const { return w_; }

 private:
  // One force of the state's width from `values` (false, with a message, when the count is wrong).
  bool read_one(const Field<std::vector<double>>& f, std::vector<double>& out);
  std::vector<unsigned> idx_;
  std::vector<double> applied_;
  int w_ = 3;
};

}  // namespace sinew
