#include "mapping/edge_kernels.h"

namespace sinew::edge {

void append_edge_row(std::vector<JacobianEntry>& out, std::uint32_t row, std::uint32_t col0, std::uint32_t col1,
                     const double* g) {
  for (std::uint32_t k = 0; k < 3; ++k) {
    out.push_back({0, row, col0 + k, -g[k]});
    out.push_back({0, row, col1 + k, g[k]});
  }
}

void add_edge_block(MatrixSink& K, const MechanicalState* s0, std::size_t i0, const MechanicalState* s1,
                    std::size_t i1, const double b[3][3]) {
  for (int j = 0; j < 3; ++j)
    for (int c = 0; c < 3; ++c) {
      K.add(s0, i0 + j, s0, i0 + c, b[j][c]);
      K.add(s0, i0 + j, s1, i1 + c, -b[j][c]);
      K.add(s1, i1 + j, s0, i0 + c, -b[j][c]);
      K.add(s1, i1 + j, s1, i1 + c, b[j][c]);
    }
}

}  // namespace sinew::edge
