// SpatialGridContainer (SofaSphFluid): the neighbour grid of a particle state
// (sph/spatial_grid.h). SPHFluidForceField and ParticlesRepulsionForceField of
// the same node rebuild and query it every force evaluation; with `sortPoints`
// it renumbers the particles cell by cell at the beginning of each step
// (through the node's PointSetTopologyModifier when there is one, else
// directly on the state), with `autoUpdate` it rebuilds itself then.
#pragma once

#include <memory>
#include <vector>

#include "core/roles.h"
#include "sph/spatial_grid.h"

namespace sinew {

class SpatialGridContainer final : public Component {
 public:
  Field<double> cell_width{this, "cellWidth", 1.0,
                           "width of a grid cell; at least the largest search radius of its users", "Grid", "length"};
  Field<bool> show_grid{this, "showGrid", false, "draw the grid blocks (viewer)", "Visualization"};
  Field<bool> auto_update{this, "autoUpdate", false, "rebuild the grid at the beginning of each step", "Grid"};
  Field<bool> sort_points{this, "sortPoints", false,
                          "renumber the particles cell by cell at the beginning of each step", "Grid"};
  Link<MechanicalState> mstate{this, "mstate", "particle state (default: the node's)"};

  SpatialGridContainer() { listening.set(true); }

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void reinit() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }

  // Rebuilds the grid from the position vector `x` (3 doubles per point).
  void update(const std::vector<double>& x) { grid_->update(x.data(), x.size() / 3); }
  sph::SpatialGrid& grid() { return *grid_; }
  const sph::SpatialGrid& grid() const { return *grid_; }

 private:
  // SOFA's sortPoints(): true when the numbering changed.
  bool sort_now();
  std::unique_ptr<sph::SpatialGrid> grid_;
  std::vector<unsigned> new2old_;
};

}  // namespace sinew
