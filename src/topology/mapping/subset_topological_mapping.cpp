#include "topology/mapping/subset_topological_mapping.h"

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <string>

#include "core/registry.h"
#include "topology/dynamic/point_set_topology_modifier.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew {
namespace {

constexpr unsigned kNone = SubsetTopologicalMapping::kNone;

// An element's vertices in increasing order: the key that ignores their order.
template <std::size_t N>
std::array<unsigned, N> sorted(std::array<unsigned, N> a) {
  std::sort(a.begin(), a.end());
  return a;
}

// The element's vertices through a point map (unchanged when the map is empty, as with samePoints).
template <std::size_t N>
std::array<unsigned, N> through(std::array<unsigned, N> a, const std::vector<unsigned>& map) {
  if (!map.empty())
    for (unsigned& v : a) v = v < map.size() ? map[v] : kNone;
  return a;
}

// Pairs each destination element with the source element of the same vertices (the last one
// when the source repeats an element, as SOFA's map keeps it). Reports the unpaired ones.
template <std::size_t N>
void pair_elements(const std::vector<std::array<unsigned, N>>& src, const std::vector<std::array<unsigned, N>>& dst,
                   const std::vector<unsigned>& point_d2s, std::vector<unsigned>& s2d, std::vector<unsigned>& d2s,
                   const char* what, const Component& owner) {
  std::map<std::array<unsigned, N>, unsigned> by_vertices;
  for (std::size_t s = 0; s < src.size(); ++s) {
    by_vertices[sorted(src[s])] = static_cast<unsigned>(s);
    s2d[s] = kNone;
  }
  for (std::size_t d = 0; d < dst.size(); ++d) {
    const auto it = by_vertices.find(sorted(through(dst[d], point_d2s)));
    if (it == by_vertices.end()) {
      owner.msg_error(std::string(what) + " " + std::to_string(d) + " not found in source topology");
      d2s[d] = kNone;
    } else {
      d2s[d] = it->second;
      s2d[it->second] = static_cast<unsigned>(d);
    }
  }
}

// Whether a removal of `removed` (decreasing) applies to a map of `size` entries.
bool removal_fits(const std::vector<unsigned>& removed, std::size_t size) {
  return removed.size() <= size && (removed.empty() || removed.front() < size);
}

// The source removes `removed` (decreasing; removal_fits): each slot takes the last element. The source →
// destination map does the same; the removed elements' partners lose their source and the moved
// element's partner follows it.
void remove_from_source(const std::vector<unsigned>& removed, std::vector<unsigned>& s2d, std::vector<unsigned>& d2s) {
  std::size_t last = s2d.size() - 1;
  for (unsigned s : removed) {
    const unsigned d = s2d[s];
    if (d != kNone && d < d2s.size()) d2s[d] = kNone;
    const unsigned d_last = s2d[last];
    s2d[s] = d_last;
    if (d_last != kNone && d_last < d2s.size() && d2s[d_last] == last) d2s[d_last] = s;
    --last;
  }
  s2d.resize(s2d.size() - removed.size());
}

// The destination removes `removed` (decreasing): the same on the other side. Each removed
// element must have lost its source already.
void remove_from_destination(const std::vector<unsigned>& removed, std::vector<unsigned>& s2d,
                             std::vector<unsigned>& d2s, const char* what, const Component& owner) {
  if (!removal_fits(removed, d2s.size())) return;
  std::size_t last = d2s.size() - 1;
  for (unsigned d : removed) {
    if (d2s[d] != kNone) owner.msg_error(std::string("Invalid ") + what + " Remove");
    const unsigned s_last = d2s[last];
    d2s[d] = s_last;
    if (s_last != kNone && s_last < s2d.size() && s2d[s_last] == last) s2d[s_last] = d;
    --last;
  }
  d2s.resize(d2s.size() - removed.size());
}

// The destination elements of removed source elements (those that have one), decreasing: the
// order the destination's container removes them in. (SOFA walks its maps in source order for
// edges and triangles, which can differ from the container's and then garbles them.)
std::vector<unsigned> partners_of(const std::vector<unsigned>& removed, const std::vector<unsigned>& s2d) {
  std::vector<unsigned> out;
  for (unsigned s : removed)
    if (s < s2d.size() && s2d[s] != kNone) out.push_back(s2d[s]);
  std::sort(out.begin(), out.end(), std::greater<unsigned>());
  return out;
}

// Whether every ancestor of new element i that weighs (non-zero coefficient) has a partner.
bool ancestors_inside(const TopologyChange& c, std::size_t i, const std::vector<unsigned>& s2d) {
  if (i >= c.ancestors.size()) return true;
  for (std::size_t a = 0; a < c.ancestors[i].size(); ++a) {
    if (c.coefficients[i][a] == 0.0) continue;
    const unsigned anc = c.ancestors[i][a];
    if (anc >= s2d.size() || s2d[anc] == kNone) return false;
  }
  return true;
}

// New element i's weighing ancestors through the map, appended as one row (with their weights).
void translate_ancestors(const TopologyChange& c, std::size_t i, const std::vector<unsigned>& s2d,
                         std::vector<std::vector<unsigned>>& ancestors, std::vector<std::vector<double>>& coefficients) {
  ancestors.emplace_back();
  coefficients.emplace_back();
  if (i >= c.ancestors.size()) return;
  for (std::size_t a = 0; a < c.ancestors[i].size(); ++a) {
    if (c.coefficients[i][a] == 0.0) continue;
    ancestors.back().push_back(s2d[c.ancestors[i][a]]);
    coefficients.back().push_back(c.coefficients[i][a]);
  }
}

// New source elements `added` (their vertices `elements[i]`): those whose vertices and weighted
// ancestors all have partners join the destination, appended in order; their ancestors are
// translated. Fills `out`, `out_ancestors`, `out_coefficients` for the destination's modifier.
template <std::size_t N>
void add_from_source(const TopologyChange& c, const std::vector<std::array<unsigned, N>>& elements,
                     const std::vector<unsigned>& point_s2d, std::vector<unsigned>& s2d, std::vector<unsigned>& d2s,
                     std::vector<std::array<unsigned, N>>& out, std::vector<std::vector<unsigned>>& out_ancestors,
                     std::vector<std::vector<double>>& out_coefficients) {
  const bool with_ancestors = !c.ancestors.empty();
  std::size_t grow = s2d.size();
  for (unsigned s : c.indices) grow = std::max<std::size_t>(grow, s + 1u);
  s2d.resize(grow, kNone);
  for (std::size_t i = 0; i < c.indices.size(); ++i) {
    const unsigned s = c.indices[i];
    s2d[s] = kNone;
    if (s >= elements.size()) continue;
    const std::array<unsigned, N> data = through(elements[s], point_s2d);
    const bool inside = std::find(data.begin(), data.end(), kNone) == data.end() &&
                        (!with_ancestors || ancestors_inside(c, i, s2d));
    if (!inside) continue;
    const auto d = static_cast<unsigned>(d2s.size());
    out.push_back(data);
    d2s.push_back(s);
    s2d[s] = d;
    if (with_ancestors) translate_ancestors(c, i, s2d, out_ancestors, out_coefficients);
  }
}

}  // namespace

void SubsetTopologicalMapping::init() {
  if (!check_links(false, ElementType::point, ElementType::point)) return;
  const MeshTopologyBase& src = *input;
  MeshContainer& dst = *output;
  const std::size_t nps = src.nb_points(), npd = dst.nb_points();
  std::vector<unsigned> ps2d, pd2s;
  if (!same_points.value()) {
    ps2d.assign(nps, 0);
    pd2s.assign(npd, 0);
    if (src.has_positions() && dst.has_positions()) {
      // Points pair by exactly equal positions.
      std::map<std::array<double, 3>, unsigned> by_position;
      for (std::size_t s = 0; s < nps; ++s) {
        const Vec3 p = src.point(s);
        by_position[{p[0], p[1], p[2]}] = static_cast<unsigned>(s);
        ps2d[s] = kNone;
      }
      for (std::size_t d = 0; d < npd; ++d) {
        const Vec3 p = dst.point(d);
        const auto it = by_position.find({p[0], p[1], p[2]});
        if (it == by_position.end()) {
          msg_error("Point " + std::to_string(d) + " not found in source topology");
          pd2s[d] = kNone;
        } else {
          pd2s[d] = it->second;
          ps2d[it->second] = static_cast<unsigned>(d);
        }
      }
    } else if (nps == npd) {
      for (std::size_t d = 0; d < npd; ++d) pd2s[d] = ps2d[d] = static_cast<unsigned>(d);
    } else {
      msg_error("If topologies do not have the same number of points then they must have associated positions");
      set_state(ComponentState::invalid);
      return;
    }
  }
  point_s2d.set(ps2d);
  point_d2s.set(pd2s);

  // One kind of element: maps sized when handled, filled when both sides have elements.
  auto pair_kind = [&](bool handled, const auto& s_elems, const auto& d_elems, Field<std::vector<unsigned>>& s2d_f,
                       Field<std::vector<unsigned>>& d2s_f, const char* what) {
    std::vector<unsigned> s2d, d2s;
    if (handled) {
      s2d.assign(s_elems.size(), 0);
      d2s.assign(d_elems.size(), 0);
      if (!s_elems.empty() && !d_elems.empty()) pair_elements(s_elems, d_elems, pd2s, s2d, d2s, what, *this);
    }
    s2d_f.set(std::move(s2d));
    d2s_f.set(std::move(d2s));
  };
  pair_kind(handle_edges.value(), src.edges(), dst.edges(), edge_s2d, edge_d2s, "Edge");
  pair_kind(handle_triangles.value(), src.triangles(), dst.triangles(), triangle_s2d, triangle_d2s, "Triangle");
  pair_kind(handle_quads.value(), src.quads(), dst.quads(), quad_s2d, quad_d2s, "Quad");
  pair_kind(handle_tetrahedra.value(), src.tetrahedra(), dst.tetrahedra(), tetrahedron_s2d, tetrahedron_d2s,
            "Tetrahedron");
  pair_kind(handle_hexahedra.value(), src.hexahedra(), dst.hexahedra(), hexahedron_s2d, hexahedron_d2s,
            "Hexahedron");

  auto count = [](const char* kind, std::size_t s, std::size_t d) {
    return std::string(" ") + kind + ": " + std::to_string(s) + "->" + std::to_string(d);
  };
  if (!same_points.value()) msg_info(count("P", nps, npd));
  if (handle_edges.value()) msg_info(count("E", src.edges().size(), dst.edges().size()));
  if (handle_triangles.value()) msg_info(count("T", src.triangles().size(), dst.triangles().size()));
  if (handle_quads.value()) msg_info(count("Q", src.quads().size(), dst.quads().size()));
  if (handle_tetrahedra.value()) msg_info(count("TE", src.tetrahedra().size(), dst.tetrahedra().size()));
  if (handle_hexahedra.value()) msg_info(count("HE", src.hexahedra().size(), dst.hexahedra().size()));
  // The output's element lists are complete: its derived lists are rebuilt from them.
  dst.init();
}

bool SubsetTopologicalMapping::input_elements(unsigned out, std::vector<unsigned>& in) const {
  const Field<std::vector<unsigned>>* maps[] = {
      handle_hexahedra.value() ? &hexahedron_d2s : nullptr, handle_tetrahedra.value() ? &tetrahedron_d2s : nullptr,
      handle_quads.value() ? &quad_d2s : nullptr,           handle_triangles.value() ? &triangle_d2s : nullptr,
      handle_edges.value() ? &edge_d2s : nullptr,           !same_points.value() ? &point_d2s : nullptr};
  for (const auto* m : maps) {
    if (!m || m->value().empty()) continue;
    if (out < m->value().size() && m->value()[out] != kNone) in.push_back(m->value()[out]);
    return true;
  }
  in.push_back(out);
  return true;
}

void SubsetTopologicalMapping::update_top_down() {
  if (!input || !output || state() != ComponentState::valid) return;
  auto* points = find_from_output<PointSetTopologyModifier>();
  if (!points) {
    msg_error("No PointSetTopologyModifier found for target topology.");
    return;
  }
  // Handlers below queue events on the output only; the input's list is stable here.
  const std::vector<TopologyChange> changes = input->topology_changes();
  for (const TopologyChange& c : changes) {
    switch (c.type) {
      case TopologyChangeType::ending: points->notify_ending_event(); break;
      case TopologyChangeType::points_added: on_points_added(c); break;
      case TopologyChangeType::points_removed: on_points_removed(c); break;
      case TopologyChangeType::edges_added: on_edges_added(c); break;
      case TopologyChangeType::edges_removed: on_edges_removed(c); break;
      case TopologyChangeType::triangles_added: on_triangles_added(c); break;
      case TopologyChangeType::triangles_removed: on_triangles_removed(c); break;
      default: msg_error("Unknown topological change (quads, tetrahedra and hexahedra are not followed)"); break;
    }
  }
}

void SubsetTopologicalMapping::on_points_added(const TopologyChange& c) {
  auto* points = find_from_output<PointSetTopologyModifier>();
  const auto n = static_cast<unsigned>(c.indices.size());
  if (same_points.value()) {
    points->add_points(n);
    return;
  }
  std::vector<unsigned> s2d = point_s2d.value(), d2s = point_d2s.value();
  const std::size_t first = s2d.size();
  s2d.resize(first + n, kNone);
  const bool with_ancestors = !c.ancestors.empty();
  std::vector<std::vector<unsigned>> ancestors;
  std::vector<std::vector<double>> coefficients;
  unsigned added = 0;
  for (unsigned i = 0; i < n; ++i) {
    const std::size_t s = first + i;
    if (with_ancestors && !ancestors_inside(c, i, s2d)) continue;
    s2d[s] = static_cast<unsigned>(d2s.size());
    d2s.push_back(static_cast<unsigned>(s));
    if (with_ancestors) translate_ancestors(c, i, s2d, ancestors, coefficients);
    ++added;
  }
  point_s2d.set(std::move(s2d));
  point_d2s.set(std::move(d2s));
  if (added > 0) points->add_points(added, std::move(ancestors), std::move(coefficients), true);
}

namespace {

// One kind's maps following a removal from the input: the input side first, then (when some
// removed elements had partners) `remove` takes those partners out of the output and the output
// side follows. Refused, with an error, when the maps do not cover the removed indices.
template <class Remove>
void follow_removal(const TopologyChange& c, Field<std::vector<unsigned>>& s2d_f, Field<std::vector<unsigned>>& d2s_f,
                    const char* what, const Component& owner, Remove&& remove) {
  std::vector<unsigned> s2d = s2d_f.value(), d2s = d2s_f.value();
  if (!removal_fits(c.indices, s2d.size())) {
    owner.msg_error(std::string(what) + "s removed from the input are not in this mapping's maps (the input changed "
                                        "before init?): not followed");
    return;
  }
  const std::vector<unsigned> gone = partners_of(c.indices, s2d);
  remove_from_source(c.indices, s2d, d2s);
  s2d_f.set(s2d);
  d2s_f.set(d2s);
  if (gone.empty()) return;
  remove(gone);
  remove_from_destination(gone, s2d, d2s, what, owner);
  s2d_f.set(std::move(s2d));
  d2s_f.set(std::move(d2s));
}

// One kind's maps following an addition to the input: `add` receives the elements that join
// the output (vertices in output numbering) with their translated ancestors.
template <std::size_t N, class Add>
void follow_addition(const TopologyChange& c, const std::vector<std::array<unsigned, N>>& elements,
                     const std::vector<unsigned>& point_s2d, Field<std::vector<unsigned>>& s2d_f,
                     Field<std::vector<unsigned>>& d2s_f, Add&& add) {
  std::vector<unsigned> s2d = s2d_f.value(), d2s = d2s_f.value();
  std::vector<std::array<unsigned, N>> out;
  std::vector<std::vector<unsigned>> ancestors;
  std::vector<std::vector<double>> coefficients;
  add_from_source(c, elements, point_s2d, s2d, d2s, out, ancestors, coefficients);
  s2d_f.set(std::move(s2d));
  d2s_f.set(std::move(d2s));
  if (!out.empty()) add(out, std::move(ancestors), std::move(coefficients));
}

}  // namespace

void SubsetTopologicalMapping::on_points_removed(const TopologyChange& c) {
  auto* points = find_from_output<PointSetTopologyModifier>();
  if (same_points.value()) {
    points->remove_points(c.indices, true);
    return;
  }
  follow_removal(c, point_s2d, point_d2s, "Point", *this,
                 [&](const std::vector<unsigned>& gone) { points->remove_points(gone, true); });
}

void SubsetTopologicalMapping::on_edges_added(const TopologyChange& c) {
  if (!handle_edges.value()) return;
  auto* edges = find_from_output<EdgeSetTopologyModifier>();
  if (!edges) return;
  follow_addition(c, input->edges(), point_s2d.value(), edge_s2d, edge_d2s, [&](auto& out, auto anc, auto coef) {
    edges->add_edges(out, std::move(anc), std::move(coef));
  });
}

void SubsetTopologicalMapping::on_edges_removed(const TopologyChange& c) {
  if (!handle_edges.value()) return;
  auto* edges = find_from_output<EdgeSetTopologyModifier>();
  if (!edges) return;
  follow_removal(c, edge_s2d, edge_d2s, "Edge", *this,
                 [&](const std::vector<unsigned>& gone) { edges->remove_edges(gone, false); });
}

void SubsetTopologicalMapping::on_triangles_added(const TopologyChange& c) {
  if (!handle_triangles.value()) return;
  auto* triangles = find_from_output<TriangleSetTopologyModifier>();
  if (!triangles) return;
  follow_addition(c, input->triangles(), point_s2d.value(), triangle_s2d, triangle_d2s,
                  [&](auto& out, auto anc, auto coef) { triangles->add_triangles(out, std::move(anc), std::move(coef)); });
}

void SubsetTopologicalMapping::on_triangles_removed(const TopologyChange& c) {
  if (!handle_triangles.value()) return;
  auto* triangles = find_from_output<TriangleSetTopologyModifier>();
  if (!triangles) return;
  // Edges left without a triangle go too unless edges are followed on their own.
  follow_removal(c, triangle_s2d, triangle_d2s, "Triangle", *this, [&](const std::vector<unsigned>& gone) {
    triangles->remove_triangles(gone, !handle_edges.value(), false);
  });
}

void register_subset_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "SubsetTopologicalMapping";
  info.category = "TopologyMapping";
  info.description =
      "TopologicalMapping where the destination topology is a subset of the source topology (both set up by the "
      "scene)";
  info.create = creator<SubsetTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
