// When a comparer looks at which reference block (regression-protocol.md §5).
//
// SOFA's comparers read their reference file forward only, once per
// AnimateBegin event, and compare at most one block per event: the last block
// that became due. This class reproduces that schedule on the list of block
// times, so state and topology comparers share one implementation and the
// quirks (blocks skipped or merged) come out identical.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace sinew::regression {

class BlockSchedule {
 public:
  // `times`: the printed block times, in file order (not necessarily sorted).
  explicit BlockSchedule(std::vector<double> times) : times_(std::move(times)) {}

  // One event. Reads blocks while the time of the next unread block is
  // <= read_limit (that is, the block header read last, whose time exceeded the
  // limit at an earlier event, is re-tested first); a block read this way is
  // "due" if its time is <= keep_limit, and the last due block is returned.
  // Returns nullopt when no block became due (nothing to compare), including
  // at and after the end of the file.
  //   state comparer:    read_limit = keep_limit = t + 0.001*dt
  //   topology comparer: read_limit = t + 1e-8, keep_limit = t
  // Like SOFA, the reader starts with "next time" 0, so nothing is read at an
  // event whose read_limit is negative.
  std::optional<std::size_t> advance(double read_limit, double keep_limit);

  // Loop mode (ReadTopology's `loop`): at the end of the file, read it again
  // from its first block, its times shifted by the time of the header read last
  // (SOFA's loopTime; the rewind happens within the event, so the first block
  // of the next pass can be due at the same event as the last one). A file
  // whose last time is <= 0 would never advance: looping stops there.
  void set_loop(bool on) { loop_ = on; }
  // Shift added to the printed times of the current pass (0 on the first).
  double offset() const { return offset_; }

  // True once every block has been read (later events compare nothing).
  bool at_end() const { return next_ == times_.size() && !pending_ && !loop_; }

 private:
  std::vector<double> times_;
  std::size_t next_ = 0;                // first block whose header is unread
  std::optional<std::size_t> pending_;  // header read, not yet due
  double next_time_ = 0.0;              // time of the pending block, shifted (0 at start)
  double offset_ = 0.0;                 // shift of the current pass
  bool loop_ = false;
};

}  // namespace sinew::regression
