// Stiffness entries of one spring between points a and b of the same Vec3d
// state, given its 3×3 tangent block k (row-major): −k on the two diagonal
// blocks, +k on the two coupling blocks. TriangularBendingSprings and
// QuadularBendingSprings emit them the same way; the entry order is part of
// the assembled pattern, so it is kept here once.
#pragma once

#include <cstddef>

#include "core/matrix_sink.h"

namespace sinew {

inline void add_spring_stiffness(MatrixSink& K, const MechanicalState* s, std::size_t a_point, std::size_t b_point,
                                 const double* k3x3) {
  const std::size_t a = 3 * a_point, b = 3 * b_point;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double k = k3x3[i * 3 + j];
      K.add(s, a + i, s, a + j, -k);
      K.add(s, a + i, s, b + j, k);
      K.add(s, b + i, s, a + j, k);
      K.add(s, b + i, s, b + j, -k);
    }
}

}  // namespace sinew
