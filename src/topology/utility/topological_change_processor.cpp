#include "topology/utility/topological_change_processor.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/node.h"
#include "core/registry.h"
#include "io/text_file.h"
#include "topology/dynamic/point_set_topology_modifier.h"

namespace sinew {

TopologicalChangeProcessor::TopologicalChangeProcessor() {
  filename.set_file(true);
  listening.set(true);
}

std::string TopologicalChangeProcessor::where(std::size_t line) const {
  return filename.value() + ":" + std::to_string(line + 1) + ": ";
}

void TopologicalChangeProcessor::init() {
  lines_.clear();
  next_ = 0;
  cmd_.clear();
  next_time_ = loop_time_ = 0;
  modifier_ = nullptr;
  MeshTopologyBase* t = topology.get();
  if (!t && node()) t = node()->get_mesh_topology_link();
  if (!t) {
    msg_error("no topology found (link `topology` or the node's)");
    set_state(ComponentState::invalid);
    return;
  }
  // SOFA: the first TopologyModifier from the topology's node upwards.
  if (t->node()) modifier_ = t->node()->find_up<PointSetTopologyModifier>();
  if (use_data_inputs.value()) {
    msg_error("useDataInputs is not supported yet: no change is applied");
    set_state(ComponentState::invalid);
    return;
  }
  if (filename.value().empty()) {
    msg_error("empty filename");
    set_state(ComponentState::invalid);
    return;
  }
  std::string err;
  auto text = io::read_text_maybe_gzip(filename.value(), &err);
  if (!text) {
    msg_error(err);
    set_state(ComponentState::invalid);
    return;
  }
  // std::getline's pieces: a text ending with '\n' ends with an empty read that reaches the end.
  std::size_t start = 0;
  for (;;) {
    const std::size_t nl = text->find('\n', start);
    if (nl == std::string::npos) {
      lines_.push_back(text->substr(start));
      break;
    }
    lines_.push_back(text->substr(start, nl - start));
    start = nl + 1;
  }
  // Commands this slice cannot apply are refused now, naming the line (never skipped silently).
  bool ok = true;
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    std::istringstream s(lines_[i]);
    std::string tok;
    s >> tok;
    if (tok == "ADD=" || tok == "INCISE=") {
      msg_error(where(i) + tok + " changes are not supported yet");
      ok = false;
    }
  }
  if (ok && !modifier_) {
    msg_error("no topology modifier found in the topology's node or its ancestors");
    ok = false;
  }
  if (!ok) set_state(ComponentState::invalid);
}

void TopologicalChangeProcessor::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin || state() != ComponentState::valid || !node()) return;
  process(node()->time.value() + shift.value());
}

std::vector<std::size_t> TopologicalChangeProcessor::read_due(double t) {
  std::vector<std::size_t> valid;
  const double eps = std::numeric_limits<double>::epsilon();
  auto due = [&] { return next_time_ < t || std::fabs(next_time_ - t) < eps; };
  while (due()) {
    if (next_ >= lines_.size()) {  // end of file
      if (!loop.value() || lines_.empty()) break;
      next_ = 0;
      loop_time_ = next_time_;
    }
    const std::size_t i = next_++;
    std::istringstream s(lines_[i]);
    std::string tok;
    if (s >> tok) cmd_ = tok;
    if (cmd_ == "T=" && !tok.empty()) {
      double v = 0;  // a failed read gives 0, as a stream read does
      if (!(s >> v)) v = 0;
      next_time_ = v + loop_time_;
      if (due()) valid.clear();
    }
    if (due()) valid.push_back(i);
  }
  return valid;
}

void TopologicalChangeProcessor::process(double t) {
  if (state() != ComponentState::valid) return;
  const std::vector<std::size_t> valid = read_due(t);
  for (std::size_t k = 0; k < valid.size(); ++k) {
    const std::size_t i = valid[k];
    std::istringstream s(lines_[i]);
    std::string tok;
    s >> tok;
    if (tok != "REMOVE=") continue;  // T= and index lines (ADD=/INCISE= were refused at init)
    long long n = -1;
    if (!(s >> n) || n < 0) {
      msg_error(where(i) + "REMOVE= needs a count of elements; line ignored");
      continue;
    }
    if (k + 1 >= valid.size()) {
      msg_error(where(i) + "REMOVE= " + std::to_string(n) + " has no index line; nothing removed");
      continue;
    }
    const std::size_t il = valid[++k];
    std::istringstream idx(lines_[il]);
    std::vector<unsigned> ids;
    long long v = 0;
    while (static_cast<long long>(ids.size()) < n && idx >> v) {
      if (v < 0) {
        msg_warning(where(il) + "negative index " + std::to_string(v) + " skipped");
        --n;
        continue;
      }
      ids.push_back(static_cast<unsigned>(v));
    }
    if (static_cast<long long>(ids.size()) < n) {
      msg_error(where(il) + "expected " + std::to_string(n) + " indices, found " + std::to_string(ids.size()) +
                "; nothing removed");
      continue;
    }
    std::string why;
    if (!modifier_->remove_items(ids, &why)) msg_error(where(i) + why);
  }
}

void register_topological_change_processor(Registry& r) {
  ComponentInfo info;
  info.name = "TopologicalChangeProcessor";
  info.category = "Topology";
  info.description = "replays topological changes (removals) read from a file at the times it gives";
  info.create = creator<TopologicalChangeProcessor>();
  r.add(std::move(info));
}

}  // namespace sinew
