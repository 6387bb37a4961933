// MeshLoader: base of the mesh loader components (spec/mechanics.md §7.1).
//
// Loading is lazy and order-independent: the loader is an engine whose
// outputs (position, edges, triangles, ...) are produced the first time
// anything reads them — a MechanicalObject or topology linked with
// `src="@loader"` or `position="@loader.position"` — and again whenever the
// file name or a transform field changes. init() forces the load so that
// errors are reported at init. The transforms, triangulate,
// createSubelements, onlyAttachedPoints and normal computation are applied
// after reading, in SOFA's order (io::finish_mesh). Those fields are not
// auto-linked by `src=` (field->set_autolink(false)), as in SOFA.
//
// Subclasses implement read_mesh() (one file format) and may publish extra
// outputs in publish_extra().
#pragma once

#include "core/engine.h"
#include "core/roles.h"
#include "io/loader_fields.h"
#include "io/mesh_readers.h"

namespace sinew {

class MeshLoader : public Engine {
 public:
  MeshLoader();

  Field<std::string> filename{this, "filename", "", "mesh file to load", "Loader"};

  Field<std::vector<Vec3>> position{this, "position", {}, "loaded vertex positions", "Vectors", "length"};
  io::ValueField<std::vector<std::vector<unsigned>>> polylines{this, "polylines", "loaded polylines", "Vectors"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "loaded edges", "Vectors"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "loaded triangles", "Vectors"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "loaded quads", "Vectors"};
  io::ValueField<std::vector<std::vector<unsigned>>> polygons{this, "polygons", "loaded polygons", "Vectors"};
  Field<std::vector<std::array<unsigned, 4>>> high_order_edge_positions{
      this, "highOrderEdgePositions", {}, "loaded high-order nodes on edges", "Vectors"};
  Field<std::vector<std::array<unsigned, 4>>> high_order_triangle_positions{
      this, "highOrderTrianglePositions", {}, "loaded high-order nodes on triangles", "Vectors"};
  Field<std::vector<std::array<unsigned, 4>>> high_order_quad_positions{
      this, "highOrderQuadPositions", {}, "loaded high-order nodes on quads", "Vectors"};
  Field<std::vector<Tetra>> tetrahedra{this, "tetrahedra", {}, "loaded tetrahedra", "Vectors"};
  Field<std::vector<Hexa>> hexahedra{this, "hexahedra", {}, "loaded hexahedra", "Vectors"};
  Field<std::vector<io::Prism>> prisms{this, "prisms", {}, "loaded prisms", "Vectors"};
  Field<std::vector<std::array<unsigned, 4>>> high_order_tetrahedron_positions{
      this, "highOrderTetrahedronPositions", {}, "loaded high-order nodes on tetrahedra", "Vectors"};
  Field<std::vector<std::array<unsigned, 4>>> high_order_hexahedron_positions{
      this, "highOrderHexahedronPositions", {}, "loaded high-order nodes on hexahedra", "Vectors"};
  Field<std::vector<io::Pyramid>> pyramids{this, "pyramids", {}, "loaded pyramids", "Vectors"};
  Field<std::vector<Vec3>> normals{this, "normals", {}, "loaded per-vertex normals", "Vectors"};

  io::ValueField<std::vector<io::PrimitiveGroup>> edges_groups{this, "edgesGroups", "groups of edges", "Groups"};
  io::ValueField<std::vector<io::PrimitiveGroup>> triangles_groups{this, "trianglesGroups", "groups of triangles",
                                                                    "Groups"};
  io::ValueField<std::vector<io::PrimitiveGroup>> quads_groups{this, "quadsGroups", "groups of quads", "Groups"};
  io::ValueField<std::vector<io::PrimitiveGroup>> polygons_groups{this, "polygonsGroups", "groups of polygons",
                                                                   "Groups"};
  io::ValueField<std::vector<io::PrimitiveGroup>> tetrahedra_groups{this, "tetrahedraGroups",
                                                                     "groups of tetrahedra", "Groups"};
  io::ValueField<std::vector<io::PrimitiveGroup>> hexahedra_groups{this, "hexahedraGroups", "groups of hexahedra",
                                                                    "Groups"};
  io::ValueField<std::vector<io::PrimitiveGroup>> prisms_groups{this, "prismsGroups", "groups of prisms", "Groups"};
  io::ValueField<std::vector<io::PrimitiveGroup>> pyramids_groups{this, "pyramidsGroups", "groups of pyramids",
                                                                   "Groups"};

  Field<bool> flip_normals{this, "flipNormals", false, "reverse the vertex order of triangles and quads", "Loader"};
  Field<bool> triangulate{this, "triangulate", false, "divide all polygons into triangles", "Loader"};
  Field<bool> create_subelements{this, "createSubelements", false,
                                 "create the boundary elements of n-D elements (e.g. triangles of tetrahedra)",
                                 "Loader"};
  Field<bool> only_attached_points{this, "onlyAttachedPoints", false,
                                   "only keep the points attached to elements of the mesh", "Loader"};
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "translation of the positions", "Transformation", "length"};
  Field<Vec3> rotation{this, "rotation", Vec3::Zero(), "rotation of the positions (Euler angles, degrees)",
                       "Transformation", "degrees"};
  Field<Vec3> scale3d{this, "scale3d", Vec3::Ones(), "scale of the positions in 3 dimensions (attribute 'scale' "
                                                     "multiplies it)",
                      "Transformation"};
  Field<std::vector<double>> transformation{
      this, "transformation", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},
      "4x4 homogeneous matrix (row-major) transforming the positions; replaces translation/rotation/scale",
      "Transformation"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void reinit() override { update(); }

  // The mesh as loaded and post-processed (valid after a successful load).
  const io::MeshData& mesh() const { return mesh_; }

 protected:
  // Reads the file into `out` (before post-processing); false with *error on failure.
  virtual bool read_mesh(io::MeshData& out, std::string* error) = 0;
  // Whether a filename is required (generators such as StringMeshCreator: false).
  virtual bool needs_file() const { return true; }
  // createSubelements used when the attribute is absent (MeshGmshLoader: true).
  virtual bool default_create_subelements() const { return false; }
  // Publishes format-specific outputs (texcoords, ...).
  virtual void publish_extra(const io::MeshData&) {}
  // Read options common to the formats.
  io::ReadOptions read_options() const;

  void do_update() override;

 private:
  void publish(const io::MeshData& m);
  io::MeshData mesh_;
};

}  // namespace sinew
