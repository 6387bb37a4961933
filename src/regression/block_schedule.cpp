#include "regression/block_schedule.h"

namespace sinew::regression {

std::optional<std::size_t> BlockSchedule::advance(double read_limit, double keep_limit) {
  std::optional<std::size_t> due;
  while (next_time_ <= read_limit) {
    if (pending_) {
      // A block within the read limit is consumed even when it is above the
      // keep limit: its lines are simply dropped (the topology 1e-8 quirk).
      if (times_[*pending_] <= keep_limit) due = pending_;
      pending_.reset();
    }
    if (next_ == times_.size()) break;  // end of file: nothing more, ever
    pending_ = next_;
    next_time_ = times_[next_++];
  }
  return due;
}

}  // namespace sinew::regression
