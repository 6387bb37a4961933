// SparseGridTopology: the cells of a regular grid that intersect or lie
// inside a closed surface mesh, as hexahedra (spec/mechanics.md §5.4).
// Built from `fileTopology` (a surface mesh: .obj, .msh, .vtk, .stl) or from
// `position` + `triangles`/`quads`. Only hexahedra and points are produced
// (no edges, quads or triangles). Voxel files (.raw, .voxel) are not
// supported (an error says so).
#pragma once

#include <array>
#include <span>

#include "topology/mesh_topology.h"

namespace sinew {

class SparseGridTopology : public MeshTopology {
 public:
  enum class CellType { outside, inside, boundary };

  Field<bool> fill_weighted{this, "fillWeighted", true, "weight cells by fill (0.5 boundary, 1 interior)", "Grid"};
  Field<bool> only_inside_cells{this, "onlyInsideCells", false, "keep interior cells only", "Grid"};
  Field<VecNi<3>> n{this, "n", VecNi<3>(2, 2, 2), "grid resolution", "Grid"};
  Field<Vec3> min{this, "min", Vec3::Zero(), "lower corner of the box", "Grid"};
  Field<Vec3> max{this, "max", Vec3::Zero(), "upper corner of the box", "Grid"};
  Field<double> cell_width{this, "cellWidth", 0.0, "if > 0, cell size; n is derived from it", "Grid", "length"};
  Field<int> nb_virtual_finer_levels{this, "nbVirtualFinerLevels", 0,
                                     "number of finer hidden grid levels used to compute the coarse cells", "Grid"};
  Field<VecNi<3>> data_resolution{this, "dataResolution", VecNi<3>(0, 0, 0), "voxel file resolution", "Grid"};
  Field<Vec3> voxel_size{this, "voxelSize", Vec3::Ones(), "voxel size", "Grid"};
  Field<unsigned> marching_cube_step{this, "marchingCubeStep", 1u, "marching-cubes step", "Grid"};
  Field<unsigned> convolution_size{this, "convolutionSize", 0u, "voxel smoothing kernel size (0: none)", "Grid"};

  void init() override;

  // Per hexahedron: its type and the coefficients FEM/mass components apply (0.5 on boundary cells
  // when fillWeighted, else 1).
  CellType cell_type(std::size_t h) const { return h < types_.size() ? types_[h] : CellType::outside; }
  float stiffness_coef(std::size_t h) const { return h < stiffness_coefs_.size() ? stiffness_coefs_[h] : 1.0f; }
  float mass_coef(std::size_t h) const { return h < mass_coefs_.size() ? mass_coefs_[h] : 1.0f; }

  // Grid look-ups (SOFA's findCube / findNearestCube): the hexahedron index and the local
  // coordinates of `p` in it; kInvalidIndex when not found. Virtual: SparseGridRamificationTopology
  // answers through its finest level.
  virtual unsigned find_cube(const Vec3& p, double& fx, double& fy, double& fz) const;
  virtual unsigned find_nearest_cube(const Vec3& p, double& fx, double& fy, double& fz) const;

  // One level of the grid hierarchy as components that integrate over it read it
  // (NonUniformHexahedronFEMForceFieldAndMass). children[h][c] is the hexahedron of the next
  // finer level filling octant c of hexahedron h (c = x + 2y + 4z, SOFA's _hierarchicalCubeMap),
  // −1 where that cell is empty; empty for the finest level.
  struct LevelView {
    std::span<const Vec3> points;
    std::span<const Hexa> hexas;
    std::span<const float> stiffness;
    std::span<const std::array<int, 8>> children;
  };
  // Virtual finer levels kept with their cell hierarchy: nbVirtualFinerLevels once the grid is
  // built from a surface, 0 without virtual levels (and for ramified grids, which keep none).
  int kept_levels() const;
  // Level k: 0 is this grid, k = 1..kept_levels() the virtual level k times finer.
  LevelView level(int k) const;

 protected:
  void generate() override;

  // The underlying regular grid (SOFA's _regularGrid).
  struct Grid {
    VecNi<3> n{2, 2, 2};
    Vec3 p0 = Vec3::Zero(), dx = Vec3::Zero(), dy = Vec3::Zero(), dz = Vec3::Zero();
    double inv_dx2 = 0, inv_dy2 = 0, inv_dz2 = 0;
    int nb_cells() const { return (n[0] - 1) * (n[1] - 1) * (n[2] - 1); }
    int cube(int i, int j, int k) const { return (n[0] - 1) * ((n[1] - 1) * k + j) + i; }
    Vec3 point(int i, int j, int k) const { return p0 + dx * i + dy * j + dz * k; }
    // Cell containing p, -1 if outside; (x,y,z) receive the continuous grid coordinates.
    int find(const Vec3& p, double& x, double& y, double& z) const;
    void set(const VecNi<3>& dims, const Vec3& lo, const Vec3& hi);
  };
  // One level of the grid hierarchy (the component itself, or a virtual finer level).
  struct Level {
    Grid grid;
    Vec3 min = Vec3::Zero(), max = Vec3::Zero();
    std::vector<CellType> types;
    std::vector<float> stiffness, mass;
    std::vector<int> sparse_of_regular;
    std::vector<Vec3> points;
    std::vector<Hexa> hexas;
    std::vector<std::array<int, 8>> children;  // per hexahedron, into the next finer level (coarsen)
  };
  // Finest level from a surface mesh (SOFA's buildFromTriangleMesh); false after an error.
  // Virtual: SparseGridMultipleTopology builds it from several meshes.
  virtual bool build_from_surface(Level& out, VecNi<3> dims, Vec3 min, Vec3 max, double cell_width, bool only_inside,
                                  const std::vector<Vec3>& vertices,
                                  const std::vector<std::vector<unsigned>>& facets) const;
  // The type of every cell of grid `g` (box lo..hi) for a closed surface: cells holding a vertex
  // or crossed by a facet are boundary, those reached from the border without crossing one are
  // outside, the rest inside (SOFA's voxelizeTriangleMesh); false after an error.
  bool voxelize(const Grid& g, const Vec3& lo, const Vec3& hi, const std::vector<Vec3>& vertices,
                const std::vector<std::vector<unsigned>>& facets, std::vector<CellType>& types) const;
  // Hexahedra, points and types of `level` (its grid set) from the type of each regular cell
  // (SOFA's buildFromRegularGridTypes): boundary cells first, then inside ones. No coefficients.
  static void build_from_types(Level& level, const std::vector<CellType>& types, bool only_inside);
  // Next coarser level (SOFA's buildFromFiner).
  static void coarsen(const Level& fine, Level& coarse);
  // Points = distinct corners of `cells` (grid coordinates) in lexicographic order; hexahedra.
  static void number_points(Level& level, const std::vector<std::array<int, 3>>& cells);
  // The steps of generate() shared with SparseGridRamificationTopology.
  // Resets the results, clamps n (returned in dims), checks nbVirtualFinerLevels and reads the
  // surface (file or position + triangles/quads); false after an error (build_failed_ set).
  bool prepare(VecNi<3>& dims, std::vector<Vec3>& vertices, std::vector<std::vector<unsigned>>& facets);
  // Whether the grid can be built without fileTopology or position (SparseGridMultipleTopology
  // reads its own files; the surface then only serves the ramifications' connectivity).
  virtual bool surface_optional() const { return false; }
  // Grid size of the finest level when nbVirtualFinerLevels > 0: (n-1)·2^levels + 1 per axis.
  static VecNi<3> finest_dims(VecNi<3> dims, int levels);
  // Makes `level` the component's grid: fields (n, min, max, position, hexahedra) and look-up data.
  void adopt(Level&& level);
  // SOFA's findNearestCube over one level: the boundary hexahedron (of those with a type) whose
  // (c0+c6)/2 centre is nearest; hexahedron 0 when none is boundary (as SOFA), kInvalidIndex
  // when there are no hexahedra.
  static unsigned nearest_boundary_cube(const std::vector<Vec3>& points, const std::vector<Hexa>& hexas,
                                        const std::vector<CellType>& types, const Vec3& p, double& fx, double& fy,
                                        double& fz);

  Grid grid_;
  std::vector<CellType> types_;
  std::vector<float> stiffness_coefs_, mass_coefs_;
  std::vector<int> sparse_of_regular_;  // regular cell → hexahedron index (-1 when absent)
  std::vector<std::array<int, 8>> children_;  // per hexahedron, into virtual_levels_.back()
  std::vector<Level> virtual_levels_;         // finest first, as SOFA's _virtualFinerLevels
  bool build_failed_ = false;
};

}  // namespace sinew
