// PairBoxROI: selects the points inside `inclusiveBox` but not inside
// `includedBox` — the frame between two nested boxes (SOFA's PairBoxROI, used
// to pick the border of a mesh). Boxes are xmin ymin zmin xmax ymax zmax,
// written back ordered; while either box is all zeros nothing is selected.
// Built on BaseROI for the positions and the point outputs (SOFA's component
// selects points only; the element outputs stay empty unless asked for). The
// viewer draws the two boxes and the points (render/draw_roi.cpp).
#pragma once

#include "engine/base_roi.h"

namespace sinew {

class PairBoxROI final : public BaseROI {
 public:
  explicit PairBoxROI(StateType type) : BaseROI(type) {
    add_input(&inclusive_box);
    add_input(&included_box);
    points_in_roi.add_alias("pointsInBox");
    // SOFA's indices start empty (BoxROI's start at 0).
    indices.raw().clear();
    compute_edges.raw() = compute_triangles.raw() = compute_quads.raw() = false;
    compute_tetrahedra.raw() = compute_hexahedra.raw() = false;
    draw_size.raw() = 0;  // SOFA's drawSize has no default: 0, drawn as 1
  }

  Field<VecN<6>> inclusive_box{this, "inclusiveBox", VecN<6>::Zero(),
                               "box holding the selected points: xmin ymin zmin xmax ymax zmax", "Inputs"};
  Field<VecN<6>> included_box{this, "includedBox", VecN<6>::Zero(),
                              "box inside it whose points are left out: xmin ymin zmin xmax ymax zmax", "Inputs"};
  Field<bool> draw_inclusive_box{this, "drawInclusiveBox", false, "draw the inclusive box (viewer)", "Visualization"};
  Field<bool> draw_included_box{this, "drawIncludedBox", false, "draw the included box (viewer)", "Visualization"};

 protected:
  bool roi_do_update() override {
    outer_ = inclusive_box.get();
    inner_ = included_box.get();
    if (outer_.isZero(0) || inner_.isZero(0)) return false;
    bool swapped_outer = false, swapped_inner = false;
    for (int a = 0; a < 3; ++a) {
      if (outer_[a] > outer_[a + 3]) std::swap(outer_[a], outer_[a + 3]), swapped_outer = true;
      if (inner_[a] > inner_[a + 3]) std::swap(inner_[a], inner_[a + 3]), swapped_inner = true;
    }
    if (swapped_outer) inclusive_box.edit() = outer_;  // SOFA writes the ordered boxes back
    if (swapped_inner) included_box.edit() = inner_;
    return true;
  }
  bool point_in_roi(const double* p) const override { return in(p, outer_) && !in(p, inner_); }

 private:
  bool in(const double* p, const VecN<6>& b) const {
    for (int i = 0; i < spatial_dim() && i < 3; ++i)
      if (!(p[i] >= b[i] && p[i] <= b[i + 3])) return false;
    return true;
  }
  VecN<6> outer_ = VecN<6>::Zero(), inner_ = VecN<6>::Zero();
};


}  // namespace sinew
