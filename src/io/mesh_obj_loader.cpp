#include "io/mesh_obj_loader.h"

#include "core/registry.h"

namespace sinew {

MeshOBJLoader::MeshOBJLoader() {
  default_material.add_alias("material");
  add_input(&handle_seams);
  add_input(&load_material);
  for (BaseField* f : std::initializer_list<BaseField*>{&default_material, &materials, &face_list, &texcoords_index, &positions_definition,
                                                        &texcoords_definition, &normals_index, &normals_definition,
                                                        &texcoords, &vert_pos_idx, &vert_norm_idx})
    add_output(f);
}

bool MeshOBJLoader::read_mesh(io::MeshData& out, std::string* error) {
  io::ReadOptions o = read_options();
  o.handle_seams = handle_seams.get();
  auto m = io::read_obj(filename.get(), error, o);
  if (!m) return false;
  if (!load_material.get()) {
    m->materials.clear();
    m->material_texts.clear();
    m->default_material.clear();
  }
  out = std::move(*m);
  return true;
}

void MeshOBJLoader::publish_extra(const io::MeshData& m) {
  materials.set(m.materials);
  if (!m.default_material.empty()) default_material.set(m.default_material);
  face_list.set(m.face_positions);
  texcoords_index.set(m.face_texcoords);
  normals_index.set(m.face_normals);
  positions_definition.set(m.positions_definition);
  texcoords_definition.set(m.texcoords_definition);
  normals_definition.set(m.normals_definition);
  texcoords.set(m.texcoords);
  vert_pos_idx.set(m.vert_pos_idx);
  vert_norm_idx.set(m.vert_norm_idx);
}

void register_mesh_obj_loader(Registry& r) {
  ComponentInfo info;
  info.name = "MeshOBJLoader";
  info.category = "Loader";
  info.description = "loads Wavefront OBJ meshes (positions, faces, texture coordinates, normals, groups)";
  info.create = creator<MeshOBJLoader>();
  r.add(std::move(info));
}

}  // namespace sinew
