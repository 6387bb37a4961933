// ShapeMatching (SOFA's Engine/Analyze, Müller et al. 2005): target
// positions that pull each cluster of points back to its rest shape. For
// each cluster (ClusteringEngine's `cluster`), the best rigid motion (polar
// factor of Σ w·x·x0ᵀ − xcm·x0cmᵀ, blended with the affine fit by
// `affineRatio`) carries the rest positions onto the current ones; a point's
// target is the mean of its clusters' predictions. Cluster entries past the
// state's points are fixed particles (fixedPosition0 at rest, fixedPosition
// now, weight `fixedweight`). Rest positions are the node's state's.
#pragma once

#include <vector>

#include "core/engine.h"
#include "core/roles.h"
#include "io/loader_fields.h"

namespace sinew {

class ShapeMatching final : public Engine {
 public:
  explicit ShapeMatching(StateType type);

  Link<MechanicalState> mstate{this, "mstate", "state whose rest positions define the shapes (default: the node's)"};
  Field<unsigned> iterations{this, "iterations", 1u, "Number of iterations.", "Inputs"};
  Field<double> affine_ratio{this, "affineRatio", 0.0, "Blending between affine and rigid.", "Inputs"};
  Field<double> fixed_weight{this, "fixedweight", 1.0, "weight of fixed particles.", "Inputs"};
  Field<FlatVec> fixed_position0;
  Field<FlatVec> fixed_position;
  Field<FlatVec> position;
  io::ValueField<std::vector<std::vector<unsigned>>> cluster{this, "cluster", "Input clusters.", "Inputs"};
  Field<FlatVec> target_position;

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;

 private:
  // Per cluster, recomputed when the clusters, the point count or the fixed weight change.
  std::size_t old_size_ = 0;
  double old_weight_ = 0;
  std::uint64_t cluster_version_ = ~std::uint64_t{0};
  std::vector<Vec3> xcm0_, xcm_;
  std::vector<double> weight_;
  std::vector<Mat3> qx_inv_, t_;
  std::vector<unsigned> clusters_of_;  // per point: how many clusters hold it
};

}  // namespace sinew
