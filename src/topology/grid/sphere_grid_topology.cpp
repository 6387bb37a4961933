// SphereGridTopology: the connectivity of a regular nx·ny·nz grid with its
// points placed in a ball (SOFA's SphereGridTopology): the cube [−r, r]³ of
// the grid is mapped onto the ball of `radius` around `center` (a point keeps
// its direction and takes the distance max(|x|, |y|, |z|)), the grid's z
// along `axis`. RegularGridTopology's min/max do not apply (SOFA's class has
// no such Data).
#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "core/registry.h"
#include "topology/grid/regular_grid_topology.h"

namespace sinew {

namespace {

class SphereGridTopology final : public RegularGridTopology {
 public:
  Field<Vec3> center{this, "center", Vec3::Zero(), "centre of the sphere", "Grid", "length"};
  Field<Vec3> axis{this, "axis", Vec3(0, 0, 1), "direction of the grid's z axis", "Grid"};
  Field<double> radius{this, "radius", 1.0, "radius of the sphere", "Grid", "length"};

  void init() override {
    if (!(axis.value().norm() > 0) || !axis.value().allFinite()) {
      msg_error("axis must be a non-zero finite vector");
      set_state(ComponentState::invalid);
      return;
    }
    const VecNi<3> d = n.get();
    if (d[0] < 2 || d[1] < 2 || d[2] < 2) {
      msg_error("needs at least 2 points along each direction (n >= 2 2 2)");
      set_state(ComponentState::invalid);
      return;
    }
    RegularGridTopology::init();
  }

 protected:
  Vec3 grid_point(int i, int j, int k) const override {
    const double r = radius.value();
    Vec3 z = axis.value();
    normalize(z);
    Vec3 x = (z - Vec3(1, 0, 0)).norm() < 0.000001 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    Vec3 y = z.cross(x);
    x = y.cross(z);
    normalize(x);
    normalize(y);
    normalize(z);
    const VecNi<3> d = dims();
    Vec3 p(i * 2 * r / (d[0] - 1) - r, j * 2 * r / (d[1] - 1) - r, k * 2 * r / (d[2] - 1) - r);
    // The cube onto the ball: same direction, distance max(|x|, |y|, |z|).
    if (p.norm() > 0.0000001) {
      const double m = std::max(std::max(std::abs(p[0]), std::abs(p[1])), std::abs(p[2]));
      p *= m / p.norm();
    }
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

void register_sphere_grid_topology(Registry& r) {
  ComponentInfo info;
  info.name = "SphereGridTopology";
  info.category = "Topology";
  info.description = "grid of nx·ny·nz points filling a ball, with hexahedra, quads, triangles and edges";
  info.create = creator<SphereGridTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
