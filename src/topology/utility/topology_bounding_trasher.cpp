#include "topology/utility/topology_bounding_trasher.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/edge_set_topology_modifier.h"
#include "topology/dynamic/hexahedron_set_topology_modifier.h"
#include "topology/dynamic/quad_set_topology_modifier.h"
#include "topology/dynamic/tetrahedron_set_topology_modifier.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew {
namespace {

// The first modifier of type M from `n` upwards (SOFA's getContext()->get<M>()).
template <class M>
PointSetTopologyModifier* find_modifier(Node* n) {
  return n ? n->find_up<M>() : nullptr;
}

}  // namespace

TopologyBoundingTrasher::TopologyBoundingTrasher()
    : position(this, "position", FlatVec{3, {}},
               "positions of the points (default: those of the topology's node state)", "Topology") {
  listening.set(true);
}

void TopologyBoundingTrasher::init() {
  if (!topology && node()) topology.set(node()->get_mesh_topology_link());
  if (!topology) {
    msg_error("no topology: set the topology link or put one in this node or above");
    set_state(ComponentState::invalid);
    return;
  }
  if (box.get().size() != 6) {
    msg_error("box needs 6 values (xmin ymin zmin xmax ymax zmax), not " + std::to_string(box.get().size()));
    set_state(ComponentState::invalid);
    return;
  }
  const MeshTopologyBase& t = *topology;
  struct Choice {
    bool present;
    ElementType type;
    PointSetTopologyModifier* mod;
    const char* modifier_name;
  };
  // SOFA's order: the highest kind present decides, and its modifier must exist.
  const Choice choices[] = {
      {!t.hexahedra().empty(), ElementType::hexahedron, find_modifier<HexahedronSetTopologyModifier>(node()),
       "HexahedronSetTopologyModifier"},
      {!t.tetrahedra().empty(), ElementType::tetrahedron, find_modifier<TetrahedronSetTopologyModifier>(node()),
       "TetrahedronSetTopologyModifier"},
      {!t.quads().empty(), ElementType::quad, find_modifier<QuadSetTopologyModifier>(node()),
       "QuadSetTopologyModifier"},
      {!t.triangles().empty(), ElementType::triangle, find_modifier<TriangleSetTopologyModifier>(node()),
       "TriangleSetTopologyModifier"},
      {!t.edges().empty(), ElementType::edge, find_modifier<EdgeSetTopologyModifier>(node()),
       "EdgeSetTopologyModifier"},
  };
  kind_ = ElementType::point;
  modifier_ = nullptr;
  for (const Choice& c : choices) {
    if (!c.present) continue;
    if (!c.mod) {
      msg_error(std::string("the topology has ") + element_type_name(c.type) + " elements but no " +
                c.modifier_name + " is found: nothing will be removed");
      return;
    }
    kind_ = c.type;
    modifier_ = c.mod;
    return;
  }
}

namespace {

bool outside(const double* p, const std::vector<double>& b) {
  return p[0] < b[0] || p[0] > b[3] || p[1] < b[1] || p[1] > b[4] || p[2] < b[2] || p[2] > b[5];
}

// Indices of the elements whose barycentre (Σ positions / n, summed in vertex order) is outside.
template <class List>
bool collect_outside(const List& elements, const FlatVec& x, const std::vector<double>& b, std::vector<unsigned>& out) {
  const std::size_t np = x.size(), w = static_cast<std::size_t>(x.width);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    double c[3] = {0, 0, 0};
    for (unsigned v : elements[e]) {
      if (v >= np) return false;
      for (int k = 0; k < 3; ++k) c[k] += x.data[v * w + k];
    }
    const double n = static_cast<double>(elements[e].size());
    for (double& ck : c) ck /= n;
    if (outside(c, b)) out.push_back(static_cast<unsigned>(e));
  }
  return true;
}

}  // namespace

std::size_t TopologyBoundingTrasher::trash() {
  if (state() != ComponentState::valid || !modifier_ || !topology) return 0;
  const MeshTopologyBase& t = *topology;
  FlatVec own;
  const FlatVec* x = &position.get();
  if (x->data.empty()) {
    // Not given: the positions of the state the topology's points belong to.
    MechanicalState* s = t.node() ? t.node()->get_mechanical_state() : nullptr;
    if (!s || s->info().coord_width < 3) return 0;
    own.width = s->info().coord_width;
    own.data = s->read(kPosition);
    x = &own;
  }
  if (x->width < 3) return 0;
  const std::vector<double>& b = box.get();
  outside_.clear();
  bool ok = true;
  switch (kind_) {
    case ElementType::hexahedron: ok = collect_outside(t.hexahedra(), *x, b, outside_); break;
    case ElementType::tetrahedron: ok = collect_outside(t.tetrahedra(), *x, b, outside_); break;
    case ElementType::quad: ok = collect_outside(t.quads(), *x, b, outside_); break;
    case ElementType::triangle: ok = collect_outside(t.triangles(), *x, b, outside_); break;
    case ElementType::edge: ok = collect_outside(t.edges(), *x, b, outside_); break;
    default: return 0;
  }
  if (!ok) {
    msg_warning("position holds fewer points than the topology's elements use; nothing removed");
    return 0;
  }
  if (outside_.empty()) return 0;
  const std::size_t n = outside_.size();
  switch (kind_) {
    case ElementType::hexahedron: static_cast<HexahedronSetTopologyModifier*>(modifier_)->remove_hexahedra(outside_); break;
    case ElementType::tetrahedron: static_cast<TetrahedronSetTopologyModifier*>(modifier_)->remove_tetrahedra(outside_); break;
    case ElementType::quad: static_cast<QuadSetTopologyModifier*>(modifier_)->remove_quads(outside_, true, true); break;
    case ElementType::triangle:
      static_cast<TriangleSetTopologyModifier*>(modifier_)->remove_triangles(outside_, true, true);
      break;
    case ElementType::edge: static_cast<EdgeSetTopologyModifier*>(modifier_)->remove_edges(outside_, true); break;
    default: break;
  }
  return n;
}

void TopologyBoundingTrasher::handle_event(Event& e) {
  if (e.kind == Event::Kind::animate_end) trash();
}

void register_topology_bounding_trasher(Registry& r) {
  ComponentInfo info;
  info.name = "TopologyBoundingTrasher";
  info.category = "Topology";
  info.description = "removes the elements whose barycentre leaves a box, after each step";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = creator<TopologyBoundingTrasher>();
  r.add(std::move(info));
}

}  // namespace sinew
