// SmoothMeshEngine: Laplacian smoothing (SOFA's Engine/Transform). Each
// iteration moves every vertex (or those of input_indices) to the mean of
// its neighbours along the topology's edges (SOFA's getVerticesAroundVertex:
// the other ends of the edges around the vertex, in edge order); a vertex
// without neighbours stays. The topology is `topology`, else the node's.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class SmoothMeshEngine final : public Engine {
 public:
  SmoothMeshEngine();

  Field<std::vector<Vec3>> input_position{this, "input_position", {}, "points to smooth", "Inputs", "length"};
  Field<std::vector<unsigned>> input_indices{this, "input_indices", {}, "points to move (all when empty)", "Inputs"};
  Field<std::vector<Vec3>> output_position{this, "output_position", {}, "smoothed points", "Outputs", "length"};
  Field<unsigned> nb_iterations{this, "nb_iterations", 1, "iterations of Laplacian smoothing", "Inputs"};
  Field<bool> show_input{this, "showInput", false, "draw the input mesh (viewer)", "Visualization"};
  Field<bool> show_output{this, "showOutput", false, "draw the output mesh (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology giving the neighbours (default: the node's)"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
