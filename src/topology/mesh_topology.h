// Static mesh containers: point coordinates and element lists as fields,
// plus the neighbourhood queries (edges around a vertex, triangles around an
// edge, ...) that force fields and mappings use (spec/mechanics.md §5.1).
//
// MeshContainer is the base of every topology container (MeshTopology, the
// grids, CubeTopology, the *SetTopologyContainer family). Subclasses that
// generate their lists (grids) override `generate()`, which runs lazily on
// first access so that components initialised earlier in the node (a
// MechanicalObject declared before its grid) already see the data.
//
// MeshTopology (registered here) derives the lists that were empty at init
// (edges from volumes or surfaces, triangles from tetrahedra, quads from
// hexahedra) on first read, as SOFA's update engines do.
#pragma once

#include <memory>
#include <string>

#include "core/roles.h"

namespace sinew {

class Engine;

// SOFA's local numbering tables (sofa/core/topology/Topology.cpp).
namespace topo {
inline constexpr unsigned kEdgesInTetra[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
inline constexpr unsigned kTrianglesInTetra[4][3] = {{1, 2, 3}, {0, 3, 2}, {1, 3, 0}, {0, 2, 1}};
inline constexpr unsigned kEdgesInHexa[12][2] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                                                 {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
inline constexpr unsigned kQuadsInHexa[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// Edges of tetrahedra then hexahedra (local tables above), stored (min,max), first occurrence order.
std::vector<Edge> edges_of_volumes(const std::vector<Tetra>& tetras, const std::vector<Hexa>& hexas);
// Edges of triangles, (t[j+1], t[j+2]) stored as found, then of quads, (q[j+1], q[j+2]) stored
// (min,max); each edge once (first occurrence).
std::vector<Edge> edges_of_surfaces(const std::vector<Triangle>& triangles, const std::vector<Quad>& quads);
// Faces of tetrahedra (kTrianglesInTetra), rotated smallest-first; a face is skipped when its
// reverse already exists, and also when the same face exists if `skip_same` (dynamic containers).
std::vector<Triangle> triangles_of_tetrahedra(const std::vector<Tetra>& tetras, bool skip_same);
// Faces of hexahedra (kQuadsInHexa), rotated smallest-first, dedup with either orientation.
std::vector<Quad> quads_of_hexahedra(const std::vector<Hexa>& hexas);
// One past the largest index of a list (0 when empty).
template <class List>
std::size_t count_points(const List& list) {
  std::size_t n = 0;
  for (const auto& e : list)
    for (unsigned i : e)
      if (i + std::size_t{1} > n) n = i + std::size_t{1};
  return n;
}
}  // namespace topo

class MeshContainer : public MeshTopologyBase {
 public:
  MeshContainer();
  ~MeshContainer() override;

  Field<std::vector<Vec3>> position{this, "position", {}, "point coordinates", "Topology", "length"};
  Field<std::vector<Edge>> edges_f{this, "edges", {}, "edges (vertex index pairs)", "Topology"};
  Field<std::vector<Triangle>> triangles_f{this, "triangles", {}, "triangles (3 vertex indices each)", "Topology"};
  Field<std::vector<Quad>> quads_f{this, "quads", {}, "quads (4 vertex indices each)", "Topology"};
  Field<std::vector<Tetra>> tetrahedra_f{this, "tetrahedra", {}, "tetrahedra (4 vertex indices each)", "Topology"};
  Field<std::vector<Hexa>> hexahedra_f{this, "hexahedra", {}, "hexahedra (8 vertex indices each)", "Topology"};
  Field<std::string> filename{this, "filename", "", "mesh file to read (alias: fileTopology)", "Topology"};

  std::size_t nb_points() const override;
  bool has_positions() const override;
  Vec3 point(std::size_t i) const override;
  const std::vector<Edge>& edges() const override { return ensure(), edges_f.get(); }
  const std::vector<Triangle>& triangles() const override { return ensure(), triangles_f.get(); }
  const std::vector<Quad>& quads() const override { return ensure(), quads_f.get(); }
  const std::vector<Tetra>& tetrahedra() const override { return ensure(), tetrahedra_f.get(); }
  const std::vector<Hexa>& hexahedra() const override { return ensure(), hexahedra_f.get(); }
  std::uint64_t elements_version(Elements e) const override;

  // Neighbourhood queries (see MeshTopologyBase).
  const std::vector<IndexList>& edges_around_vertex() const override;
  const std::vector<IndexList>& triangles_around_vertex() const override;
  const std::vector<IndexList>& triangles_around_edge() const override;
  const std::vector<IndexList>& quads_around_vertex() const override;
  const std::vector<IndexList>& quads_around_edge() const override;
  const std::vector<IndexList>& tetrahedra_around_vertex() const override;
  const std::vector<IndexList>& tetrahedra_around_edge() const override;
  const std::vector<IndexList>& tetrahedra_around_triangle() const override;
  const std::vector<IndexList>& hexahedra_around_vertex() const override;
  const std::vector<IndexList>& hexahedra_around_edge() const override;
  const std::vector<IndexList>& hexahedra_around_quad() const override;
  const std::vector<std::array<unsigned, 3>>& edges_in_triangle() const override;
  const std::vector<std::array<unsigned, 4>>& edges_in_quad() const override;
  const std::vector<std::array<unsigned, 6>>& edges_in_tetrahedron() const override;
  const std::vector<std::array<unsigned, 4>>& triangles_in_tetrahedron() const override;
  const std::vector<std::array<unsigned, 12>>& edges_in_hexahedron() const override;
  const std::vector<std::array<unsigned, 6>>& quads_in_hexahedron() const override;
  unsigned edge_index(unsigned a, unsigned b) const override;
  unsigned triangle_index(unsigned a, unsigned b, unsigned c) const override;
  unsigned quad_index(unsigned a, unsigned b, unsigned c, unsigned d) const override;

  void init() override;

  // Writing interface used by topological mappings (SOFA's clear/setNbPoints/addX, then init()).
  virtual void clear_topology();
  virtual void set_nb_points(std::size_t n) { nb_points_hint_ = n; }

 protected:
  // Fills the fields from the subclass's parameters; called once, lazily.
  virtual void generate() {}
  // Invalidate generated data (parameters changed).
  void regenerate() { generated_ = false; }
  // Replaces the lists by the content of a mesh file (filename=); false (with an error) on failure.
  bool load_file(const std::string& file);
  // Warns (naming the first element) when an element uses a point index >= n; false then.
  bool check_indices(std::size_t n) const;
  // Changes whenever nb_points() may change for reasons other than the lists (subclasses).
  virtual std::uint64_t points_stamp() const { return 0; }
  // Number of points given explicitly (mapping's setNbPoints, nbPoints field); 0 when unknown.
  std::size_t nb_points_hint_ = 0;

 private:
  void ensure() const;
  mutable bool generated_ = false;
  struct Cache;
  // Rebuilds the neighbourhood cache when an element list changed since it was built.
  Cache& cache() const;
  mutable std::unique_ptr<Cache> cache_;
};

// MeshTopology: generic constant topology (lists given in the scene or by a loader).
class MeshTopology : public MeshContainer {
 public:
  MeshTopology();
  ~MeshTopology() override;

  Field<std::vector<std::array<unsigned, 6>>> prisms{this, "prisms", {}, "prisms (6 vertex indices each)", "Topology"};
  Field<std::vector<std::array<unsigned, 5>>> pyramids{
      this, "pyramids", {}, "pyramids (5 vertex indices each)", "Topology"};
  Field<std::vector<Vec2>> uv{this, "uv", {}, "texture coordinates", "Topology"};
  Field<bool> compute_all_buffers{this, "computeAllBuffers", false, "build all adjacency tables at init", "Topology"};
  Field<bool> draw_edges{this, "drawEdges", false, "draw the edges (viewer)", "Visualization"};
  Field<bool> draw_triangles{this, "drawTriangles", false, "draw the triangles (viewer)", "Visualization"};
  Field<bool> draw_quads{this, "drawQuads", false, "draw the quads (viewer)", "Visualization"};
  Field<bool> draw_tetrahedra{this, "drawTetrahedra", false, "draw the tetrahedra (viewer)", "Visualization"};
  Field<bool> draw_hexahedra{this, "drawHexahedra", false, "draw the hexahedra (viewer)", "Visualization"};

  void init() override;
  void clear_topology() override;

 private:
  void drop_updates();
  // Lazy derivations of the lists that were empty at init (SOFA's Edge/Triangle/QuadUpdate).
  std::unique_ptr<Engine> edge_update_, triangle_update_, quad_update_;
};

// The prisms and pyramids of a topology: only a MeshTopology holds them (SOFA's
// BaseMeshTopology::getPrisms/getPyramids); empty for every other topology.
using Prism = std::array<unsigned, 6>;
using Pyramid = std::array<unsigned, 5>;
const std::vector<Prism>& prisms_of(const MeshTopologyBase& t);
const std::vector<Pyramid>& pyramids_of(const MeshTopologyBase& t);

}  // namespace sinew
