#include "topology/utility/topological_change_processor.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <type_traits>

#include "core/node.h"
#include "core/registry.h"
#include "io/text_file.h"
#include "topology/algorithm/triangle_incision.h"
#include "topology/dynamic/point_set_topology_modifier.h"
#include "topology/dynamic/hexahedron_set_topology_modifier.h"
#include "topology/dynamic/quad_set_topology_modifier.h"
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
  if (use_data_inputs.value()) return;  // SOFA reads no file then
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
  incisions_ = 0;
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    std::istringstream s(lines_[i]);
    std::string tok;
    s >> tok;
    if (tok == "INCISE=") {
      std::string why;
      if (!check_incise(i, &why)) {
        msg_error(where(i) + why);
        ok = false;
      } else {
        ++incisions_;
      }
    } else if (tok == "ADD=" && is_points_in_triangle(lines_[i])) {
      std::string why;
      if (!parse_points_in_triangle(i, nullptr, &why)) {
        msg_error(where(i) + why);
        ok = false;
      }
    } else if (tok == "ADD=") {
      std::string why;
      if (!parse_add(i, nullptr, &why)) {
        msg_error(where(i) + why);
        ok = false;
      }
    }
  }
  incision::Mesh mesh;
  if (ok && incisions_ > 0 && !incision_mesh(&mesh)) {
    msg_error("INCISE= needs a Vec3 MechanicalObject and a TriangleSetTopologyModifier with the topology");
    ok = false;
  }
  if (ok && !modifier_) {
    msg_error("no topology modifier found in the topology's node or its ancestors");
    ok = false;
  }
  if (!ok) {
    set_state(ComponentState::invalid);
    return;
  }
  saved_.clear();
  if (incisions_ > 0 && save_indices_at_init.value()) save_incisions();
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
  if (use_data_inputs.value()) {
    process_data_inputs(node()->time.value());  // SOFA passes getTime(), without the shift
    return;
  }
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
    if (tok == "ADD=" && is_points_in_triangle(lines_[i])) {
      PointsInTriangle p;
      std::string why;
      if (k + 1 >= valid.size() || valid[k + 1] != i + 1) {
        msg_error(where(i) + "ADD= has no coordinate line in its block; nothing added");
        continue;
      }
      ++k;
      if (!parse_points_in_triangle(i, &p, &why)) {
        msg_error(where(i) + why);
        continue;
      }
      apply_points_in_triangle(i, p);
      continue;
    }
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
    if (tok == "INCISE=") {
      // SOFA: with saved indices the incision of the current time (not shifted); else the block's
      // own line of points.
      if (save_indices_at_init.value()) incise_saved(node() ? node()->time.value() : t);
      else incise_from_file(i);
      if (k + 1 < valid.size() && valid[k + 1] == i + 1) ++k;  // its coordinate line
      continue;
    }
    if (tok != "REMOVE=") continue;  // T= and index lines
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

// ---------------------------------------------------------------- incisions

// SOFA's getValuesInLine rules: the next line holds n points, each "triangle x y z" (4n numbers)
// or "x y z" (3n); fewer than 3n numbers abort the incision; other counts are read as SOFA does
// (warned).
bool TopologicalChangeProcessor::check_incise(std::size_t line, std::string* why) {
  std::istringstream s(lines_[line]);
  std::string tok;
  long long n = -1;
  s >> tok;
  if (!(s >> n) || n < 1) {
    *why = "INCISE= needs a count of points (at least 1)";
    return false;
  }
  if (line + 1 >= lines_.size()) {
    *why = "INCISE= has no coordinate line";
    return false;
  }
  std::istringstream v(lines_[line + 1]);
  std::size_t count = 0;
  std::string word;
  while (v >> word) {
    char* end = nullptr;
    std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0') {
      *why = "INCISE= " + std::to_string(n) + ": line " + std::to_string(line + 2) + " holds '" + word +
             "', not a number";
      return false;
    }
    ++count;
  }
  const std::size_t un = static_cast<std::size_t>(n);
  if (count < 3 * un) {
    *why = "INCISE= " + std::to_string(n) + ": line " + std::to_string(line + 2) + " needs " +
           std::to_string(3 * un) + " (coordinates) or " + std::to_string(4 * un) +
           " (triangle and coordinates) numbers, has " + std::to_string(count);
    return false;
  }
  if (count != 3 * un && count != 4 * un)
    msg_warning(where(line + 1) + std::to_string(count) + " numbers for " + std::to_string(n) +
                " points: neither coordinates only nor triangle and coordinates");
  return true;
}

// ---------------------------------------------------------------- points in triangles

bool TopologicalChangeProcessor::is_points_in_triangle(const std::string& line) {
  std::istringstream s(line);
  std::string tok, kind;
  s >> tok >> kind;
  return tok == "ADD=" && (kind == "PointInTriangle" || kind == "PointsInTriangle");
}

bool TopologicalChangeProcessor::parse_points_in_triangle(std::size_t line, PointsInTriangle* out,
                                                          std::string* why) const {
  std::istringstream s(lines_[line]);
  std::string tok, kind;
  s >> tok >> kind;
  long long n = -1;
  if (!(s >> n) || n < 0) {
    *why = "ADD= " + kind + " needs a count of points";
    return false;
  }
  if (line + 1 >= lines_.size()) {
    *why = "ADD= " + kind + " has no coordinate line";
    return false;
  }
  std::istringstream v(lines_[line + 1]);
  PointsInTriangle p;
  for (long long k = 0; k < n; ++k) {
    long long t = -1;
    std::array<double, 2> b{};
    if (!(v >> t) || t < 0 || !(v >> b[0] >> b[1])) {
      *why = "ADD= " + kind + " " + std::to_string(n) + ": line " + std::to_string(line + 2) + " needs " +
             std::to_string(n) + " groups 'triangle b0 b1' (non-negative triangle index)";
      return false;
    }
    p.triangles.push_back(static_cast<unsigned>(t));
    p.bary.push_back(b);
  }
  MeshTopologyBase* t = topology.get();
  if (!t && node()) t = node()->get_mesh_topology_link();
  if (!t || !t->node() || !t->node()->find_up<TriangleSetTopologyModifier>()) {
    *why = "ADD= " + kind + " needs a TriangleSetTopologyModifier in the topology's node or its ancestors";
    return false;
  }
  if (out) *out = std::move(p);
  return true;
}

void TopologicalChangeProcessor::apply_points_in_triangle(std::size_t line, const PointsInTriangle& p) {
  MeshTopologyBase* t = topology.get();
  if (!t && node()) t = node()->get_mesh_topology_link();
  auto* mod = t && t->node() ? t->node()->find_up<TriangleSetTopologyModifier>() : nullptr;
  if (!mod) return;  // checked at init
  const auto& tris = t->triangles();
  std::vector<std::vector<unsigned>> ancestors;
  std::vector<std::vector<double>> coefs;
  for (std::size_t i = 0; i < p.triangles.size(); ++i) {
    if (p.triangles[i] >= tris.size()) {
      msg_error(where(line + 1) + "triangle " + std::to_string(p.triangles[i]) + " is out of range (" +
                std::to_string(tris.size()) + " triangles); no point added");
      return;
    }
    const Triangle& tr = tris[p.triangles[i]];
    ancestors.push_back({tr[0], tr[1], tr[2]});
    coefs.push_back({p.bary[i][0], p.bary[i][1], 1 - p.bary[i][0] - p.bary[i][1]});
  }
  mod->add_points(static_cast<unsigned>(p.triangles.size()), std::move(ancestors), std::move(coefs), true);
}

// ---------------------------------------------------------------- useDataInputs

void TopologicalChangeProcessor::process_data_inputs(double time) {
  if (time_to_remove.value() >= time) return;
  MeshTopologyBase* t = topology.get();
  if (!t && node()) t = node()->get_mesh_topology_link();
  Node* from = t ? t->node() : nullptr;
  auto remove = [&](const std::vector<unsigned>& ids, PointSetTopologyModifier* mod, const char* what) {
    if (ids.empty()) return;
    if (!mod) {
      msg_error(std::string("No ") + what + " modifier available");
      return;
    }
    std::string why;
    if (!mod->remove_items(ids, &why)) msg_error(why);
  };
  // SOFA's order: hexahedra, tetrahedra, quads, triangles, edges, points.
  remove(hexahedra_to_remove.get(), from ? from->find_up<HexahedronSetTopologyModifier>() : nullptr, "hexahedron");
  remove(tetrahedra_to_remove.get(), from ? from->find_up<TetrahedronSetTopologyModifier>() : nullptr, "tetrahedron");
  remove(quads_to_remove.get(), from ? from->find_up<QuadSetTopologyModifier>() : nullptr, "quad");
  remove(triangles_to_remove.get(), from ? from->find_up<TriangleSetTopologyModifier>() : nullptr, "triangle");
  remove(edges_to_remove.get(), from ? from->find_up<EdgeSetTopologyModifier>() : nullptr, "edge");
  remove(points_to_remove.get(), from ? from->find_up<PointSetTopologyModifier>() : nullptr, "point");
  // SOFA's Index is 32-bit: without interval the next time is (Index)-1.
  if (interval.value() != 0.0) time_to_remove.set(time_to_remove.value() + interval.value());
  else time_to_remove.set(static_cast<double>(~0u));
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
