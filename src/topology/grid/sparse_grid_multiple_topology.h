// SparseGridMultipleTopology: a sparse grid over several closed surfaces,
// each with its own stiffness and mass coefficient (spec/mechanics.md §5.4):
// a frog whose eyes are stiffer than its body. Every file of `fileTopologies`
// is voxelized on the same grid (its box spans all of them); a cell takes the
// coefficients of the last file it is inside of, and a cell on a file's
// surface (with fillWeighted) the mean of its previous coefficients and that
// file's (or that file's alone with erasePreviousCoef). The hexahedra are the
// cells inside or on the surface of any file; `fileTopology` is only the
// surface whose edges decide the connectivity of the ramifications.
//
// With computeRamifications (the default) the grid is a
// SparseGridRamificationTopology, else a plain SparseGridTopology.
#pragma once

#include <string>
#include <vector>

#include "topology/grid/sparse_grid_ramification_topology.h"

namespace sinew {

class SparseGridMultipleTopology final : public SparseGridRamificationTopology {
 public:
  Field<std::vector<std::string>> file_topologies{this, "fileTopologies", {}, "All topology filenames", "Grid"};
  // Stored as SOFA does, in single precision (read as double, rounded to float).
  Field<std::vector<double>> stiffness_coefs{this, "stiffnessCoefs", {},
                                             "A stiffness coefficient for each topology filename", "Grid"};
  Field<std::vector<double>> mass_coefs{this, "massCoefs", {}, "A mass coefficient for each topology filename",
                                        "Grid"};
  Field<bool> compute_ramifications{this, "computeRamifications", true, "Are ramifications wanted?", "Grid"};
  Field<bool> erase_previous_coef{this, "erasePreviousCoef", false,
                                  "Does a new stiffness/mass coefficient replace the previous or blend half/half "
                                  "with it?",
                                  "Grid"};

  SparseGridMultipleTopology();

  unsigned find_cube(const Vec3& p, double& fx, double& fy, double& fz) const override;
  unsigned find_nearest_cube(const Vec3& p, double& fx, double& fy, double& fz) const override;

 protected:
  void generate() override;
  bool surface_optional() const override { return !(compute_ramifications.value() && finest_connectivity.value()); }
  bool build_from_surface(Level& out, VecNi<3> dims, Vec3 min, Vec3 max, double cell_width, bool only_inside,
                          const std::vector<Vec3>& vertices,
                          const std::vector<std::vector<unsigned>>& facets) const override;
};

}  // namespace sinew
