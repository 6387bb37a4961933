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

}  // namespace sinew
