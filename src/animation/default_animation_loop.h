// DefaultAnimationLoop: SOFA's standard step pipeline (spec/framework.md §4.1).
//
//   begin event → collision → explicit interaction forces → solve every solver
//   node → project → propagate through mappings → end integration → time += dt
//   → end event.
#pragma once

#include <memory>

#include "core/mechanical_ops.h"
#include "core/roles.h"

namespace sinew {

class DefaultAnimationLoop final : public AnimationLoop {
 public:
  Field<bool> parallel_ode_solving{this, "parallelODESolving", false,
                                   "solve sibling solver nodes concurrently (results are identical)", "Solver"};
  Field<bool> compute_bounding_box{this, "computeBoundingBox", true, "update bounding boxes (viewer only)",
                                   "Visualization"};

  void step(double dt) override;

 private:
  // Stages, in order.
  void solve(Node& node, double dt);
  // Parallel mode: explicit interaction forces first, then the solver nodes to run concurrently.
  void collect_solver_nodes(Node& node);
  void project_and_propagate(Node& root, double t1);
  void end_integration(Node& root);
  void advance_time(Node& root, double dt);

  std::unique_ptr<MechanicalOps> whole_graph_;
  std::vector<Node*> solver_nodes_;  // scope of the root, for projection/propagation
};

}  // namespace sinew
