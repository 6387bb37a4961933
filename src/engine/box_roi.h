// BoxROI: selects the points and elements lying in axis-aligned or oriented
// boxes (spec/mechanics.md §7.7). An engine: outputs are recomputed lazily
// when an input (boxes, positions, element lists) changed. Selection rules
// and outputs are shared with the other ROIs (engine/base_roi.h).
#pragma once

#include "engine/base_roi.h"

namespace sinew {

// Puts each box (xmin ymin zmin xmax ymax zmax) in min/max order; true when some corner pair was swapped.
bool order_box_corners(std::vector<VecN<6>>& boxes);

class BoxROI final : public BaseROI {
 public:
  explicit BoxROI(StateType type);

  Field<std::vector<VecN<6>>> box{this, "box", {}, "boxes: xmin ymin zmin xmax ymax zmax, ...", "Inputs"};
  Field<std::vector<VecN<10>>> oriented_box{
      this, "orientedBox", {},
      "oriented boxes: p0 p1 p2 (a parallelogram with p3 = p0 + p2 - p1) and a depth, extruded by depth/2 on both "
      "sides",
      "Inputs"};

 protected:
  void roi_init() override;
  bool roi_do_update() override;
  bool point_in_roi(const double* p) const override;

 private:
  struct OrientedBox {
    Vec3 p0, p2, normal, plane0, plane1, plane2, plane3;
    double width = 0, length = 0, depth = 0;
  };
  void normalize_boxes();
  std::vector<OrientedBox> oriented_;
  std::vector<VecN<6>> boxes_;  // aligned boxes, min ≤ max per axis
};

}  // namespace sinew
