#include "topology/mapping/triangle2_edge_topological_mapping.h"

#include <algorithm>
#include <functional>

#include "core/registry.h"
#include "topology/dynamic/edge_set_topology_modifier.h"

namespace sinew {

void Triangle2EdgeTopologicalMapping::init() {
  modifier_ = nullptr;
  if (!check_links(true, ElementType::triangle, ElementType::edge)) return;
  modifier_ = find_from_output<EdgeSetTopologyModifier>();
  if (!modifier_) {
    msg_error("No EdgeSetTopologyModifier found in the Edge topology Node.");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<Edge> edges = input->edges();
  const auto& around = input->triangles_around_edge();
  const std::size_t np = input->nb_points();
  output->clear_topology();
  output->set_nb_points(np);
  loc2glob_.clear();
  glob2loc_.assign(edges.size(), kUnmapped);
  std::vector<Edge> out;
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (i < around.size() && around[i].size() == 1) {
      out.push_back(edges[i]);
      glob2loc_[i] = static_cast<unsigned>(loc2glob_.size());
      loc2glob_.push_back(static_cast<unsigned>(i));
    }
  output->edges_f.set(std::move(out));
  output->init();
}

void Triangle2EdgeTopologicalMapping::set_glob2loc(unsigned glob, unsigned loc) {
  if (glob >= glob2loc_.size()) glob2loc_.resize(glob + 1u, kUnmapped);
  glob2loc_[glob] = loc;
}

void Triangle2EdgeTopologicalMapping::update_top_down() {
  if (!input || !output || !modifier_ || state() != ComponentState::valid) return;
  // Handlers below may queue events on the output only; the input's list is stable here.
  const std::vector<TopologyChange> changes = input->topology_changes();
  for (const TopologyChange& c : changes) {
    switch (c.type) {
      case TopologyChangeType::ending: modifier_->notify_ending_event(); break;
      case TopologyChangeType::edges_removed: on_edges_removed(c.indices); break;
      case TopologyChangeType::triangles_removed: on_triangles_removed(c.indices); break;
      case TopologyChangeType::triangles_added: on_triangles_added(c.indices); break;
      case TopologyChangeType::points_removed: modifier_->remove_points(c.indices, false); break;
      case TopologyChangeType::points_added:
        modifier_->add_points(static_cast<unsigned>(c.indices.size()), c.ancestors, c.coefficients, false);
        break;
      // EDGESADDED comes with the triangles that bring the edges (handled there).
      default: break;
    }
  }
}

// Input edges removed (received before the input changes; indices decreasing): the input moves
// its last edge into each slot; the maps follow that swap, then the output copy of the removed
// edge goes the same way (its last local edge moves into the slot). One output removal per edge,
// as SOFA does.
void Triangle2EdgeTopologicalMapping::on_edges_removed(const std::vector<unsigned>& removed) {
  unsigned last = static_cast<unsigned>(input->edges().size()) - 1;
  unsigned ind_last = static_cast<unsigned>(output->edges().size());
  for (unsigned k : removed) {
    const unsigned ind_k0 = glob2loc(k);
    if (ind_k0 == kUnmapped) {
      msg_warning("edge " + std::to_string(k) + " removed from the input is not mapped (" +
                  std::to_string(ind_last) + " output edges)");
      --last;
      continue;
    }
    --ind_last;
    const unsigned ind_k = ind_k0;
    const unsigned ind_real_last = glob2loc(last);
    if (ind_real_last != kUnmapped && k != last) {
      // The input's last edge takes slot k: its copy now maps to k; the removed copy to `last`.
      glob2loc_[k] = ind_real_last;
      glob2loc_[last] = ind_k;
      std::swap(loc2glob_[ind_real_last], loc2glob_[ind_k]);
    }
    if (ind_k != ind_last) {
      // The output's last edge will take local slot ind_k.
      const unsigned g_last = loc2glob_[ind_last], g_k = loc2glob_[ind_k];
      glob2loc_[g_last] = ind_k;
      glob2loc_[g_k] = ind_last;
      std::swap(loc2glob_[ind_k], loc2glob_[ind_last]);
    }
    glob2loc_[loc2glob_.back()] = kUnmapped;
    loc2glob_.pop_back();
    modifier_->remove_edges({ind_k}, false);
    --last;
  }
}

// Input triangles removed (received before the input changes): an edge shared with a kept
// triangle becomes boundary and is appended to the output (lower vertex first). Edges left
// without any triangle leave through the edges-removed event that follows.
void Triangle2EdgeTopologicalMapping::on_triangles_removed(const std::vector<unsigned>& removed) {
  const auto& edges_in = input->edges_in_triangle();
  const auto& around = input->triangles_around_edge();
  std::vector<Edge> create;
  for (std::size_t i = 0; i < removed.size(); ++i) {
    const unsigned tri = removed[i];
    if (tri >= edges_in.size()) continue;
    for (unsigned e : edges_in[tri]) {
      const auto& shell = around[e];
      if (shell.size() != 2) continue;
      const unsigned other = shell[0] == tri ? shell[1] : shell[0];
      const auto end = removed.begin() + static_cast<std::ptrdiff_t>(i);
      if (std::find(removed.begin(), end, other) != end) continue;  // handled from the other side
      Edge ne = input->edges()[e];
      if (ne[0] > ne[1]) std::swap(ne[0], ne[1]);
      create.push_back(ne);
      if (glob2loc(e) != kUnmapped) msg_error("edge " + std::to_string(e) + " is already mapped");
      loc2glob_.push_back(e);
      set_glob2loc(e, static_cast<unsigned>(loc2glob_.size() - 1));
    }
  }
  modifier_->add_edges(create);
}

// Input triangles added (received after the input changed): their boundary edges not yet mapped
// are appended first; then mapped edges no longer on the boundary leave (decreasing input
// index, swap-pop of the local list).
void Triangle2EdgeTopologicalMapping::on_triangles_added(const std::vector<unsigned>& added) {
  const auto& edges_in = input->edges_in_triangle();
  const auto& around = input->triangles_around_edge();
  std::vector<Edge> create;
  std::vector<unsigned> stale;
  for (unsigned tri : added) {
    if (tri >= edges_in.size()) continue;
    for (unsigned e : edges_in[tri]) {
      const std::size_t shell = around[e].size();
      if (glob2loc(e) != kUnmapped) {
        if (shell != 1) stale.push_back(e);
        continue;
      }
      if (shell > 1) continue;
      create.push_back(input->edges()[e]);
      loc2glob_.push_back(e);
      set_glob2loc(e, static_cast<unsigned>(loc2glob_.size() - 1));
    }
  }
  modifier_->add_edges(create);

  std::sort(stale.begin(), stale.end(), std::greater<unsigned>());
  std::vector<unsigned> locals;
  for (unsigned g : stale) {
    const unsigned loc = glob2loc(g);
    if (loc == kUnmapped) {
      msg_error("on triangles added: edge " + std::to_string(g) + " is not mapped");
      continue;
    }
    const unsigned last_glob = loc2glob_.back();
    loc2glob_[loc] = last_glob;
    loc2glob_.pop_back();
    glob2loc_[g] = kUnmapped;
    set_glob2loc(last_glob, loc);
    locals.push_back(loc);
  }
  modifier_->remove_edges(locals, true);
}

void register_triangle2_edge_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Triangle2EdgeTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where TriangleSetTopology is converted to EdgeSetTopology";
  info.create = creator<Triangle2EdgeTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
