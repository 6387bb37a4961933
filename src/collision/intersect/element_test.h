// Glue between an intersection method's table and the element tests: reads
// the two elements out of their models and calls the test with the method's
// parameters. One indirect call per element pair, as SOFA's intersectors.
#pragma once

#include <vector>

#include "collision/intersection.h"

namespace sinew {

template <class Method, class M1, class M2, auto Fn>
int element_test(const Intersection& in, const CollisionModelBase& m1, unsigned i1, const CollisionModelBase& m2,
                 unsigned i2, std::vector<DetectionOutput>& out) {
  return Fn(static_cast<const Method&>(in).params(), static_cast<const M1&>(m1).elem(i1),
            static_cast<const M2&>(m2).elem(i2), out);
}

// Glue for tests that take the pair's distances instead of the method's
// parameters (the oriented-box tests): both models' skins plus the method's
// alarm and contact distances, summed in SOFA's order.
template <class M1, class M2, auto Fn>
int distance_test(const Intersection& in, const CollisionModelBase& m1, unsigned i1, const CollisionModelBase& m2,
                  unsigned i2, std::vector<DetectionOutput>& out) {
  const auto& e1 = static_cast<const M1&>(m1).elem(i1);
  const auto& e2 = static_cast<const M2&>(m2).elem(i2);
  const double skins = e1.info.cd + e2.info.cd;
  return Fn(skins + in.alarm_distance(), skins + in.contact_distance(), e1, e2, out);
}

}  // namespace sinew
