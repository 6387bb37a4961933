#include "mass/mesh_geometry.h"

namespace sinew::meshgeo {

namespace {
template <class V>
std::size_t max_of(const V& elems) {
  std::size_t m = 0;
  for (const auto& e : elems)
    for (unsigned i : e) m = std::max<std::size_t>(m, static_cast<std::size_t>(i) + 1);
  return m;
}
}  // namespace

std::size_t max_index_plus_one(const MeshTopologyBase& t, MassElement k) {
  switch (k) {
    case MassElement::edge: return max_of(t.edges());
    case MassElement::triangle: return max_of(t.triangles());
    case MassElement::quad: return max_of(t.quads());
    case MassElement::tetra: return max_of(t.tetrahedra());
    case MassElement::hexa: return max_of(t.hexahedra());
    case MassElement::none: return 0;
  }
  return 0;
}

}  // namespace sinew::meshgeo
