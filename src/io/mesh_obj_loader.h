// MeshOBJLoader: Wavefront OBJ files (spec/mechanics.md §7.2).
#pragma once

#include "io/mesh_loader.h"

namespace sinew {

class MeshOBJLoader final : public MeshLoader {
 public:
  MeshOBJLoader();

  Field<bool> handle_seams{this, "handleSeams", false,
                           "preserve UV and normal seams (one vertex per position/texcoord/normal triple)", "Loader"};
  Field<bool> load_material{this, "loadMaterial", true, "load the related .mtl file", "Shading"};
  Field<std::string> default_material{this, "defaultMaterial", "", "default material (viewer)", "Shading"};
  Field<std::vector<std::string>> materials{this, "materials", {}, "names of the materials found", "Shading"};
  io::ValueField<std::vector<std::vector<int>>> face_list{this, "faceList", "faces as written (position indices)",
                                                          "Geometry"};
  io::ValueField<std::vector<std::vector<int>>> texcoords_index{
      this, "texcoordsIndex", "texture coordinate indices of the faces", "Texturing"};
  Field<std::vector<Vec3>> positions_definition{this, "positionsDefinition", {}, "vertex positions as written",
                                                "Geometry"};
  Field<std::vector<Vec2>> texcoords_definition{this, "texcoordsDefinition", {}, "texture coordinates as written",
                                                "Texturing"};
  io::ValueField<std::vector<std::vector<int>>> normals_index{this, "normalsIndex", "normal indices of the faces",
                                                              "Geometry"};
  Field<std::vector<Vec3>> normals_definition{this, "normalsDefinition", {}, "normals as written", "Geometry"};
  Field<std::vector<Vec2>> texcoords{this, "texcoords", {}, "texture coordinates per vertex", "Texturing"};
  Field<bool> compute_material_faces{this, "computeMaterialFaces", false,
                                     "export the face indices of each material", "Shading"};
  Field<std::vector<unsigned>> vert_pos_idx{this, "vertPosIdx", {}, "handleSeams: position index of each vertex",
                                            "Geometry"};
  Field<std::vector<unsigned>> vert_norm_idx{this, "vertNormIdx", {}, "handleSeams: normal index of each vertex",
                                             "Geometry"};

 protected:
  bool read_mesh(io::MeshData& out, std::string* error) override;
  void publish_extra(const io::MeshData& m) override;
};

}  // namespace sinew
