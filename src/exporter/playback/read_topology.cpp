#include "exporter/playback/read_topology.h"

#include <limits>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {

// SOFA's readers read this far past the clock (ReadTopology::readNext's epsilon).
constexpr double kReadMargin = 1e-8;

// Elements [0, count) of one type from a block's index line; a short or negative line ends
// the list there (SOFA reads garbage past it; here the elements read are kept, reported once).
template <class Elem>
std::vector<Elem> elements(const regression::TopologyBlock& b, regression::ElementType type, bool* short_line) {
  const auto k = static_cast<std::size_t>(type);
  const long long n = b.counts[k];
  const std::vector<long long>& idx = b.indices[k];
  std::vector<Elem> out;
  constexpr std::size_t w = std::tuple_size_v<Elem>;
  const std::size_t available = idx.size() / w;
  const std::size_t wanted = n > 0 ? static_cast<std::size_t>(n) : 0;
  out.reserve(std::min(wanted, available));
  for (std::size_t i = 0; i < wanted; ++i) {
    if (i >= available) {
      *short_line = true;
      break;
    }
    Elem e{};
    bool ok = true;
    for (std::size_t j = 0; j < w; ++j) {
      const long long v = idx[i * w + j];
      ok = ok && v >= 0 && v <= std::numeric_limits<unsigned>::max();
      e[j] = static_cast<unsigned>(v);
    }
    if (!ok) {
      *short_line = true;
      break;
    }
    out.push_back(e);
  }
  return out;
}

}  // namespace

ReadTopology::ReadTopology() {
  filename.set_file(true, /*required=*/false);  // not found: reported at init
  listening.set(true);
}

void ReadTopology::init() {
  if (!topology.get() && node()) topology.set(node()->get_mesh_topology_link());
  if (!topology.get()) msg_error("topology: no mesh topology in this node or above, and no 'topology' link");
  reset();
}

void ReadTopology::reset() {
  open();
  read_ = 0;
}

bool ReadTopology::open() {
  opened_ = false;
  blocks_.clear();
  schedule_.reset();
  last_time_ = 0;
  const std::string& path = filename.get();
  if (path.empty()) {
    msg_error("filename: empty");
    return false;
  }
  std::string error;
  auto blocks = regression::read_topology_file(path, &error);
  if (!blocks) {
    msg_error("filename: cannot read '" + path + "': " + error);
    return false;
  }
  blocks_ = std::move(*blocks);
  std::vector<double> times;
  times.reserve(blocks_.size());
  for (const regression::TopologyBlock& b : blocks_) times.push_back(b.time);
  schedule_.emplace(std::move(times));
  schedule_->set_loop(loop.get());
  opened_ = true;
  return true;
}

const regression::TopologyBlock* ReadTopology::advance() {
  if (!node() || !topology.get() || !opened_) return nullptr;
  const double t = node()->time.get() + shift.get();
  // Time went back (a reset): read from the start again, as SOFA's setTime.
  if (t + 0.5 * node()->dt.get() < last_time_ && !open()) return nullptr;
  last_time_ = t;
  const auto due = schedule_->advance(t + kReadMargin, t);
  return due ? &blocks_[*due] : nullptr;
}

void ReadTopology::publish(const regression::TopologyBlock& b) {
  using regression::ElementType;
  bool short_line = false;
  edges.set(elements<Edge>(b, ElementType::edges, &short_line));
  triangles.set(elements<Triangle>(b, ElementType::triangles, &short_line));
  quads.set(elements<Quad>(b, ElementType::quads, &short_line));
  tetrahedra.set(elements<Tetra>(b, ElementType::tetrahedra, &short_line));
  hexahedra.set(elements<Hexa>(b, ElementType::hexahedra, &short_line));
  if (short_line && !warned_short_) {
    warned_short_ = true;
    msg_warning("filename: the block at T= " + std::to_string(b.time) +
                " holds fewer valid indices than its counts say; the elements read are kept");
  }
  ++read_;
}

void ReadTopology::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin) return;
  if (const regression::TopologyBlock* b = advance()) publish(*b);
}

void register_read_topology(Registry& r) {
  ComponentInfo info;
  info.name = "ReadTopology";
  info.category = "Playback";
  info.description = "reads a topology file (WriteTopology's format) into element lists at every step";
  info.create = creator<ReadTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
