// SphereROI: selects the points and elements inside spheres, optionally
// filtering edges by direction and triangles by normal (SOFA's SphereROI).
#pragma once

#include "engine/base_roi.h"

namespace sinew {

class SphereROI final : public BaseROI {
 public:
  explicit SphereROI(StateType type);

  Field<std::vector<Vec3>> centers{this, "centers", {}, "centre(s) of the sphere(s)", "Inputs"};
  Field<std::vector<double>> radii{this, "radii", {}, "radius(ii) of the sphere(s); one value applies to all",
                                   "Inputs"};
  Field<Vec3> direction{this, "direction", Vec3::Zero(), "edge direction (if edgeAngle > 0)", "Inputs"};
  Field<Vec3> normal{this, "normal", Vec3::Zero(), "normal direction of the triangles (if triAngle > 0)", "Inputs"};
  Field<double> edge_angle{this, "edgeAngle", 0.0,
                           "max angle (degrees) between the selected edges and 'direction'", "Inputs"};
  Field<double> tri_angle{this, "triAngle", 0.0, "max angle (degrees) between the selected triangles' normal and "
                                                 "'normal'",
                          "Inputs"};

 protected:
  bool roi_do_update() override;
  bool point_in_roi(const double* p) const override;
  bool edge_extra(const Edge& e) const override;
  bool triangle_extra(const Triangle& t) const override;

 private:
  std::vector<Vec3> c_;
  std::vector<double> r_;
  Vec3 dir_ = Vec3::Zero(), normal_ = Vec3::Zero();
};

}  // namespace sinew
