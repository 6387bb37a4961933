// SpatialGridPointModel (SofaSphFluid): the collision model of a particle
// fluid, a PointCollisionModel whose points live in the node's
// SpatialGridContainer. SOFA builds its bounding tree from the grid's cells
// (an octree of non-empty cells, `leafScale` levels below a block); Sinew
// keeps the point model's own tree: the same element pairs are tested and the
// same contacts found, in a different traversal order.
#include <memory>
#include <string>

#include "collision/model/point_collision_model.h"
#include "core/node.h"
#include "core/registry.h"
#include "sph/spatial_grid.h"
#include "sph/spatial_grid_container.h"

namespace sinew {

namespace {

class SpatialGridPointModel final : public PointCollisionModel {
 public:
  Field<int> leaf_scale{this, "leafScale", 0,
                        "octree level of the leaf cubes below a grid block (at most 3, SOFA's GRIDDIM_LOG2)",
                        "Collision"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    PointCollisionModel::parse(attrs, diag);
    if (leaf_scale.value() < 0) diag.error(where, describe() + ": leafScale must not be negative");
    else if (leaf_scale.value() > sph::SpatialGrid::kLog2)
      diag.warning(where, describe() + ": leafScale " + std::to_string(leaf_scale.value()) + " is above " +
                              std::to_string(sph::SpatialGrid::kLog2) + ": " +
                              std::to_string(sph::SpatialGrid::kLog2) + " is used");
  }

 protected:
  bool init_model() override {
    if (!PointCollisionModel::init_model()) return false;
    if (!node()->find_up<SpatialGridContainer>()) msg_error("requires a SpatialGridContainer in its node or above");
    return true;
  }
};

}  // namespace

void register_spatial_grid_point_model(Registry& r) {
  ComponentInfo info;
  info.name = "SpatialGridPointModel";
  info.category = "Collision/Geometry";
  info.description = "point collision model of a fluid held in a SpatialGridContainer (SofaSphFluid)";
  info.create = [](const std::string&) -> std::unique_ptr<Component> {
    return std::make_unique<SpatialGridPointModel>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
