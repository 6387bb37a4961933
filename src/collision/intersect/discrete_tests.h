// Element tests of DiscreteIntersection (spec/interaction.md §2.3): spheres only
// (alarm = contact = 0). Each test appends 0 or 1 DetectionOutput and returns
// how many it appended; element 1 belongs to model 1 of the pair.
#pragma once

#include <vector>

#include "collision/detection_output.h"
#include "collision/intersect/elements.h"

namespace sinew::discrete {

int sphere_sphere(const SphereElem& e1, const SphereElem& e2, std::vector<DetectionOutput>& out);

// The sphere–sphere test with explicit effective distances (SOFA's
// computeIntersectionSphere), shared with MinProximityIntersection, which
// passes its own alarm/contact distances plus both models' skins [length].
// Radii are added here: accepted iff |c2−c1| ≤ alarm + r1 + r2.
int sphere_sphere(const SphereElem& e1, const SphereElem& e2, double alarm, double contact,
                  std::vector<DetectionOutput>& out);

}  // namespace sinew::discrete
