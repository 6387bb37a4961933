// Element tests of oriented boxes (SOFA's CollisionOBBCapsule plugin, after
// Geometric Tools' separating-axis queries): box–box, triangle–box and
// sphere–box. Each appends at most one DetectionOutput and returns how many it
// appended; e1 belongs to model 1 of the pair.
//
// `alarm` and `contact` are the distances of the pair: the two models' skins
// (contactDistance) plus the intersection method's distances, summed by the
// caller in SOFA's order (skin 1 + skin 2 + method). Discrete intersection
// passes the skins alone.
#pragma once

#include <vector>

#include "collision/detection_output.h"
#include "collision/intersect/elements.h"

namespace sinew::obb {

// The axis of largest separation among the 15 box–box axes (and those of the
// relative velocity crossed with the edges); contact points from the faces,
// edges or corners that realise it. Boxes farther apart than `alarm` on one axis
// give nothing. Penetrating pairs get value −depth − contact.
int obb_obb(double alarm, double contact, const ObbElem& e1, const ObbElem& e2, std::vector<DetectionOutput>& out);

// The same separating-axis search between a triangle and a box, with the
// triangle's owned edges and vertices (its flags) only. Kept from SOFA: the
// value is +distance − contact even when the two overlap.
int triangle_obb(double alarm, double contact, const TriangleElem& e1, const ObbElem& e2,
                 std::vector<DetectionOutput>& out);

// The sphere's centre clamped into the box. Outside: along the segment to the
// clamped point; inside: along the box axis of largest relative coordinate.
int sphere_obb(double alarm, double contact, const SphereElem& e1, const ObbElem& e2, std::vector<DetectionOutput>& out);

}  // namespace sinew::obb
