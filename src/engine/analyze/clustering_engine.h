// ClusteringEngine (SOFA's Engine/Analyze): overlapping clusters of points
// for shape matching. `number` centres are chosen by farthest point sampling
// from point 0 (geodesic distances along the node's mesh edges when useTopo
// and a topology exist, else straight-line distances); every point when
// number = -1. Each cluster then holds its centre and, through the edges,
// the points of its Voronoi cell with one more ring and every point closer
// than `radius` to the centre (without a topology: the points closer than
// radius, a point near none going to the nearest centre, and the fixed
// points closer than fixedRadius, numbered after the state's). Clusters can
// be read from `inFile` instead and written to `outFile` (SOFA's format).
#pragma once

#include <string>
#include <vector>

#include "core/engine.h"
#include "core/roles.h"
#include "io/loader_fields.h"

namespace sinew {

class ClusteringEngine final : public Engine {
 public:
  explicit ClusteringEngine(StateType type);

  Field<bool> use_topo{this, "useTopo", true, "Use available topology to compute neighborhood.", "Inputs"};
  Field<double> radius{this, "radius", 1.0, "Neighborhood range.", "Inputs", "length"};
  Field<double> fixed_radius{this, "fixedRadius", 1.0, "Neighborhood range (for non mechanical particles).",
                             "Inputs", "length"};
  Field<int> number{this, "number", -1, "Number of clusters (-1 means that all input points are selected).",
                    "Inputs"};
  Field<FlatVec> fixed_position;
  Field<FlatVec> position;
  Field<std::string> in_file{this, "inFile", "", "import precomputed clusters", "Inputs"};
  Field<std::string> out_file{this, "outFile", "", "export clusters", "Outputs"};
  io::ValueField<std::vector<std::vector<unsigned>>> cluster{this, "cluster", "Computed clusters.", "Outputs"};

  void init() override;

 protected:
  void do_update() override;

 private:
  using Index = unsigned;
  // SOFA's farthestPointSampling: the centres, and each point's nearest centre (its place in
  // `centres`).
  void farthest_point_sampling(const std::vector<double>& x, std::vector<Index>& centres,
                               std::vector<Index>& voronoi) const;
  void dijkstra(const std::vector<double>& x, const std::vector<Index>& centres, std::vector<double>& distances,
                std::vector<Index>& voronoi) const;
  static void voronoi_of(const std::vector<double>& x, const std::vector<Index>& centres,
                         std::vector<double>& distances, std::vector<Index>& voronoi);
  std::vector<Index> neighbours(Index v) const;
  bool load();
  void save() const;

  MeshTopologyBase* topo_ = nullptr;
  std::string loaded_;
};

}  // namespace sinew
