// Element tests of DiscreteIntersection (spec/interaction.md §2.3): exact
// intersections (alarm = contact = 0): spheres, a segment crossing a
// triangle, a point inside a tetrahedron. Each test appends 0 or 1 DetectionOutput and returns
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

// Segment e2 crossing triangle e1 (SOFA's MeshDiscreteIntersection): both
// points at the crossing, normal = the triangle's stored normal, value 0,
// id = the line's index. A segment parallel to the triangle's plane (singular
// system, |det| <= machine epsilon) does not cross it.
int triangle_line(const TriangleElem& e1, const LineElem& e2, std::vector<DetectionOutput>& out);

// Point e2 inside tetrahedron e1 (SOFA's TetrahedronDiscreteIntersection): the
// point leaves along its own normal −n; point1 is where the ray P − l·n meets
// the tetrahedron's surface, value −l, normal −n, id = the point's index.
// Points without a normal (n = 0) and, when both index one state, the tetrahedron's own
// vertices are skipped. A point outside still counts as handled (returns 1,
// appends nothing), as SOFA does.
int tetrahedron_point(const TetrahedronElem& e1, const PointElem& e2, bool same_state,
                      std::vector<DetectionOutput>& out);

}  // namespace sinew::discrete
