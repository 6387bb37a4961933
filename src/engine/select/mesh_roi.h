// MeshROI: selects the points and elements inside a closed triangle mesh
// (SOFA's Engine/Select). A point is inside when it lies in the mesh's
// bounding box and a ray from it to a point 100 units beyond the nearer box
// corner crosses an odd number of the mesh's triangles (SOFA's test, with its
// same-side edge checks). The box is computed from ROIposition at init and
// reinit (output `box`). Non-strict by default (SOFA's MeshROI keeps its old
// default): an element is in when all its vertices are, else when its centroid is.
// With computeMeshROI = false every point is inside.
#pragma once

#include "engine/base_roi.h"

namespace sinew {

class MeshROI final : public BaseROI {
 public:
  explicit MeshROI(StateType type);

  Field<FlatVec> roi_position;
  Field<std::vector<Edge>> roi_edges{this, "ROIedges", {}, "edges of the ROI mesh", "Inputs"};
  Field<std::vector<Triangle>> roi_triangles{this, "ROItriangles", {}, "triangles of the ROI mesh", "Inputs"};
  Field<bool> compute_mesh_roi{this, "computeMeshROI", true, "test against the mesh (else every point is in)",
                               "Inputs"};
  Field<VecN<6>> box{this, "box", VecN<6>::Zero(), "bounding box of the ROI mesh: xmin ymin zmin xmax ymax zmax",
                     "Outputs", "length"};
  Field<bool> draw_out{this, "drawOut", false, "draw what is outside (viewer)", "Visualization"};
  Field<bool> draw_box{this, "drawBox", false, "draw the bounding box (viewer)", "Visualization"};

 protected:
  void roi_init() override;
  bool point_in_roi(const double* p) const override;
  bool inside_vertices_suffice() const override { return true; }

 private:
  std::vector<Vec3> mesh_x_;
  std::vector<Triangle> mesh_t_;
  bool roi_ready_ = false;
};

}  // namespace sinew
