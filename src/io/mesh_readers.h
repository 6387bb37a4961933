// Plain mesh-file readers: a file in, a MeshData out, no component needed.
//
// Used by the loader components (MeshOBJLoader, MeshGmshLoader, ...) and by
// any component that reads a mesh file itself (OglModel filename=,
// MeshTopology filename=, SparseGridTopology fileTopology=). Each reader
// produces exactly what SOFA's loader of that format puts in its Data *before*
// MeshLoader's post-processing (spec/mechanics.md §7): no transform, no
// createSubelements, no computed normals. Call finish_mesh() to apply those
// (loader components do it with their own fields).
//
// Errors: the readers return std::nullopt and write a one-line reason, with
// the file name and line number for parse errors, to *error (when non-null).
//
// Files: one reader per format (obj_reader.cpp, gmsh_reader.cpp, vtk_legacy_reader.cpp,
// vtk_xml_reader.cpp, stl_reader.cpp, sph_reader.cpp, off_reader.cpp), the choice by
// extension in mesh_readers.cpp, the post-processing in mesh_finish.cpp; their shared
// helpers are in reader_text.h and vtk_common.h.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew::io {

using Prism = std::array<unsigned, 6>;
using Pyramid = std::array<unsigned, 5>;
// SOFA's HighOrderEdgePosition: (point index, edge index, 1, 1).
using HighOrderEdgePosition = std::array<unsigned, 4>;

// A run of primitives sharing a group / material (OBJ `g` / `usemtl`, Gmsh physical tags).
struct PrimitiveGroup {
  int p0 = 0;   // first primitive index
  int nbp = 0;  // number of primitives
  std::string material_name;
  std::string group_name;
  int material_id = -1;
  bool operator==(const PrimitiveGroup&) const = default;
};

// A named per-point or per-cell array (VTK point/cell data).
struct DataArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

struct MeshData {
  std::vector<Vec3> positions;
  std::vector<Edge> edges;
  std::vector<Triangle> triangles;
  std::vector<Quad> quads;
  std::vector<std::vector<unsigned>> polygons;
  std::vector<std::vector<unsigned>> polylines;
  std::vector<Tetra> tetrahedra;
  std::vector<Hexa> hexahedra;
  std::vector<Prism> prisms;
  std::vector<Pyramid> pyramids;
  std::vector<HighOrderEdgePosition> high_order_edge_positions;

  std::vector<Vec3> normals;    // per point when size == positions.size() (else as the format gives them)
  std::vector<Vec2> texcoords;  // per point (OBJ)

  std::vector<PrimitiveGroup> edges_groups, triangles_groups, quads_groups, polygons_groups, tetrahedra_groups,
      hexahedra_groups, prisms_groups, pyramids_groups;

  // OBJ only: the faces as written (0-based indices, -1 when absent) and the raw lists.
  std::vector<std::vector<int>> face_positions, face_texcoords, face_normals;
  std::vector<Vec3> positions_definition, normals_definition;
  std::vector<Vec2> texcoords_definition;
  std::vector<std::string> materials;  // names of the materials found in the .mtl files
  std::vector<std::string> material_texts;  // the same materials in sofa::type::Material's text format
  std::string default_material;  // the first material named by a usemtl (SOFA's defaultMaterial)
  std::vector<unsigned> vert_pos_idx, vert_norm_idx;  // OBJ handleSeams: source position / normal per vertex

  // SphereLoader only: one radius per centre (positions).
  std::vector<double> radii;

  // VTK only: point and cell data arrays.
  std::vector<DataArray> point_data, cell_data;
};

// Options that change how a file is parsed (SOFA applies them while adding elements).
struct ReadOptions {
  bool flip_normals = false;  // reverse triangle/quad/polygon vertex order when adding (OBJ, VTK, STL)
  bool triangulate = false;   // OBJ: 4-vertex faces become two fan triangles instead of a quad
  bool handle_seams = false;  // OBJ: one vertex per distinct (position, texcoord, normal) triple
  // STL
  bool force_binary = false;
  unsigned header_size = 80;
};

std::optional<MeshData> read_obj(const std::string& path, std::string* error, const ReadOptions& opt = {});
// Gmsh ASCII v1 ($NOD), v2 and v4 ($MeshFormat).
std::optional<MeshData> read_gmsh(const std::string& path, std::string* error, const ReadOptions& opt = {});
// VTK legacy (.vtk, ASCII or BINARY) and XML (.vtu/.vtp, ascii or base64 "binary" arrays, uncompressed,
// little- or big-endian).
std::optional<MeshData> read_vtk(const std::string& path, std::string* error, const ReadOptions& opt = {});
// STL ASCII or binary (auto-detected); duplicate vertices merged (exact equality, first occurrence order).
std::optional<MeshData> read_stl(const std::string& path, std::string* error, const ReadOptions& opt = {});
// Sphere files (.sph): positions = centres, radii.
std::optional<MeshData> read_sph(const std::string& path, std::string* error);
// Object File Format (.off): "OFF", counts, vertices, faces "n i0 … in-1" (3 → triangle, 4 → quad, others skipped).
std::optional<MeshData> read_off(const std::string& path, std::string* error, const ReadOptions& opt = {});
// Picks the reader from the extension (.obj .msh .vtk .vtu .vtp .stl .sph .off, case-insensitive).
std::optional<MeshData> read_mesh(const std::string& path, std::string* error, const ReadOptions& opt = {});

// MeshLoader post-processing (spec/mechanics.md §7.1), in SOFA's order.
struct FinishOptions {
  bool create_subelements = false;
  bool only_attached_points = false;
  bool triangulate = false;  // quads → (q0,q1,q2),(q0,q2,q3) (flip_normals applies to the new triangles)
  bool flip_normals = false;
  bool compute_normals = true;  // per-point normals when the file gave none of the right size
  Vec3 translation = Vec3::Zero();
  Vec3 rotation = Vec3::Zero();  // Euler angles in degrees (SOFA's createQuaterFromEuler, ZYX)
  Vec3 scale = Vec3::Ones();
  std::array<double, 16> transformation{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // row-major 4×4
};
// reinit() of SOFA's MeshLoader: transform positions, then updateElements
// (triangulate, createSubelements), updatePoints (onlyAttachedPoints), updateNormals.
void finish_mesh(MeshData& m, const FinishOptions& opt);

// The 4×4 row-major matrix SOFA builds from translation, Euler rotation (degrees) and scale: T·R·S.
std::array<double, 16> trs_matrix(const Vec3& translation, const Vec3& rotation_deg, const Vec3& scale);
// p' = M·(p,1) with SOFA's summation order.
Vec3 transform_point(const std::array<double, 16>& M, const Vec3& p);

}  // namespace sinew::io
