// Element tests of NewProximityIntersection (spec/interaction.md §2.5).
// Each test appends DetectionOutputs and returns how many it appended;
// e1 belongs to model 1 of the pair (the orientation SOFA registers the pair with).
#pragma once

#include <vector>

#include "collision/detection_output.h"
#include "collision/intersect/elements.h"

namespace sinew::new_proximity {

struct Params {
  double alarm = 1.0;    // alarmDistance [length]
  double contact = 0.5;  // contactDistance [length]
  bool use_line_line = false;
};

int point_point(const Params&, const PointElem& e1, const PointElem& e2, std::vector<DetectionOutput>& out);
int line_point(const Params&, const LineElem& e1, const PointElem& e2, std::vector<DetectionOutput>& out);
int line_line(const Params&, const LineElem& e1, const LineElem& e2, std::vector<DetectionOutput>& out);
int triangle_point(const Params&, const TriangleElem& e1, const PointElem& e2, std::vector<DetectionOutput>& out);
int triangle_line(const Params&, const TriangleElem& e1, const LineElem& e2, std::vector<DetectionOutput>& out);
int triangle_triangle(const Params&, const TriangleElem& e1, const TriangleElem& e2, std::vector<DetectionOutput>& out);
int sphere_sphere(const Params&, const SphereElem& e1, const SphereElem& e2, std::vector<DetectionOutput>& out);
int sphere_point(const Params&, const SphereElem& e1, const PointElem& e2, std::vector<DetectionOutput>& out);
int line_sphere(const Params&, const LineElem& e1, const SphereElem& e2, std::vector<DetectionOutput>& out);
int triangle_sphere(const Params&, const TriangleElem& e1, const SphereElem& e2, std::vector<DetectionOutput>& out);

}  // namespace sinew::new_proximity
