#include "exporter/playback/write_state.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

WriteState::WriteState() { listening.set(true); }

void WriteState::cleanup() { out_.close(); }

void WriteState::reinit() {
  out_.close();
  init();
}

void WriteState::init() {
  valid_ = true;
  periodic_ = false;
  state_ = node() ? node()->get_mechanical_state() : nullptr;
  if (!state_) msg_warning("no mechanical state in this node or above: nothing will be written");
  if (!filename.is_set() || filename.get().empty()) {
    // SOFA falls back on " defaultExportFile" (leading space included); a plain name here.
    msg_warning("filename: no file name given; writing to defaultExportFile");
    filename.set(std::string("defaultExportFile"));
  }
  const std::string& path = filename.get();
  if (std::string error; !out_.open(path, &error)) msg_error("filename: " + error);
  const double dt = node() ? node()->dt.get() : 0.0;
  if (period.is_set()) {
    periodic_ = true;
    if (time.get().empty()) {
      msg_warning("period given without a starting time: the periodic export starts at t = 0");
      time.set(std::vector<double>{0.0});
    }
    if (time.get().size() > 1) {
      std::vector<double> first{time.get()[0]};
      time.set(first);
      msg_warning("period given: only the first time is kept as the start of the periodic export (" +
                  std::to_string(first[0]) + ")");
    }
    if (period.get() < dt)
      msg_warning("period (" + std::to_string(period.get()) + ") is smaller than the time step (" +
                  std::to_string(dt) + ")");
    if (time.get()[0] != 0.0 && time.get()[0] < dt)
      msg_warning("starting time (" + std::to_string(time.get()[0]) + ") is smaller than the time step");
  } else if (!time.is_set()) {
    // Neither given: every step from t = 0 (SOFA sets period = dt).
    period.set(dt);
    periodic_ = true;
  }
  if (!time.is_set() && time.get().empty()) {
    time.set(std::vector<double>{0.0});
  } else {
    const std::vector<double>& ts = time.get();
    for (std::size_t i = 0; i < ts.size(); ++i) {
      if (ts[i] < 0 || (i > 0 && ts[i] == 0)) {
        msg_error("time: export times must be positive (only the first may be 0); nothing will be written");
        valid_ = false;
        return;
      }
      if (dt > 0) {
        const double steps = ts[i] / dt;
        if (steps - std::floor(steps) > std::numeric_limits<double>::epsilon())
          msg_warning("time: " + std::to_string(ts[i]) + " is not a multiple of the time step " + std::to_string(dt));
      }
    }
  }
  if (stop_at.get() < 0) {
    msg_warning("stopAt must be positive; 0 used");
    stop_at.set(0.0);
  }
  if (stop_at.get() != 0)
    msg_warning("stopAt / keperiod (stop writing when the kinetic energy settles) are not implemented: "
                "the file is written on");
  reset();
}

void WriteState::reset() {
  next_ = 0;
  last_time_ = 0;
}

void WriteState::append_vec(std::string& out, const char* tag, int id) const {
  out += "  ";
  out += tag;
  out += "= ";
  const std::vector<double>& v = state_->read(id);
  char buf[32];
  for (std::size_t i = 0; i < v.size(); ++i) {
    // Shortest text that reads back to the same double.
    auto r = std::to_chars(buf, buf + sizeof buf, v[i]);
    if (i) out += ' ';
    out.append(buf, r.ptr);
  }
  out += '\n';
}

void WriteState::handle_event(Event& e) {
  if (!valid_ || e.kind != Event::Kind::animate_begin || !state_ || !out_.is_open()) return;
  const double t = node()->time.get();
  const double eps = 0.1 * node()->dt.get();
  bool now = false;
  const std::vector<double>& ts = time.get();
  if (next_ < ts.size()) {
    last_time_ = ts[next_];
    if (t > last_time_ || std::fabs(t - last_time_) < eps) {
      now = true;
      first_export_ = true;
      ++next_;
    }
  } else if (first_export_ && periodic_) {
    const double due = last_time_ + period.get();
    if (t > due || std::fabs(t - due) < eps) {
      now = true;
      last_time_ += period.get();
    }
  }
  if (!now) return;
  std::string block = "T= ";
  char buf[32];
  block.append(buf, std::to_chars(buf, buf + sizeof buf, t).ptr);
  block += '\n';
  if (write_x.get()) append_vec(block, "X", kPosition);
  if (write_x0.get()) append_vec(block, "X0", kRestPosition);
  if (write_v.get()) append_vec(block, "V", kVelocity);
  // SOFA's compressed branch leaves the forces out; written in both here.
  if (write_f.get()) append_vec(block, "F", kForce);
  out_.put(block);
  ++exports_;
}

void register_write_state(Registry& r) {
  ComponentInfo info;
  info.name = "WriteState";
  info.category = "Playback";
  info.description = "writes the node's state (positions, velocities, forces) to a text file at given times";
  info.create = creator<WriteState>();
  r.add(std::move(info));
}

}  // namespace sinew
