#include "topology/dynamic/point_set_topology_modifier.h"

#include <algorithm>
#include <functional>

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/element_addition.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "topology/mapping/topological_mapping.h"

namespace sinew {

void PointSetTopologyModifier::init() {
  container_ = nullptr;
  // SOFA: getContext()->get(container), i.e. this node first, then its ancestors.
  for (Node* n = node(); n && !container_; n = n->parent())
    for (const auto& o : n->objects())
      if (accepts(*o)) {
        container_ = static_cast<MeshContainer*>(static_cast<PointSetTopologyContainer*>(o.get()));
        break;
      }
  if (!container_) {
    msg_error(std::string("no ") + container_kind() + " found in this node or its ancestors");
    set_state(ComponentState::invalid);
  }
}

// After every init (the mappings that fill containers included): the container's neighbourhood
// arrays become the live ones the removals edit, so that the first cut does not pay for building
// and copying them (≈ 0.2 s on 100k tetrahedra). They are copies of the sorted cache: queries
// answer the same until something changes.
void PointSetTopologyModifier::bwd_init() {
  PointSetTopologyContainer* c = container_ ? dynamic_container() : nullptr;
  if (!c || state() != ComponentState::valid) return;
  c->begin_edit();
  c->end_edit(false, false, false);
}

bool PointSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const PointSetTopologyContainer*>(&c) != nullptr; }

PointSetTopologyContainer* PointSetTopologyModifier::dynamic_container() const {
  return static_cast<PointSetTopologyContainer*>(container_);
}

std::vector<unsigned> PointSetTopologyModifier::checked_ids(std::vector<unsigned> ids, std::size_t count,
                                                            const char* what) {
  std::vector<unsigned> out;
  out.reserve(ids.size());
  for (unsigned i : ids) {
    if (i >= count) msg_warning(std::string(what) + " " + std::to_string(i) + " is out of bounds (" +
                                std::to_string(count) + ") and is not removed");
    else out.push_back(i);
  }
  std::sort(out.begin(), out.end(), std::greater<unsigned>());
  const auto dup = std::unique(out.begin(), out.end());
  if (dup != out.end()) {
    msg_warning(std::string("a ") + what + " index is listed more than once; it is removed once");
    out.erase(dup, out.end());
  }
  return out;
}

void PointSetTopologyModifier::warn(TopologyChangeType type, const std::vector<unsigned>& decreasing) {
  container_->edit_topology_changes().push_back(TopologyChange{type, decreasing, {}, {}});
}

void PointSetTopologyModifier::warn(TopologyChange change) {
  container_->edit_topology_changes().push_back(std::move(change));
}

namespace {
// SOFA's TopologyChangeVisitor, top-down from the modifier's node.
void visit_topology_change(Node& top, MeshTopologyBase& source) {
  traverse(
      top,
      [&](Node& n, bool) {
        for (const auto& o : n.objects())
          if (auto* tm = dynamic_cast<TopologicalMapping*>(o.get()); tm && tm->input.get() == &source)
            tm->update_top_down();
        for (const auto& o : n.objects()) o->handle_topology_change(source);
        return Visit::descend;
      },
      // SOFA's TopologyChangeVisitor::processNodeBottomUp: mappings whose output is the source.
      [&](Node& n) {
        for (const auto& o : n.objects())
          if (auto* tm = dynamic_cast<TopologicalMapping*>(o.get());
              tm && tm->output.get() && static_cast<MeshTopologyBase*>(tm->output.get()) == &source)
            tm->update_bottom_up();
      });
}

// SOFA's StateChangeVisitor: the states of the subtree whose topology is `source` lose the
// points; a node under a mapping that does not keep the points (not sameTopology) is pruned.
// Each state once (traverse()); `f` runs on the states reached.
template <class F>
void visit_states(Node& top, MeshTopologyBase& source, F&& f) {
  traverse(top, [&](Node& n, bool pruned) {
    if (pruned) return Visit::prune;
    if (&n != &top && n.mechanical_mapping && !n.mechanical_mapping->same_topology()) return Visit::prune;
    if (n.mechanical_state && n.get_mesh_topology_link() == &source) f(*n.mechanical_state);
    return Visit::descend;
  });
}

void visit_state_change(Node& top, MeshTopologyBase& source, const std::vector<unsigned>& decreasing) {
  visit_states(top, source, [&](MechanicalState& s) { s.remove_points(decreasing); });
}

// The same visit for point additions.
void visit_state_add(Node& top, MeshTopologyBase& source, unsigned count,
                     const std::vector<std::vector<unsigned>>& ancestors,
                     const std::vector<std::vector<double>>& coefficients) {
  visit_states(top, source, [&](MechanicalState& s) { s.add_points(count, ancestors, coefficients); });
}
}  // namespace

bool PointSetTopologyModifier::add_points(unsigned n, std::vector<std::vector<unsigned>> ancestors,
                                          std::vector<std::vector<double>> coefficients, bool add_dof) {
  if (!container_ || n == 0) return false;
  const unsigned before = static_cast<unsigned>(container_->nb_points());
  if (!ancestors.empty() && ancestors.size() != n) {
    msg_error("addPoints: " + std::to_string(ancestors.size()) + " ancestor rows for " + std::to_string(n) +
              " points; nothing added");
    return false;
  }
  for (const auto& row : ancestors)
    for (unsigned a : row)
      if (a >= before) {
        msg_error("addPoints: ancestor " + std::to_string(a) + " is out of bounds (" + std::to_string(before) +
                  " points); nothing added");
        return false;
      }
  PointSetTopologyContainer& c = *dynamic_container();
  topo::DynamicMesh& m = c.begin_edit();
  topo::add_points_process(m, n);
  c.end_edit(false, false, false);
  if (add_dof && node()) visit_state_add(*node(), c, n, ancestors, coefficients);
  TopologyChange added{TopologyChangeType::points_added, {}, std::move(ancestors), std::move(coefficients)};
  for (unsigned i = 0; i < n; ++i) added.indices.push_back(before + i);
  warn(std::move(added));
  propagate_topological_changes();
  return true;
}

namespace {
// SOFA's movePointsProcess on the states (POINTSMOVED state change): each moved DoF, in every
// vector, becomes the weighted sum of its ancestors'. MechanicalState has no in-place move, so the
// new values are appended (add_points interpolates every allocated vector) and the moved slots
// removed: removal moves the last DoF into each slot in decreasing order, so appending in
// increasing slot order puts each value in its slot.
void visit_state_move(Node& top, MeshTopologyBase& source, const std::vector<unsigned>& increasing,
                      const std::vector<std::vector<unsigned>>& ancestors,
                      const std::vector<std::vector<double>>& coefficients) {
  visit_states(top, source, [&](MechanicalState& s) {
    s.add_points(increasing.size(), ancestors, coefficients);
    s.remove_points(std::vector<unsigned>(increasing.rbegin(), increasing.rend()));
  });
}

}  // namespace

bool PointSetTopologyModifier::move_points(const std::vector<unsigned>& ids,
                                           const std::vector<std::vector<unsigned>>& ancestors,
                                           const std::vector<std::vector<double>>& coefficients) {
  if (!container_ || ids.empty() || !node()) return false;
  const std::size_t np = container_->nb_points();
  if (ancestors.size() != ids.size() || coefficients.size() != ids.size()) {
    msg_error("movePoints: one ancestor row and one coefficient row per moved point are needed; nothing moved");
    return false;
  }
  std::vector<std::size_t> order(ids.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
  std::vector<unsigned> increasing;
  std::vector<std::vector<unsigned>> anc;
  std::vector<std::vector<double>> coef;
  for (std::size_t k : order) {
    if (ids[k] >= np || (!increasing.empty() && increasing.back() == ids[k])) {
      msg_error("movePoints: point " + std::to_string(ids[k]) + " is out of bounds or repeated; nothing moved");
      return false;
    }
    for (unsigned a : ancestors[k])
      if (a >= np) {
        msg_error("movePoints: ancestor " + std::to_string(a) + " is out of bounds; nothing moved");
        return false;
      }
    increasing.push_back(ids[k]);
    anc.push_back(ancestors[k]);
    coef.push_back(coefficients[k]);
  }
  visit_state_move(*node(), *container_, increasing, anc, coef);
  return true;
}

void PointSetTopologyModifier::propagate_topological_changes() {
  auto& changes = container_->edit_topology_changes();
  if (changes.empty()) return;
  changes.push_back(TopologyChange{TopologyChangeType::ending, {}, {}, {}});
  // A handler may detach itself (or another) while it runs: iterate over a copy.
  const std::vector<TopologyHandler*> handlers = container_->topology_handlers();
  for (TopologyHandler* h : handlers)
    if (h->attached() == container_)
      for (const TopologyChange& c : changes) h->apply(*container_, c);
  if (node()) visit_topology_change(*node(), *container_);
  container_->edit_topology_changes().clear();
}

void PointSetTopologyModifier::notify_ending_event() {
  if (!container_) return;
  // The list is empty here (a propagation clears it); propagate sends {ending} alone.
  auto& changes = container_->edit_topology_changes();
  if (!changes.empty()) {
    propagate_topological_changes();
    return;
  }
  const std::vector<TopologyHandler*> handlers = container_->topology_handlers();
  const TopologyChange end{TopologyChangeType::ending, {}, {}, {}};
  changes.push_back(end);
  for (TopologyHandler* h : handlers)
    if (h->attached() == container_) h->apply(*container_, end);
  if (node()) visit_topology_change(*node(), *container_);
  container_->edit_topology_changes().clear();
}

void PointSetTopologyModifier::remove_points_process(const std::vector<unsigned>& decreasing, bool remove_dof) {
  PointSetTopologyContainer& c = *dynamic_container();
  topo::DynamicMesh& m = c.begin_edit();
  topo::remove_points_process(m, decreasing);
  c.end_edit(!m.edges->empty(), !m.triangles->empty(), !m.tetrahedra->empty(), !m.quads->empty(),
             !m.hexahedra->empty());
  if (remove_dof && node()) visit_state_change(*node(), c, decreasing);
}

void PointSetTopologyModifier::remove_points(std::vector<unsigned> ids, bool remove_dof) {
  if (!container_) return;
  const std::vector<unsigned> d = checked_ids(std::move(ids), container_->nb_points(), "point");
  if (d.empty()) return;
  warn(TopologyChangeType::points_removed, d);
  propagate_topological_changes();
  remove_points_process(d, remove_dof);
}

void PointSetTopologyModifier::cascade_isolated_points(std::vector<unsigned> points) {
  if (points.empty()) return;
  // A point is isolated when no element of the container uses it. A removal finds candidates
  // through its own kind's shells; lists of another kind the container also holds (a hexahedral
  // container given a grid's triangles and diagonal edges by src=@grid, which SOFA never
  // updates) may still use one: it stays, rather than leaving those elements dangling.
  if (PointSetTopologyContainer* c = dynamic_container()) {
    const topo::DynamicMesh& m = c->begin_edit();
    auto used = [&](unsigned v) {
      for (const auto* shells : {&m.edges_around_vertex, &m.triangles_around_vertex, &m.quads_around_vertex,
                                 &m.tetrahedra_around_vertex, &m.hexahedra_around_vertex})
        if (v < shells->size() && !(*shells)[v].empty()) return true;
      return false;
    };
    std::erase_if(points, used);
    if (points.empty()) return;
  }
  std::sort(points.begin(), points.end(), std::greater<unsigned>());
  warn(TopologyChangeType::points_removed, points);
  propagate_topological_changes();
  remove_points_process(points, propagate_to_dof.value());
}

bool PointSetTopologyModifier::remove_items(const std::vector<unsigned>& ids, std::string* why) {
  if (!container_) {
    if (why) *why = "the modifier has no container";
    return false;
  }
  remove_points(ids, propagate_to_dof.value());
  return true;
}

void register_point_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "PointSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to a point topology";
  info.create = creator<PointSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
