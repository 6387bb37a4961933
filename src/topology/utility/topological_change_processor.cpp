#include "topology/utility/topological_change_processor.h"

#include <array>
#include <cmath>
#include <type_traits>
#include <limits>
#include <sstream>

#include "core/node.h"
#include "core/registry.h"
#include "io/text_file.h"
#include "topology/dynamic/point_set_topology_modifier.h"
#include "topology/dynamic/hexahedron_set_topology_modifier.h"
#include "topology/dynamic/tetrahedron_set_topology_modifier.h"

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
  // Commands this slice cannot apply, and malformed ADD= lines, are refused now, naming the line
  // (never skipped silently).
  bool ok = true;
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    std::istringstream s(lines_[i]);
    std::string tok;
    s >> tok;
    if (tok == "INCISE=") {
      msg_error(where(i) + tok + " changes are not supported yet");
      ok = false;
    } else if (tok == "ADD=") {
      std::string why;
      if (!parse_add(i, nullptr, &why)) {
        msg_error(where(i) + why);
        ok = false;
      }
    }
  }
  if (ok && !modifier_) {
    msg_error("no topology modifier found in the topology's node or its ancestors");
    ok = false;
  }
  if (!ok) set_state(ComponentState::invalid);
}

namespace {
using AddKind = TopologicalChangeProcessor::AddKind;
// The element kinds an ADD= line may name (SOFA's keywords), with their vertex count; arity 0 for
// the kinds SOFA knows that are not supported here, -1 for unknown words.
int add_kind_arity(const std::string& kind, AddKind* k) {
  if (kind == "Edge" || kind == "Edges") return *k = AddKind::edge, 2;
  if (kind == "Triangle" || kind == "Triangles") return *k = AddKind::triangle, 3;
  if (kind == "Quad" || kind == "Quads") return *k = AddKind::quad, 4;
  if (kind == "Tetrahedron" || kind == "Tetrahedra") return *k = AddKind::tetrahedron, 4;
  if (kind == "Hexahedron" || kind == "Hexahedra") return *k = AddKind::hexahedron, 8;
  if (kind == "PointInTriangle" || kind == "PointsInTriangle") return 0;
  return -1;
}
}  // namespace

bool TopologicalChangeProcessor::parse_add(std::size_t line, AddCommand* out, std::string* why) const {
  std::istringstream s(lines_[line]);
  std::string tok, kind;
  s >> tok >> kind;
  AddKind add_kind = AddKind::edge;
  const int arity = add_kind_arity(kind, &add_kind);
  if (arity < 0) {
    *why = "ADD= of unknown kind '" + kind + "'";
    return false;
  }
  if (arity == 0) {
    *why = "ADD= " + kind + " is not supported yet";
    return false;
  }
  long long n = -1;
  if (!(s >> n) || n < 0) {
    *why = "ADD= " + kind + " needs a count of elements";
    return false;
  }
  AddCommand cmd;
  cmd.arity = static_cast<unsigned>(arity);
  cmd.kind = add_kind;
  std::string word;
  if (s >> word) {
    if (add_kind != AddKind::triangle || (word != "Ancestor" && word != "Ancestors")) {
      *why = "unexpected '" + word + "' after the count (only triangles take Ancestors)";
      return false;
    }
    for (long long k = 0; k < n; ++k) {
      long long a = -1;
      if (!(s >> a) || a < 0) {
        *why = "ADD= " + kind + " " + std::to_string(n) + " Ancestors: expected " + std::to_string(n) +
               " non-negative ancestor indices";
        return false;
      }
      cmd.ancestors.push_back({static_cast<unsigned>(a)});
    }
  }
  if (line + 1 >= lines_.size()) {
    *why = "ADD= " + kind + " has no vertex line";
    return false;
  }
  std::istringstream v(lines_[line + 1]);
  const long long need = n * arity;
  for (long long k = 0; k < need; ++k) {
    long long x = -1;
    if (!(v >> x) || x < 0) {
      *why = "ADD= " + kind + " " + std::to_string(n) + ": line " + std::to_string(line + 2) + " needs " +
             std::to_string(need) + " non-negative vertex indices";
      return false;
    }
    cmd.vertices.push_back(static_cast<unsigned>(x));
  }
  PointSetTopologyModifier* mod = nullptr;
  MeshTopologyBase* t = topology.get();
  if (!t && node()) t = node()->get_mesh_topology_link();
  Node* from = t ? t->node() : nullptr;
  if (from) {
    switch (add_kind) {
      case AddKind::edge: mod = from->find_up<EdgeSetTopologyModifier>(); break;
      case AddKind::triangle: mod = from->find_up<TriangleSetTopologyModifier>(); break;
      case AddKind::quad: mod = from->find_up<QuadSetTopologyModifier>(); break;
      case AddKind::tetrahedron: mod = from->find_up<TetrahedronSetTopologyModifier>(); break;
      case AddKind::hexahedron: mod = from->find_up<HexahedronSetTopologyModifier>(); break;
    }
  }
  if (!mod) {
    static const char* names[] = {"EdgeSetTopologyModifier", "TriangleSetTopologyModifier",
                                  "QuadSetTopologyModifier", "TetrahedronSetTopologyModifier",
                                  "HexahedronSetTopologyModifier"};
    *why = "ADD= " + kind + " needs a " + names[static_cast<int>(add_kind)] +
           " in the topology's node or its ancestors";
    return false;
  }
  cmd.modifier = mod;
  if (out) *out = std::move(cmd);
  return true;
}

void TopologicalChangeProcessor::apply_add(const AddCommand& a) {
  const std::size_t n = a.vertices.size() / a.arity;
  // The n elements of `a`, N vertex indices each, in file order.
  auto items = [&]<std::size_t N>(std::integral_constant<std::size_t, N>) {
    std::vector<std::array<unsigned, N>> out(n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < N; ++c) out[i][c] = a.vertices[N * i + c];
    return out;
  };
  switch (a.kind) {
    case AddKind::edge:
      static_cast<EdgeSetTopologyModifier*>(a.modifier)->add_edges(items(std::integral_constant<std::size_t, 2>{}));
      break;
    case AddKind::triangle:
      static_cast<TriangleSetTopologyModifier*>(a.modifier)
          ->add_triangles(items(std::integral_constant<std::size_t, 3>{}), a.ancestors);
      break;
    case AddKind::quad:  // SOFA passes no ancestors for quads and hexahedra
      static_cast<QuadSetTopologyModifier*>(a.modifier)->add_quads(items(std::integral_constant<std::size_t, 4>{}));
      break;
    case AddKind::tetrahedron:
      static_cast<TetrahedronSetTopologyModifier*>(a.modifier)
          ->add_tetrahedra(items(std::integral_constant<std::size_t, 4>{}));
      break;
    case AddKind::hexahedron:
      static_cast<HexahedronSetTopologyModifier*>(a.modifier)
          ->add_hexahedra(items(std::integral_constant<std::size_t, 8>{}));
      break;
  }
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
    if (tok == "ADD=") {
      // Checked at init; the vertex line is the next collected one, as in SOFA.
      AddCommand a;
      std::string why;
      if (k + 1 >= valid.size() || valid[k + 1] != i + 1) {
        msg_error(where(i) + "ADD= has no vertex line in its block; nothing added");
        continue;
      }
      ++k;
      if (!parse_add(i, &a, &why)) {
        msg_error(where(i) + why);
        continue;
      }
      apply_add(a);
      continue;
    }
    if (tok != "REMOVE=") continue;  // T= and index lines (INCISE= was refused at init)
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
      // SOFA sizes the list to the count and reads what the line holds: the entries the line
      // lacks keep their zero. Several of SOFA's own change files count one index too many, so
      // element 0 goes too; reproduced (one 0 suffices: duplicates collapse) and said.
      msg_warning(where(il) + "REMOVE= " + std::to_string(n) + " lists " + std::to_string(ids.size()) +
                  " indices; as in SOFA the missing entries read as index 0, which is removed too");
      ids.push_back(0);
    }
    std::string why;
    if (!modifier_->remove_items(ids, &why)) msg_error(where(i) + why);
  }
}

void register_topological_change_processor(Registry& r) {
  ComponentInfo info;
  info.name = "TopologicalChangeProcessor";
  info.category = "Topology";
  info.description = "replays topological changes (removals, additions) read from a file at the times it gives";
  info.create = creator<TopologicalChangeProcessor>();
  r.add(std::move(info));
}

}  // namespace sinew
