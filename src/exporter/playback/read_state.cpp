#include "exporter/playback/read_state.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"
#include "core/simulation.h"
#include "io/sofa_quat.h"

namespace sinew {

ReadState::ReadState() {
  filename.set_file(true, /*required=*/false);  // not found: reported at init
  listening.set(true);
}

void ReadState::init() { reset(); }

void ReadState::bwd_init() { process(); }

void ReadState::reset() {
  state_ = node() ? node()->get_mechanical_state() : nullptr;
  opened_ = false;
  blocks_.clear();
  const std::string& path = filename.get();
  if (path.empty()) {
    msg_error("filename: empty");
  } else {
    std::string error;
    if (auto blocks = regression::read_state_file(path, &error)) {
      blocks_ = std::move(*blocks);
      opened_ = true;
    } else {
      msg_error("filename: cannot read '" + path + "': " + error);
    }
  }
  cursor_ = 0;
  loop_offset_ = last_time_ = next_time_ = 0;
}

bool ReadState::process() {
  if (!node() || !state_ || !opened_) return false;
  const double t = node()->time.get() + shift.get();
  // Time went back (a reset): read from the start again, as SOFA's setTime.
  if (t + 0.5 * node()->dt.get() < last_time_) {
    reset();
    if (!opened_) return false;
  }
  last_time_ = t;
  const regression::StateBlock* due = nullptr;
  while (next_time_ <= t) {
    if (cursor_ >= blocks_.size()) {
      if (!loop.get() || blocks_.empty()) break;
      // SOFA rewinds and shifts the file's times by the last time it read.
      cursor_ = 0;
      loop_offset_ = next_time_;
    }
    const regression::StateBlock& b = blocks_[cursor_];
    next_time_ = b.time + loop_offset_;
    if (next_time_ > t) break;  // read again at a later step
    due = &b;
    ++cursor_;
  }
  if (!due) return false;
  if (!apply(*due)) return false;
  project_and_propagate(*node(), node()->time.get());
  return true;
}

bool ReadState::apply(const regression::StateBlock& b) {
  bool updated = false;
  const int w = state_->info().coord_width;
  for (const regression::StateLine& line : b.lines) {
    const int id = line.tag == 'X' ? kPosition : kVelocity;
    std::vector<double>& v = state_->write(id);
    if (line.values.size() != v.size() && !warned_size_) {
      warned_size_ = true;
      msg_warning("filename: a block at T= " + std::to_string(b.time) + " holds " + std::to_string(line.values.size()) +
                  " values where the state has " + std::to_string(v.size()) + "; the common part is read");
    }
    const std::size_t n = std::min(v.size(), line.values.size());
    std::copy(line.values.begin(), line.values.begin() + static_cast<std::ptrdiff_t>(n), v.begin());
    if (line.tag == 'X' && w >= 3) {
      // Scale, rotation, translation of the points (Rigid3d: their centres), in SOFA's order.
      const double s = scale_pos.get();
      const io::SQuat q = io::SQuat::from_euler(rotation.get() * (M_PI / 180.0));
      const Vec3 tr = translation.get();
      for (std::size_t i = 0; i + 3 <= v.size(); i += static_cast<std::size_t>(w)) {
        Vec3 p(v[i] * s, v[i + 1] * s, v[i + 2] * s);
        p = q.rotate(p) + tr;
        v[i] = p.x(), v[i + 1] = p.y(), v[i + 2] = p.z();
      }
    }
    updated = true;
  }
  return updated;
}

void ReadState::handle_event(Event& e) {
  if (e.kind == Event::Kind::animate_begin) process();
}

void register_read_state(Registry& r) {
  ComponentInfo info;
  info.name = "ReadState";
  info.category = "Playback";
  info.description = "replays a state file (WriteState's format) into the node's mechanical state";
  info.create = creator<ReadState>();
  r.add(std::move(info));
}

}  // namespace sinew
