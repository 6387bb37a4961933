#include "exporter/playback/write_topology.h"

#include "core/node.h"
#include "core/registry.h"
#include "exporter/playback/topology_view.h"
#include "regression/number_format.h"

namespace sinew {

WriteTopology::WriteTopology() { listening.set(true); }

void WriteTopology::init() {
  out_.close();
  if (!topology.get() && node()) topology.set(node()->get_mesh_topology_link());
  if (!topology.get()) {
    msg_error("topology: no mesh topology in this node or above, and no 'topology' link: nothing will be written");
    return;
  }
  if (filename.get().empty()) {
    msg_warning("filename: no file name given: nothing will be written");
    return;
  }
  if (period.get() < 0) {
    msg_error("period (" + std::to_string(period.get()) + ") must not be negative: nothing will be written");
    return;
  }
  if (write_shell_containers.get())
    msg_warning("writeShellContainers: shell containers are not written (SOFA does not write them either)");
  if (std::string error; !out_.open(filename.get(), &error)) msg_error("filename: " + error);
  reset();
}

void WriteTopology::reset() {
  next_ = 0;
  last_time_ = 0;
}

void WriteTopology::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin || !out_.is_open() || !topology.get()) return;
  const double t = node()->time.get();
  bool now = false;
  const std::vector<double>& ts = time.get();
  if (next_ < ts.size()) {
    last_time_ = ts[next_];
    if (t >= last_time_) {
      now = true;
      ++next_;
    }
  } else if (t >= last_time_ + period.get()) {
    now = true;
    last_time_ += period.get();
  }
  if (!now) return;
  std::string block;
  if (write_containers.get()) {
    regression::append_topology_block(block, t, topology_view(*topology));
  } else {
    block = "T= ";
    regression::append_g6(block, t);
    block += '\n';
  }
  out_.put(block);
  ++exports_;
}

void register_write_topology(Registry& r) {
  ComponentInfo info;
  info.name = "WriteTopology";
  info.category = "Playback";
  info.description = "writes a mesh topology's element lists to a text file at given times";
  info.create = creator<WriteTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
