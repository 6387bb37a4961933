#include "engine/select/mesh_subset_engine.h"

#include <map>

#include "core/registry.h"

namespace sinew {

MeshSubsetEngine::MeshSubsetEngine() {
  for (BaseField* f : std::initializer_list<BaseField*>{&input_position, &input_edges, &input_triangles, &input_quads,
                                                        &input_tetrahedra, &input_hexahedra, &indices})
    add_input(f);
  for (BaseField* f :
       std::initializer_list<BaseField*>{&position, &edges, &triangles, &quads, &tetrahedra, &hexahedra})
    add_output(f);
}

namespace {
template <class Elem>
void extract(const std::map<unsigned, unsigned>& to_subset, const std::vector<Elem>& in, std::vector<Elem>& out) {
  out.clear();
  for (const Elem& e : in) {
    Elem m{};
    bool inside = true;
    for (std::size_t j = 0; j < e.size() && inside; ++j) {
      auto it = to_subset.find(e[j]);
      if (it == to_subset.end()) inside = false;
      else m[j] = it->second;
    }
    if (inside) out.push_back(m);
  }
}
}  // namespace

void MeshSubsetEngine::do_update() {
  const std::vector<Vec3>& x = input_position.get();
  const std::vector<unsigned>& ids = indices.get();
  std::vector<Vec3>& out = position.edit();
  out.clear();
  std::map<unsigned, unsigned> to_subset;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] >= x.size()) {
      msg_error("indices[" + std::to_string(i) + "] = " + std::to_string(ids[i]) + " is beyond the " +
                std::to_string(x.size()) + " input vertices: the subset is left empty");
      out.clear();
      edges.edit().clear();
      triangles.edit().clear();
      quads.edit().clear();
      tetrahedra.edit().clear();
      hexahedra.edit().clear();
      return;
    }
    out.push_back(x[ids[i]]);
    to_subset[ids[i]] = static_cast<unsigned>(i);
  }
  extract(to_subset, input_edges.get(), edges.edit());
  extract(to_subset, input_triangles.get(), triangles.edit());
  extract(to_subset, input_quads.get(), quads.edit());
  extract(to_subset, input_tetrahedra.get(), tetrahedra.edit());
  extract(to_subset, input_hexahedra.get(), hexahedra.edit());
}

void register_mesh_subset_engine(Registry& r) {
  ComponentInfo info;
  info.name = "MeshSubsetEngine";
  info.category = "Engine/Select";
  info.description = "the sub-mesh spanned by a list of vertices";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<MeshSubsetEngine>(); };
  r.add(std::move(info));
}

}  // namespace sinew
