#include "topology/mapping/simple_tesselated_tetra_topological_mapping.h"

#include "core/registry.h"
#include "topology/dynamic/tetrahedron_set_topology_modifier.h"

namespace sinew {

void SimpleTesselatedTetraTopologicalMapping::init() {
  if (!check_links(true, ElementType::tetrahedron, ElementType::tetrahedron)) return;
  const MeshTopologyBase& in = *input;
  // Copies: the output may alias the input's lists.
  const std::vector<Tetra> tets = in.tetrahedra();
  const std::vector<Edge> edges = in.edges();
  const std::vector<std::array<unsigned, 6>> edges_in_tet = in.edges_in_tetrahedron();
  const std::size_t np = in.nb_points();
  if (edges_in_tet.size() != tets.size()) {
    msg_error("the input topology " + in.describe() + " gives no edges of its tetrahedra");
    set_state(ComponentState::invalid);
    return;
  }
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (edges[e][0] >= np || edges[e][1] >= np) {
      msg_error("edge " + std::to_string(e) + " of " + in.describe() + " uses a point beyond its " +
                std::to_string(np) + " points");
      set_state(ComponentState::invalid);
      return;
    }
  // SOFA reads the container's coordinates, (0, 0, 0) for a point it has none for.
  const bool has_pos = in.has_positions();
  auto pos = [&](unsigned i) { return has_pos ? in.point(i) : Vec3(Vec3::Zero()); };

  std::vector<Vec3> points;
  points.reserve(np + edges.size());
  std::vector<unsigned> from_point(np), from_edge(edges.size());
  std::vector<unsigned> source(np + edges.size(), 0u);
  for (unsigned i = 0; i < np; ++i) {
    points.push_back(pos(i));
    from_point[i] = i;
    source[i] = i + 1;
  }
  for (unsigned e = 0; e < edges.size(); ++e) {
    const Vec3 a = pos(edges[e][0]), b = pos(edges[e][1]);
    // Coordinate by coordinate as SOFA: (a + b) / 2.
    points.push_back(Vec3((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2));
    from_edge[e] = static_cast<unsigned>(np + e);
    source[np + e] = ~e;  // −(e + 1) in SOFA's unsigned vector
  }

  std::vector<Tetra> out_tets;
  out_tets.reserve(8 * tets.size());
  std::vector<std::array<unsigned, 8>> children(tets.size());
  std::vector<unsigned> tet_source(8 * tets.size());
  for (unsigned i = 0; i < tets.size(); ++i) {
    const Tetra& t = tets[i];
    std::array<unsigned, 6> m{};
    for (int k = 0; k < 6; ++k) {
      const unsigned e = edges_in_tet[i][k];
      if (e >= from_edge.size()) {
        msg_error("tetrahedron " + std::to_string(i) + " of " + in.describe() + " names edge " + std::to_string(e) +
                  " beyond its " + std::to_string(edges.size()) + " edges");
        set_state(ComponentState::invalid);
        return;
      }
      m[k] = from_edge[e];
    }
    const Tetra split[8] = {{t[0], m[0], m[1], m[2]}, {t[1], m[0], m[4], m[3]}, {t[2], m[1], m[3], m[5]},
                            {t[3], m[2], m[5], m[4]}, {m[1], m[0], m[3], m[5]}, {m[1], m[0], m[5], m[2]},
                            {m[4], m[0], m[5], m[3]}, {m[4], m[0], m[2], m[5]}};
    for (int k = 0; k < 8; ++k) {
      children[i][k] = static_cast<unsigned>(out_tets.size());
      tet_source[out_tets.size()] = i;
      out_tets.push_back(split[k]);
    }
  }

  const std::size_t n_out = points.size();
  output->clear_topology();
  output->position.set(std::move(points));
  output->set_nb_points(n_out);
  output->tetrahedra_f.set(std::move(out_tets));
  output->init();

  point_mapped_from_point.set(std::move(from_point));
  point_mapped_from_edge.set(std::move(from_edge));
  point_source.set(std::move(source));
  tetrahedra_mapped_from_tetra.set(std::move(children));
  tetra_source.set(std::move(tet_source));
  tetrahedra_to_remove_.clear();
}

// ------------------------------------------------------------------ input changes (top-down)

void SimpleTesselatedTetraTopologicalMapping::update_top_down() {
  if (!input || !output || state() != ComponentState::valid) return;
  const std::vector<TopologyChange> changes = input->topology_changes();
  for (const TopologyChange& c : changes) {
    switch (c.type) {
      case TopologyChangeType::points_removed: remove_input_points(c.indices); break;
      case TopologyChangeType::edges_removed: remove_input_edges(c.indices); break;
      case TopologyChangeType::tetrahedra_removed: remove_input_tetrahedra(c.indices); break;
      default: break;  // SOFA leaves additions to do; the output itself never changes here
    }
  }
}

// Input points and edges share one bookkeeping: `from` maps each input element to its output point
// and pointSource holds code(i) for element i (i+1 for a point, ~i = −(i+1) for an edge).
void SimpleTesselatedTetraTopologicalMapping::swap_input(std::vector<unsigned>& from, unsigned a, unsigned b,
                                                         unsigned (*code)(unsigned)) {
  auto& src = point_source.edit();
  if (a >= from.size() || b >= from.size()) return;
  const unsigned am = from[a], bm = from[b];
  from[a] = bm;
  if (bm != kNone && bm < src.size()) src[bm] = code(a);
  from[b] = am;
  if (am != kNone && am < src.size()) src[am] = code(b);
}

void SimpleTesselatedTetraTopologicalMapping::remove_input(std::vector<unsigned>& from,
                                                           const std::vector<unsigned>& removed,
                                                           unsigned (*code)(unsigned)) {
  auto& src = point_source.edit();
  unsigned last = static_cast<unsigned>(from.size()) - 1u;  // wraps when empty, as SOFA's Index
  for (unsigned r : removed) {
    swap_input(from, r, last, code);
    if (last < from.size() && from[last] != kNone && from[last] < src.size()) src[from[last]] = 0;
    --last;
  }
  from.resize(last + 1u);
}

void SimpleTesselatedTetraTopologicalMapping::remove_input_points(const std::vector<unsigned>& removed) {
  remove_input(point_mapped_from_point.edit(), removed, [](unsigned i) { return i + 1; });
}

void SimpleTesselatedTetraTopologicalMapping::remove_input_edges(const std::vector<unsigned>& removed) {
  remove_input(point_mapped_from_edge.edit(), removed, [](unsigned i) { return ~i; });
}

void SimpleTesselatedTetraTopologicalMapping::swap_input_tetrahedra(unsigned a, unsigned b) {
  auto& children = tetrahedra_mapped_from_tetra.edit();
  auto& src = tetra_source.edit();
  if (a >= children.size() || b >= children.size()) return;
  const std::array<unsigned, 8> am = children[a], bm = children[b];
  children[a] = bm;
  for (unsigned c : bm)
    if (c != kNone && c < src.size()) src[c] = a;
  children[b] = am;
  for (unsigned c : am)
    if (c != kNone && c < src.size()) src[c] = b;
}

void SimpleTesselatedTetraTopologicalMapping::remove_input_tetrahedra(const std::vector<unsigned>& removed) {
  auto& children = tetrahedra_mapped_from_tetra.edit();
  auto& src = tetra_source.edit();
  unsigned last = static_cast<unsigned>(children.size()) - 1u;
  for (unsigned r : removed) {
    swap_input_tetrahedra(r, last);
    if (last < children.size())
      for (unsigned c : children[last])
        if (c != kNone && c < src.size()) src[c] = kNone;
    --last;
  }
  children.resize(last + 1u);
}

// ------------------------------------------------------------------ output changes (bottom-up)

void SimpleTesselatedTetraTopologicalMapping::update_bottom_up() {
  if (!input || !output || state() != ComponentState::valid) return;
  const std::vector<TopologyChange> changes = output->topology_changes();
  for (const TopologyChange& c : changes) {
    switch (c.type) {
      case TopologyChangeType::points_removed: remove_output_points(c.indices); break;
      case TopologyChangeType::tetrahedra_removed: remove_output_tetrahedra(c.indices); break;
      case TopologyChangeType::ending: {
        // SOFA's input modifier is the first one found from the input's node up.
        auto* mod = input->node() ? input->node()->find_up<TetrahedronSetTopologyModifier>() : nullptr;
        if (!mod || tetrahedra_to_remove_.empty()) break;
        const std::vector<unsigned> items(tetrahedra_to_remove_.rbegin(), tetrahedra_to_remove_.rend());
        tetrahedra_to_remove_.clear();
        std::string why;
        if (!mod->remove_items(items, &why)) msg_warning("input tetrahedra not removed: " + why);
        mod->notify_ending_event();
        break;
      }
      default: break;
    }
  }
}

void SimpleTesselatedTetraTopologicalMapping::set_point_source(unsigned i, int source) {
  auto& src = point_source.edit();
  if (i < src.size()) src[i] = static_cast<unsigned>(source);
  if (source > 0) {
    auto& from = point_mapped_from_point.edit();
    if (static_cast<unsigned>(source - 1) < from.size()) from[source - 1] = i;
  } else if (source < 0) {
    auto& from = point_mapped_from_edge.edit();
    if (static_cast<unsigned>(-source - 1) < from.size()) from[-source - 1] = i;
  }
}

void SimpleTesselatedTetraTopologicalMapping::swap_output_points(unsigned a, unsigned b) {
  const auto& src = point_source.value();
  if (a >= src.size() || b >= src.size()) return;
  const int as = static_cast<int>(src[a]), bs = static_cast<int>(src[b]);
  set_point_source(a, bs);
  set_point_source(b, as);
}

void SimpleTesselatedTetraTopologicalMapping::remove_output_points(const std::vector<unsigned>& removed) {
  auto& src = point_source.edit();
  unsigned last = static_cast<unsigned>(src.size()) - 1u;
  for (unsigned r : removed) {
    swap_output_points(r, last);
    const int source = last < src.size() ? static_cast<int>(src[last]) : 0;
    if (source > 0) {
      auto& from = point_mapped_from_point.edit();
      if (static_cast<unsigned>(source - 1) < from.size()) from[source - 1] = kNone;
    } else if (source < 0) {
      auto& from = point_mapped_from_edge.edit();
      if (static_cast<unsigned>(-source - 1) < from.size()) from[-source - 1] = kNone;
    }
    --last;
  }
  src.resize(src.size() >= removed.size() ? src.size() - removed.size() : 0);
}

void SimpleTesselatedTetraTopologicalMapping::swap_output_tetrahedra(unsigned a, unsigned b) {
  auto& src = tetra_source.edit();
  auto& children = tetrahedra_mapped_from_tetra.edit();
  if (a >= src.size() || b >= src.size()) return;
  const unsigned as = src[a], bs = src[b];
  src[a] = bs;
  src[b] = as;
  // SOFA renames the first matching child of each parent, one after the other (when both have
  // the same parent, the second rename can undo the first: kept).
  if (as != kNone && as < children.size())
    for (unsigned& c : children[as])
      if (c == a) {
        c = b;
        break;
      }
  if (bs != kNone && bs < children.size())
    for (unsigned& c : children[bs])
      if (c == b) {
        c = a;
        break;
      }
}

void SimpleTesselatedTetraTopologicalMapping::remove_output_tetrahedra(const std::vector<unsigned>& removed) {
  auto& src = tetra_source.edit();
  auto& children = tetrahedra_mapped_from_tetra.edit();
  unsigned last = static_cast<unsigned>(src.size()) - 1u;
  for (unsigned r : removed) {
    swap_output_tetrahedra(r, last);
    const unsigned source = last < src.size() ? src[last] : kNone;
    // SOFA moves `last` down only for an output tetrahedron that has a source.
    if (source != kNone && source < children.size()) {
      int left = 0;
      for (unsigned& c : children[source]) {
        if (c == last) c = kNone;
        else if (c != kNone) ++left;
      }
      if (left == 0) tetrahedra_to_remove_.insert(source);
      else
        msg_info("source tetrahedron " + std::to_string(source) + " now has " + std::to_string(left) +
                 " / 8 children");
      --last;
    }
  }
  src.resize(src.size() >= removed.size() ? src.size() - removed.size() : 0);
}

void register_simple_tesselated_tetra_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "SimpleTesselatedTetraTopologicalMapping";
  info.category = "TopologyMapping";
  info.description =
      "Special case of mapping where TetrahedronSetTopology is converted into a finer TetrahedronSetTopology";
  info.create = creator<SimpleTesselatedTetraTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
