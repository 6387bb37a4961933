#include "exporter/playback/topology_view.h"

#include <tuple>
#include <type_traits>

namespace sinew {

regression::TopologyView topology_view(const MeshTopologyBase& t) {
  regression::TopologyView view;
  auto flat = [](const auto& list) {
    using Elem = typename std::decay_t<decltype(list)>::value_type;
    static_assert(sizeof(Elem) == std::tuple_size_v<Elem> * sizeof(std::uint32_t));
    return std::span<const std::uint32_t>(reinterpret_cast<const std::uint32_t*>(list.data()),
                                          list.size() * std::tuple_size_v<Elem>);
  };
  view.indices[0] = flat(t.edges());
  view.indices[1] = flat(t.triangles());
  view.indices[2] = flat(t.quads());
  view.indices[3] = flat(t.tetrahedra());
  view.indices[4] = flat(t.hexahedra());
  return view;
}

}  // namespace sinew
