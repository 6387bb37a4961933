// MatrixSink: where components add their matrix contributions during
// assembly (stiffness ∂f/∂x, damping ∂f/∂v, mass M, geometric stiffness).
//
// Components add *raw* entries; the assembler sets `factor` before calling
// each component (e.g. kFact + bFact·rayleighStiffness for a force field's
// stiffness, spec/solvers.md §0.1) and skips components whose factor is 0.
// Indices are scalar indices inside a state: dof·deriv_width + component.
// Non-virtual and inline: called once per element block in hot loops.
//
// Modes:
// * standalone (no layout): entries are kept with their states (entries()),
//   for tests and tools;
// * recording (a Layout is bound by the assembler): each state pair is
//   mapped once to a target matrix and offsets, and entries are recorded as
//   (target, global row, global col, factor·value) triplets in a buffer that
//   keeps its capacity. The assembler builds the pattern from them;
// * replaying (steady assembly): entries of the global matrix (target 0) are
//   checked against the recorded sequence of (row, col) keys and added
//   straight into the matrix values through the recorded slots, with no
//   intermediate buffer; entries of other targets (mapped states) are still
//   recorded. A sequence that differs from the recording sets replay_ok()
//   false and the assembler records again (solver/system_assembler.h).
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
  // Where entries of a pair of states go: target matrix (0 = global system,
  // others chosen by the layout) and the offsets added to the local indices.
  struct Binding {
    int target = 0;
    std::uint32_t row_offset = 0, col_offset = 0;
  };
  class Layout {
   public:
    virtual ~Layout() = default;
    virtual Binding bind(const MechanicalState* rs, const MechanicalState* cs) = 0;
  };
  struct Triplet {
    int target;
    std::uint32_t row, col;
    double value;
  };

  void set_factor(double f) { factor_ = f; }
  double factor() const { return factor_; }

  void add(const MechanicalState* rs, std::size_t r, const MechanicalState* cs, std::size_t c, double v) {
    if (!layout_) {
      entries_.push_back({rs, cs, static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(c), v * factor_});
      return;
    }
    if (rs != rs_ || cs != cs_) rebind(rs, cs);
    const auto gr = static_cast<std::uint32_t>(binding_.row_offset + r);
    const auto gc = static_cast<std::uint32_t>(binding_.col_offset + c);
    if (replay_keys_ && binding_.target == 0) replay(gr, gc, v * factor_);
    else triplets_.push_back({binding_.target, gr, gc, v * factor_});
  }
  // A 3×3 block whose top-left entry is at scalar indices (r, c).
  void add_block(const MechanicalState* rs, std::size_t r, const MechanicalState* cs, std::size_t c, const Mat3& b) {
    if (replay_keys_ && replay_block(rs, r, cs, c, b)) return;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) add(rs, r + i, cs, c + j, b(i, j));
  }

  void clear() {
    entries_.clear();
    triplets_.clear();
  }
  const std::vector<Entry>& entries() const { return entries_; }

  // ---- assembler side
  // Binds a layout (nullptr: standalone mode) and clears what was recorded.
  void begin(Layout* layout) {
    layout_ = layout;
    rs_ = cs_ = nullptr;
    factor_ = 1.0;
    replay_keys_ = nullptr;
    clear();
  }
  // Replaying: target-0 entries must come as keys[i] = (row << 32) | col,
  // i < count, and go to values[slots[i]] (skipped when slots[i] < 0).
  // block_slots[i] ≥ 0 when keys[i..i+9) are a whole 3×3 block in row-major
  // order stored contiguously from values[block_slots[i]] (one key check
  // then covers the block; see add_block).
  void begin_replay(Layout* layout, const std::uint64_t* keys, const std::int64_t* slots,
                    const std::int64_t* block_slots, std::size_t count, double* values) {
    begin(layout);
    replay_keys_ = keys;
    replay_slots_ = slots;
    replay_block_slots_ = block_slots;
    replay_count_ = count;
    replay_values_ = values;
    cursor_ = 0;
    replay_ok_ = true;
  }
  // After a replay: every entry matched the recording, and all of it was met.
  bool replay_ok() const { return replay_ok_ && cursor_ == replay_count_; }
  // Adds an entry already expressed in target indices (no factor applied).
  void add_raw(int target, std::uint32_t r, std::uint32_t c, double v) {
    if (replay_keys_ && target == 0) replay(r, c, v);
    else triplets_.push_back({target, r, c, v});
  }
  const std::vector<Triplet>& triplets() const { return triplets_; }

 private:
  void replay(std::uint32_t r, std::uint32_t c, double v) {
    if (cursor_ < replay_count_ && replay_keys_[cursor_] == ((static_cast<std::uint64_t>(r) << 32) | c)) {
      const std::int64_t s = replay_slots_[cursor_++];
      if (s >= 0) replay_values_[s] += v;
    } else {
      replay_ok_ = false;
      cursor_ = replay_count_;  // nothing further matches: the assembler records again
    }
  }
  // The whole-block path of add_block while replaying: false when the block
  // is not next in the recording as a contiguous block (the entry-wise path
  // then checks it, and fails the replay if it differs).
  bool replay_block(const MechanicalState* rs, std::size_t r, const MechanicalState* cs, std::size_t c,
                    const Mat3& b) {
    if (rs != rs_ || cs != cs_) rebind(rs, cs);
    if (binding_.target != 0 || cursor_ + 9 > replay_count_) return false;
    const std::uint64_t key = (static_cast<std::uint64_t>(binding_.row_offset + r) << 32) | (binding_.col_offset + c);
    const std::int64_t s = replay_block_slots_[cursor_];
    if (s < 0 || replay_keys_[cursor_] != key) return false;
    double* v = replay_values_ + s;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) v[i * 3 + j] += b(i, j) * factor_;
    cursor_ += 9;
    return true;
  }
  void rebind(const MechanicalState* rs, const MechanicalState* cs) {
    rs_ = rs;
    cs_ = cs;
    binding_ = layout_->bind(rs, cs);
  }

  double factor_ = 1.0;
  std::vector<Entry> entries_;
  Layout* layout_ = nullptr;
  const MechanicalState* rs_ = nullptr;
  const MechanicalState* cs_ = nullptr;
  Binding binding_;
  std::vector<Triplet> triplets_;
  const std::uint64_t* replay_keys_ = nullptr;  // non-null while replaying
  const std::int64_t* replay_slots_ = nullptr;
  const std::int64_t* replay_block_slots_ = nullptr;
  double* replay_values_ = nullptr;
  std::size_t replay_count_ = 0, cursor_ = 0;
  bool replay_ok_ = false;
};

// One entry of a mapping Jacobian: ∂out[row] / ∂in_k[col] where in_k is
// input number `input` of the mapping (scalar indices).
struct JacobianEntry {
  std::uint32_t input;
  std::uint32_t row, col;
  double value;
};

}  // namespace sinew
