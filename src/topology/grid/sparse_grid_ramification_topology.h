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
};

}  // namespace sinew
