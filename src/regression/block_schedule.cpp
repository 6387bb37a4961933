#include "regression/block_schedule.h"

namespace sinew::regression {

namespace {
constexpr int kMaxRewinds = 100000;
}

std::optional<std::size_t> BlockSchedule::advance(double read_limit, double keep_limit) {
  std::optional<std::size_t> due;
  // A file of tiny positive times would take a pass per 1e-300 of clock: rewinds per event
  // are bounded so that hostile input lags instead of hanging.
  int rewinds = 0;
  while (next_time_ <= read_limit) {
    if (pending_) {
      // A block within the read limit is consumed even when it is above the
      // keep limit: its lines are simply dropped (the topology 1e-8 quirk).
      if (next_time_ <= keep_limit) due = pending_;
      pending_.reset();
    }
    if (next_ == times_.size()) {
      // End of file: nothing more, ever, unless looping over a file that moves time on.
      if (!loop_ || times_.empty() || next_time_ <= offset_ || ++rewinds > kMaxRewinds) break;
      offset_ = next_time_;
      next_ = 0;
    }
    pending_ = next_;
    next_time_ = times_[next_++] + offset_;
  }
  return due;
}

}  // namespace sinew::regression
