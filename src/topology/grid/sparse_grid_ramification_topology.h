// SparseGridRamificationTopology: a SparseGridTopology whose cells are split
// by connectivity (spec/mechanics.md §5.5). A cell covering several pieces of
// the surface that are not connected inside it (the two prongs of a fork)
// becomes one hexahedron per piece, with its own corner points, so that the
// pieces are not glued together.
//
// Connectivity is a graph of "connexions" (one per connected piece of a cell):
// - finest level: one connexion per cell, linked to its face neighbours; with
//   finestConnectivity, two boundary cells are linked only if a surface edge
//   crosses their common face, and each connexion becomes a hexahedron;
// - coarser levels (nbVirtualFinerLevels): the connexions of the 2×2×2 fine
//   cells of a coarse cell are grouped into connected components, one coarse
//   connexion (hexahedron) each.
// Hexahedra sharing a face in the graph share its corner points.
#pragma once

#include <array>
#include <set>
#include <span>
#include <vector>

#include "topology/grid/sparse_grid_topology.h"

namespace sinew {

class SparseGridRamificationTopology : public SparseGridTopology {
 public:
  Field<bool> finest_connectivity{this, "finestConnectivity", true,
                                  "test connectivity at the finest level (surface edges crossing the faces "
                                  "between boundary cells): more precise, slower",
                                  "Grid"};

  // With virtual finer levels, look-ups start on the finest level and climb to the hexahedron
  // of the coarsest parent connexion; local coordinates are those of the component's grid.
  unsigned find_cube(const Vec3& p, double& fx, double& fy, double& fz) const override;
  unsigned find_nearest_cube(const Vec3& p, double& fx, double& fy, double& fz) const override;

  // The grid hierarchy of a ramified grid with virtual finer levels, kept for
  // HexahedronCompositeFEMForceFieldAndMass and its mapping. Level k = 0 is this grid,
  // k = 1..ramified_levels() the level k times finer (SOFA's _virtualFinerLevels[L − k]).
  struct RamifiedLevel {
    std::span<const Vec3> points;
    std::span<const Hexa> hexas;
    // Per hexahedron. The finest level keeps its unramified lists, read with hexahedron indices (SOFA).
    std::span<const float> stiffness, mass;
    // Per hexahedron and octant (x + 2y + 4z), the hexahedra of level k + 1 in it (SOFA's
    // _hierarchicalCubeMapRamification); empty for the finest level.
    std::span<const std::array<std::vector<int>, 8>> children;
    // SOFA's _hierarchicalCubeMap of a ramified level, quirks kept: unramified cell indices of
    // level k + 1, and for a split cell's hexahedra only the last child; empty for the finest level.
    std::span<const std::array<int, 8>> cube_map;
  };
  // 0 without virtual finer levels (or before the grid is built).
  int ramified_levels() const;
  RamifiedLevel ramified_level(int k) const;
  // SOFA's SparseGridTopology::findCube and findNearestCube on virtual level k >= 1 (its own
  // regular grid and unramified cell indices; no climbing): kInvalidIndex when not found.
  unsigned find_cube_on_level(int k, const Vec3& p, double& fx, double& fy, double& fz) const;
  unsigned find_nearest_cube_on_level(int k, const Vec3& p, double& fx, double& fy, double& fz) const;

 protected:
  void generate() override;

 private:
  // Directions of the connexion graph (SOFA's order: opposite directions pair up as 2k, 2k+1).
  enum Direction { kUp, kDown, kRight, kLeft, kBefore, kBehind, kNbDirections };

  struct Connexion {
    std::array<std::set<int>, kNbDirections> neighbours;  // connexion ids at the same level
    std::vector<std::pair<int, int>> children;            // (place 0..7 in the cell, fine connexion id)
    int parent = -1;                                      // coarser connexion id
    int cell = 0;                                         // unramified cell (sparse index)
    int hexa = 0;                                         // hexahedron index
    int tmp = 0;                                          // component number while grouping
  };
  // One level: the sparse grid (hexahedra possibly ramified) and its connexion graph.
  // As in SOFA, level.types and the coefficients are listed per hexahedron but the coarser
  // level reads them with unramified cell indices.
  struct RamLevel {
    Level level;
    std::vector<std::vector<int>> cell_connexions;  // unramified cell → its connexion ids
    std::vector<Connexion> connexions;
    std::vector<std::array<int, 8>> cube_map;  // SOFA's _hierarchicalCubeMap (coarser levels)
  };

  // SOFA's findConnexionsAtFinestLevel (one connexion per cell, face neighbours linked).
  void link_finest(RamLevel& L, bool test_surface, const std::vector<Vec3>& vertices,
                   const std::vector<std::vector<unsigned>>& facets) const;
  // SOFA's buildRamifiedFinestLevel: one hexahedron per connexion.
  static void ramify_finest(RamLevel& L);
  // SOFA's buildFromFiner for ramified grids; sets the parents of fine's connexions.
  static void coarsen_ramified(RamLevel& fine, RamLevel& coarse);
  // Hexahedra of a level from its connexions: 8 fresh points each, corners merged across linked
  // faces, points renumbered in first-use order. corners: corner positions per unramified cell.
  static void build_hexahedra(RamLevel& L, const std::vector<std::array<Vec3, 8>>& corners);

  // Finest level kept for the look-ups (virtual levels only). SparseGridMultipleTopology
  // clears it when it builds without ramifications.
 protected:
  bool climb_lookup_ = false;

 private:
  Grid finest_grid_;
  std::vector<int> finest_sparse_of_regular_;
  std::vector<Vec3> finest_points_;
  std::vector<Hexa> finest_hexas_;
  std::vector<CellType> finest_types_;
  std::vector<unsigned> coarsest_of_finest_;  // finest unramified cell → hexahedron of this grid
  // The hierarchy (ramified_level): virtual levels finest first, and per level (finest first, this
  // grid last) the ramified children and SOFA's cube map.
  std::vector<Level> ram_levels_;
  std::vector<std::vector<std::array<std::vector<int>, 8>>> ram_children_;
  std::vector<std::vector<std::array<int, 8>>> ram_cube_map_;
};

}  // namespace sinew
