#include "exporter/playback/compare_state.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void CompareState::init() {
  ReadState::init();  // parses the file
  comparer_.reset();
  if (!opened_ || !node()) return;
  comparer_ = std::make_unique<regression::StateComparer>(blocks_, node()->dt.get());
  comparer_->set_loop(loop.get());
}

void CompareState::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin || !comparer_ || !state_) return;
  const std::vector<double>& x = state_->read(kPosition);
  const std::vector<double>& v = state_->read(kVelocity);
  comparer_->on_step_begin(node()->time.get() + shift.get(), x.data(), x.size(), v.data(), v.size(), state_->size());
}

void CompareState::cleanup() {
  if (print_log.get() && comparer_)
    msg_info("compared " + std::to_string(comparer_->compared_blocks()) + " blocks: total error " +
             std::to_string(total_error()) + ", error by DoF " + std::to_string(error_by_dof()));
}

void register_compare_state(Registry& r) {
  ComponentInfo info;
  info.name = "CompareState";
  info.category = "Playback";
  info.description = "compares the node's state with a state file (WriteState's format) at every step";
  info.create = creator<CompareState>();
  r.add(std::move(info));
}

}  // namespace sinew
