// CylinderGridTopology: the connectivity of a regular nx·ny·nz grid with its
// points placed in a cylinder (SOFA's CylinderGridTopology): each square
// layer of the grid is mapped onto a disc of `radius` around `axis` (a point
// of the square keeps its direction and takes the distance max(|x|, |y|)),
// layers spaced along `length` from `center`. RegularGridTopology's min/max
// do not apply (SOFA's class has no such Data).
#include <Eigen/Geometry>
#include <cmath>

#include "core/registry.h"
#include "topology/grid/regular_grid_topology.h"

namespace sinew {

namespace {

class CylinderGridTopology final : public RegularGridTopology {
 public:
  Field<Vec3> center{this, "center", Vec3::Zero(), "centre of the first disc", "Grid", "length"};
  Field<Vec3> axis{this, "axis", Vec3(0, 0, 1), "main direction of the cylinder", "Grid"};
  Field<double> radius{this, "radius", 1.0, "radius of the cylinder", "Grid", "length"};
  Field<double> length{this, "length", 1.0, "length of the cylinder along its axis", "Grid", "length"};

  void init() override {
    if (!(axis.value().norm() > 0) || !axis.value().allFinite()) {
      msg_error("axis must be a non-zero finite vector");
      set_state(ComponentState::invalid);
      return;
    }
    if (n.get()[0] < 2 || n.get()[1] < 2) {
      msg_error("needs at least 2 points across the disc (nx and ny >= 2)");
      set_state(ComponentState::invalid);
      return;
    }
    RegularGridTopology::init();
  }

 protected:
  Vec3 grid_point(int i, int j, int k) const override {
    const double r = radius.value(), l = length.value();
    Vec3 z = axis.value();
    normalize(z);
    Vec3 x = (z - Vec3(1, 0, 0)).norm() < 0.000001 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    Vec3 y = z.cross(x);
    x = y.cross(z);
    normalize(x);
    normalize(y);
    normalize(z);
    const VecNi<3> d = dims();
    Vec3 p(i * 2 * r / (d[0] - 1) - r, j * 2 * r / (d[1] - 1) - r, 0);
    // The square onto the disc: same direction, distance max(|x|, |y|).
    if (p.norm() > 0.0000001) p *= std::max(std::abs(p[0]), std::abs(p[1])) / p.norm();
    if (d[2] > 1) p[2] = k * l / (d[2] - 1);
    return center.value() + x * p[0] + y * p[1] + z * p[2];
  }

 private:
  // SOFA's Vec::normalize: divides only above machine epsilon.
  static void normalize(Vec3& v) {
    const double n = v.norm();
    if (n > std::numeric_limits<double>::epsilon()) v /= n;
  }
};

}  // namespace

void register_cylinder_grid_topology(Registry& r) {
  ComponentInfo info;
  info.name = "CylinderGridTopology";
  info.category = "Topology";
  info.description = "grid of nx·ny·nz points filling a cylinder, with hexahedra, quads, triangles and edges";
  info.create = creator<CylinderGridTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
