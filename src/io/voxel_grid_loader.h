// VoxelGridLoader: hexahedra (or points) from a raw 8-bit voxel image (SOFA's
// IO/Mesh). The file holds `header` bytes then resolution x·y·z voxels, x
// fastest. A voxel of the region of interest ROI (inclusive voxel bounds,
// clamped to the image at init) is active when its value is in dataValue,
// else when it is not in bgValue (every voxel when both are empty). With
// generateHexa each active voxel gives a hexahedron over the corner points
// it uses (points numbered z, then y, then x fastest, at i·voxelSize); else
// each active voxel gives the point at its corner. idxInRegularGrid is each
// element's voxel index.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class VoxelGridLoader final : public Engine {
 public:
  VoxelGridLoader();

  Field<std::string> filename{this, "filename", "", "raw voxel file (.raw)", "Loader"};
  Field<Vec3> voxel_size{this, "voxelSize", Vec3(1, 1, 1), "size of a voxel", "Loader", "length"};
  Field<VecNi<3>> resolution{this, "resolution", VecNi<3>(0, 0, 0), "voxels along x, y, z in the file", "Loader"};
  Field<std::vector<int>> roi{this, "ROI", {0, 0, 0, 0xFFFF, 0xFFFF, 0xFFFF},
                               "region of interest: xmin ymin zmin xmax ymax zmax (voxels, inclusive)", "Loader"};
  Field<int> header{this, "header", 0, "bytes before the voxels", "Loader"};
  Field<int> segmentation_header{this, "segmentationHeader", 0, "unused (as in SOFA)", "Loader"};
  Field<std::vector<int>> bg_value{this, "bgValue", {}, "background values (inactive voxels)", "Loader"};
  Field<std::vector<int>> data_value{this, "dataValue", {}, "active values (when given, the only active ones)",
                                     "Loader"};
  Field<bool> generate_hexa{this, "generateHexa", true, "voxels as hexahedra (else as points)", "Loader"};
  Field<std::vector<Vec3>> position{this, "position", {}, "points", "Vectors", "length"};
  Field<std::vector<Hexa>> hexahedra{this, "hexahedra", {}, "hexahedra", "Vectors"};
  Field<std::vector<unsigned>> idx_in_regular_grid{this, "idxInRegularGrid", {}, "voxel index of each element",
                                                   "Vectors"};

  void init() override;
  void reinit() override;

 protected:
  void do_update() override;

 private:
  bool load();
  bool active(std::size_t idx) const;
  std::vector<unsigned char> voxels_;
  bool loaded_ = false;
};

}  // namespace sinew
