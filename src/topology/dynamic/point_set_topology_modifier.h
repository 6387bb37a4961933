// PointSetTopologyModifier: Topology modifier dedicated to a point topology,
// and the base of the dynamic modifiers: it finds its container at init and
// carries topological changes (spec/interaction.md §7.2, core/topology_change.h).
//
// A removal is warn → propagate → process: the events are queued on the
// container (indices sorted in decreasing order), propagated (the container's
// handlers, then a top-down visit from this modifier's node: topological
// mappings whose input is the container, then every object's
// handle_topology_change, then the children), and only then applied to the
// arrays (topology/dynamic/element_removal.h). Elements left isolated are
// removed the same way, in SOFA's cascade order; with `propagateToDOF` the
// states of the subtree that use the container lose the removed points too.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class MeshContainer;
class PointSetTopologyContainer;

class PointSetTopologyModifier : public TopologyObject {
 public:
  Field<bool> propagate_to_dof{this, "propagateToDOF", true, "apply point additions/removals to the node's state",
                               "Topology"};

  void init() override;
  void bwd_init() override;
  // The container this modifier edits (first of the node, else of its ancestors).
  MeshContainer* container() const { return container_; }

  // SOFA's removeItems for this modifier's element kind (ids in any order). Indices out of
  // range are skipped with a warning naming them; false with `why` when this modifier has no
  // container.
  virtual bool remove_items(const std::vector<unsigned>& ids, std::string* why);
  // Removes points (expected isolated: elements using them are not removed); with `remove_dof`
  // the states using the container follow.
  void remove_points(std::vector<unsigned> ids, bool remove_dof);
  // SOFA's addPoints: the container grows by n points (process); with `add_dof` the states of
  // the subtree using the container grow (new DoFs interpolated from `ancestors` with
  // `coefficients`, see MechanicalState::add_points); then a points-added event carrying both is
  // propagated. Rows are empty or one per new point; ancestors out of range are refused with an
  // error (nothing added).
  bool add_points(unsigned n, std::vector<std::vector<unsigned>> ancestors = {},
                  std::vector<std::vector<double>> coefficients = {}, bool add_dof = true);
  // SOFA's movePointsProcess for the states: each point of `ids` (distinct) takes, in every vector
  // of the states of the subtree using the container, Σ coefficient · ancestor value. No
  // topological event: the elements are unchanged (SOFA's TrianglesMoved events are not relayed;
  // force fields rebuilding on element changes read the moved rest positions then).
  bool move_points(const std::vector<unsigned>& ids, const std::vector<std::vector<unsigned>>& ancestors,
                   const std::vector<std::vector<double>>& coefficients);
  // Sends the queued events (plus the ending event) to handlers and the subtree, then clears them.
  void propagate_topological_changes();
  // SOFA's notifyEndingEvent: propagates a lone ending event (a topological mapping relays the
  // end of its input's list this way).
  void notify_ending_event();

 protected:
  // Whether `c` is a container this modifier can edit.
  virtual bool accepts(const Component& c) const;
  virtual const char* container_kind() const { return "PointSetTopologyContainer"; }

  PointSetTopologyContainer* dynamic_container() const;
  // Keeps ids < count (warning for the others, naming this modifier), distinct, sorted decreasing.
  std::vector<unsigned> checked_ids(std::vector<unsigned> ids, std::size_t count, const char* what);
  // Queues one event on the container.
  void warn(TopologyChangeType type, const std::vector<unsigned>& decreasing);
  void warn(TopologyChange change);
  // The process step of point removal (arrays, then the states when `remove_dof`).
  void remove_points_process(const std::vector<unsigned>& decreasing, bool remove_dof);
  // Warn, propagate and process the isolated points a removal found (any order, distinct).
  void cascade_isolated_points(std::vector<unsigned> points);

 private:
  MeshContainer* container_ = nullptr;
};

}  // namespace sinew
