#include "engine/select/mesh_splitting_engine.h"

#include "core/registry.h"

namespace sinew {

MeshSplittingEngine::MeshSplittingEngine() {
  for (BaseField* f : std::initializer_list<BaseField*>{&input_position, &input_edges, &input_triangles, &input_quads,
                                                        &input_tetrahedra, &input_hexahedra, &nb_inputs})
    add_input(f);
  add_output(&index_pairs);
  grow(nb_inputs.value());
}

void MeshSplittingEngine::grow(unsigned n) {
  auto in = [this](BaseField* f) { add_input(f); };
  indices.grow(*this, n, in);
  edge_indices.grow(*this, n, in);
  triangle_indices.grow(*this, n, in);
  quad_indices.grow(*this, n, in);
  tetrahedron_indices.grow(*this, n, in);
  hexahedron_indices.grow(*this, n, in);
  position.grow(*this, n + 1, [this](BaseField* f) { add_output(f); });
}

void MeshSplittingEngine::parse(AttributeMap& attrs, Diagnostics& diag) {
  const unsigned n = read_field_count(*this, nb_inputs, attrs, diag,
                                      {"indices", "edgeIndices", "triangleIndices", "quadIndices",
                                       "tetrahedronIndices", "hexahedronIndices"});
  grow(n);
  Engine::parse(attrs, diag);
}

void MeshSplittingEngine::init() {
  grow(nb_inputs.get());
  set_dirty();
}

void MeshSplittingEngine::reinit() {
  grow(nb_inputs.get());
  update();
}

void MeshSplittingEngine::do_update() {
  const std::vector<Vec3>& x = input_position.get();
  // Fields are made at parse, init and reinit; a count raised since then waits for reinit.
  const unsigned nb = static_cast<unsigned>(std::min<std::size_t>(nb_inputs.get(), indices.size()));
  std::vector<unsigned> pairs(2 * x.size(), 0);
  for (std::size_t i = 0; i < x.size(); ++i) pairs[2 * i] = nb;  // the remaining part
  auto mark = [&](unsigned v, unsigned part) {
    if (2 * static_cast<std::size_t>(v) < pairs.size()) pairs[2 * static_cast<std::size_t>(v)] = part;
  };
  bool bad = false;
  auto mark_cells = [&](const std::vector<unsigned>& ids, const auto& cells, unsigned part) {
    for (unsigned c : ids) {
      if (c >= cells.size()) {
        bad = true;
        continue;
      }
      for (unsigned v : cells[c]) mark(v, part);
    }
  };
  // Reverse order: the first selections win.
  for (int i = static_cast<int>(nb) - 1; i >= 0; --i) {
    const unsigned part = static_cast<unsigned>(i);
    for (unsigned v : indices[part].get()) mark(v, part);
    mark_cells(edge_indices[part].get(), input_edges.get(), part);
    mark_cells(triangle_indices[part].get(), input_triangles.get(), part);
    mark_cells(quad_indices[part].get(), input_quads.get(), part);
    mark_cells(tetrahedron_indices[part].get(), input_tetrahedra.get(), part);
    mark_cells(hexahedron_indices[part].get(), input_hexahedra.get(), part);
  }
  if (bad) msg_error("an element index is beyond its element list: ignored");
  std::vector<std::vector<Vec3>> parts(nb + 1);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const unsigned part = pairs[2 * i];
    pairs[2 * i + 1] = static_cast<unsigned>(parts[part].size());
    parts[part].push_back(x[i]);
  }
  for (unsigned k = 0; k <= nb; ++k) position[k].set(std::move(parts[k]));
  index_pairs.set(std::move(pairs));
}

void register_mesh_splitting_engine(Registry& r) {
  ComponentInfo info;
  info.name = "MeshSplittingEngine";
  info.category = "Engine/Select";
  info.description = "splits a mesh's vertices into parts given by vertex or element selections";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> {
    return std::make_unique<MeshSplittingEngine>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
