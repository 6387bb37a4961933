// VolumeFromTriangles: volume enclosed by a closed triangle/quad surface
// (SOFA's Engine/Generate): |Σ over the triangles (quads cut along 0-2) of
// ((p1−p0)×(p2−p0))ₓ (x0+x1+x2)/6|. Positions default to the node's state's
// position, triangles and quads to the node's topology's (copied at init).
// The volume is computed at init and reinit; with `update` it follows the
// state's positions whenever it is read, as SOFA. Vec3d and Rigid3d
// (the frames' centres).
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class VolumeFromTriangles final : public Engine {
 public:
  explicit VolumeFromTriangles(StateType type);

  Link<MeshTopologyBase> topology{this, "topology", "topology giving the surface (default: the node's)"};
  Link<MechanicalState> mechanical{this, "mechanical", "state giving the positions (default: the node's)"};
  Field<FlatVec> position;
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles (default: the topology's)", "Inputs"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quads (default: the topology's)", "Inputs"};
  Field<double> volume{this, "volume", 0.0, "enclosed volume (meaningful for a closed surface)", "Outputs",
                       "length³"};
  Field<bool> do_update_field{this, "update", false, "follow the state's positions (recompute when read)",
                              "Inputs"};

  void init() override;
  void reinit() override;

 protected:
  void do_update() override;

 private:
  void compute();
};

// |Σ signed volume| of the triangles and quads over points of `width` scalars (x y z first).
double enclosed_volume(const std::vector<double>& x, int width, const std::vector<Triangle>& tris,
                       const std::vector<Quad>& quads);

}  // namespace sinew
