#include "topology/mesh_topology.h"

#include <algorithm>

namespace sinew {

MeshContainer::MeshContainer() {
  position.add_alias("points");
  edges_f.add_alias("lines");
  tetrahedra_f.add_alias("tetras");
  hexahedra_f.add_alias("hexas");
}

void MeshContainer::ensure() const {
  if (generated_) return;
  generated_ = true;
  const_cast<MeshContainer*>(this)->generate();
}

std::size_t MeshContainer::nb_points() const {
  ensure();
  const auto& p = position.get();
  if (!p.empty()) return p.size();
  // Without coordinates: one past the largest index used by any element.
  unsigned m = 0;
  bool any = false;
  auto scan = [&](const auto& list) {
    for (const auto& e : list)
      for (unsigned i : e) m = std::max(m, i), any = true;
  };
  scan(edges_f.get());
  scan(triangles_f.get());
  scan(quads_f.get());
  scan(tetrahedra_f.get());
  scan(hexahedra_f.get());
  return any ? m + 1 : 0;
}

bool MeshContainer::has_positions() const {
  ensure();
  return !position.get().empty();
}

Vec3 MeshContainer::point(std::size_t i) const {
  ensure();
  const auto& p = position.get();
  return i < p.size() ? p[i] : Vec3::Zero();
}

}  // namespace sinew
