#include "engine/select/mesh_boundary_roi.h"

#include <algorithm>
#include <map>
#include <set>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

MeshBoundaryROI::MeshBoundaryROI() {
  add_input(&triangles);
  add_input(&quads);
  add_input(&input_roi);
  add_output(&indices);
}

void MeshBoundaryROI::init() {
  if (!triangles.is_set() || !quads.is_set()) {
    if (auto* topo = node()->find_local<MeshTopologyBase>()) {
      if (!triangles.is_set())
        if (BaseField* f = topo->find_field("triangles")) triangles.set_parent(f);
      if (!quads.is_set())
        if (BaseField* f = topo->find_field("quads")) quads.set_parent(f);
    }
  }
  if (!triangles.is_set() && !quads.is_set() && !triangles.parent() && !quads.parent())
    msg_warning("no triangles or quads given and no topology in the node: no mesh to process");
  set_dirty();
}

void MeshBoundaryROI::do_update() {
  const std::vector<unsigned>& roi = input_roi.get();
  auto in_roi = [&](unsigned i) { return roi.empty() || std::find(roi.begin(), roi.end(), i) != roi.end(); };
  std::map<std::pair<unsigned, unsigned>, unsigned> count;
  auto edge = [&](unsigned a, unsigned b) { ++count[{std::min(a, b), std::max(a, b)}]; };
  for (const Triangle& t : triangles.get())
    if (in_roi(t[0]) && in_roi(t[1]) && in_roi(t[2]))
      for (int j = 0; j < 3; ++j) edge(t[j], t[(j + 1) % 3]);
  for (const Quad& q : quads.get())
    if (in_roi(q[0]) && in_roi(q[1]) && in_roi(q[2]) && in_roi(q[3]))
      for (int j = 0; j < 4; ++j) edge(q[j], q[(j + 1) % 4]);
  std::set<unsigned> out;
  for (const auto& [e, n] : count)
    if (n == 1) {
      out.insert(e.first);
      out.insert(e.second);
    }
  indices.set(std::vector<unsigned>(out.begin(), out.end()));
}

void register_mesh_boundary_roi(Registry& r) {
  ComponentInfo info;
  info.name = "MeshBoundaryROI";
  info.category = "Engine/Select";
  info.description = "indices of the boundary vertices of a triangle/quad mesh";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<MeshBoundaryROI>(); };
  r.add(std::move(info));
}

}  // namespace sinew
