// MatrixSink: where components add their matrix contributions during
// assembly (stiffness ∂f/∂x, damping ∂f/∂v, mass M, geometric stiffness).
//
// Components add *raw* entries; the assembler sets `factor` before calling
// each component (e.g. kFact + bFact·rayleighStiffness for a force field's
// stiffness, spec/solvers.md §0.1) and skips components whose factor is 0.
// Indices are scalar indices inside a state: dof·deriv_width + component.
// Non-virtual and inline: called once per element block in hot loops.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "math/types.h"

namespace sinew {

class MechanicalState;

class MatrixSink {
 public:
  struct Entry {
    const MechanicalState* row_state;
    const MechanicalState* col_state;
    std::uint32_t row, col;
    double value;
  };

  void set_factor(double f) { factor_ = f; }
  double factor() const { return factor_; }

  void add(const MechanicalState* rs, std::size_t r, const MechanicalState* cs, std::size_t c, double v) {
    entries_.push_back({rs, cs, static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(c), v * factor_});
  }
  // A 3×3 block whose top-left entry is at scalar indices (r, c).
  void add_block(const MechanicalState* rs, std::size_t r, const MechanicalState* cs, std::size_t c, const Mat3& b) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) add(rs, r + i, cs, c + j, b(i, j));
  }

  void clear() { entries_.clear(); }
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  double factor_ = 1.0;
  std::vector<Entry> entries_;
};

// One entry of a mapping Jacobian: ∂out[row] / ∂in_k[col] where in_k is
// input number `input` of the mapping (scalar indices).
struct JacobianEntry {
  std::uint32_t input;
  std::uint32_t row, col;
  double value;
};

}  // namespace sinew
