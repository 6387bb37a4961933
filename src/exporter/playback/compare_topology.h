// CompareTopology (SOFA's Sofa.Component.Playback): reads a topology file as ReadTopology does
// (same Data, same schedule) but, instead of exposing it, compares the node's own mesh topology
// with each block due: per element type whose count in the file is not 0, a different count
// adds |difference|, otherwise each element whose indices differ in any position adds 1
// (regression::compare_topology_block; the regression's topology metric). The sums are SOFA's
// per-container errors and TotalError; with printLog they are reported when the simulation
// closes. Like SOFA's, they are not cleared by a reset of the simulation. The topology
// compared is the 'topology' link when given, else the mesh topology of this node (SOFA looks
// in this node only).
#pragma once

#include <array>

#include "exporter/playback/read_topology.h"

namespace sinew {

class CompareTopology final : public ReadTopology {
 public:
  void init() override;
  void handle_event(Event& e) override;
  void cleanup() override;

  // Σ over compared blocks of the errors of every type (SOFA's getTotalError).
  long long total_error() const;
  // Errors of edges, triangles, quads, tetrahedra, hexahedra (SOFA's getErrors).
  const std::array<long long, regression::kElementTypeCount>& errors() const { return errors_; }
  int compared_blocks() const { return compared_; }

 private:
  std::array<long long, regression::kElementTypeCount> errors_{};
  int compared_ = 0;
};

}  // namespace sinew
