#include "forcefield/spring/regular_grid_spring_force_field.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"
#include "topology/grid/regular_grid_topology.h"

namespace sinew {

namespace {
// |v| as SOFA computes it (squares summed in index order).
double norm3(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
}  // namespace

void RegularGridSpringForceField::parse(AttributeMap& attrs, Diagnostics& diag) {
  // `stiffness`/`damping` are SOFA aliases of the three per-element values (and the base lists).
  if (const std::string* s = attrs.peek("stiffness"); s && !s->empty() && (*s)[0] != '@')
    for (Field<double>* f : {&lines_stiffness, &quads_stiffness, &cubes_stiffness}) f->read(*s);
  if (const std::string* d = attrs.peek("damping"); d && !d->empty() && (*d)[0] != '@')
    for (Field<double>* f : {&lines_damping, &quads_damping, &cubes_damping}) f->read(*d);
  SpringForceField::parse(attrs, diag);
}

void RegularGridSpringForceField::init() {
  if (!bind_states()) return;
  grid_springs_.clear();
  if (s1_ == s2_) {
    auto* grid = dynamic_cast<RegularGridTopology*>(s1_->node() ? s1_->node()->find_up<MeshTopologyBase>() : nullptr);
    if (!grid) {
      msg_warning("the first topology of the state's node is not a RegularGridTopology: only explicit springs are used");
    } else if (dim_ != 3) {
      msg_error("grid springs need a Vec3d state");
      set_state(ComponentState::invalid);
      return;
    } else {
      grid->edges();  // generates the grid if it was not yet
      const VecNi<3> n = grid->dims();
      const int nx = n[0], ny = n[1], nz = n[2];
      const Vec3 dx = grid->dx(), dy = grid->dy(), dz = grid->dz();
      auto pt = [&](int x, int y, int z) { return static_cast<unsigned>(grid->point_index(x, y, z)); };
      auto make = [](double l0, double k, double d) {
        springs::LinearSpring s;
        s.l0 = l0;
        s.ks = k / l0;
        s.kd = d / l0;
        return s;
      };
      auto push = [&](springs::LinearSpring s, unsigned a, unsigned b) {
        s.m1 = a;
        s.m2 = b;
        grid_springs_.push_back(s);
      };
      const double ls = lines_stiffness.get(), ld = lines_damping.get();
      if (ls != 0.0 || ld != 0.0) {
        springs::LinearSpring s = make(norm3(dx), ls, ld);
        for (int z = 0; z < nz; z++)
          for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx - 1; x++) push(s, pt(x, y, z), pt(x + 1, y, z));
        s = make(norm3(dy), ls, ld);
        for (int z = 0; z < nz; z++)
          for (int y = 0; y < ny - 1; y++)
            for (int x = 0; x < nx; x++) push(s, pt(x, y, z), pt(x, y + 1, z));
        s = make(norm3(dz), ls, ld);
        for (int z = 0; z < nz - 1; z++)
          for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx; x++) push(s, pt(x, y, z), pt(x, y, z + 1));
      }
      const double qs = quads_stiffness.get(), qd = quads_damping.get();
      if (qs != 0.0 || qd != 0.0) {
        springs::LinearSpring s1 = make(norm3(dx + dy), qs, qd), s2 = make(norm3(dx - dy), qs, qd);
        for (int z = 0; z < nz; z++)
          for (int y = 0; y < ny - 1; y++)
            for (int x = 0; x < nx - 1; x++) {
              push(s1, pt(x, y, z), pt(x + 1, y + 1, z));
              push(s2, pt(x + 1, y, z), pt(x, y + 1, z));
            }
        s1 = make(norm3(dx + dz), qs, qd);
        s2 = make(norm3(dx - dz), qs, qd);
        for (int z = 0; z < nz - 1; z++)
          for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx - 1; x++) {
              push(s1, pt(x, y, z), pt(x + 1, y, z + 1));
              push(s2, pt(x + 1, y, z), pt(x, y, z + 1));
            }
        s1 = make(norm3(dy + dz), qs, qd);
        // SOFA divides the second yz spring's stiffness/damping by the first one's length.
        s2 = s1;
        s2.l0 = norm3(dy - dz);
        for (int z = 0; z < nz - 1; z++)
          for (int y = 0; y < ny - 1; y++)
            for (int x = 0; x < nx; x++) {
              push(s1, pt(x, y, z), pt(x, y + 1, z + 1));
              push(s2, pt(x, y + 1, z), pt(x, y, z + 1));
            }
      }
      const double cs = cubes_stiffness.get(), cd = cubes_damping.get();
      if (cs != 0.0 || cd != 0.0) {
        const springs::LinearSpring c1 = make(norm3(dx + dy + dz), cs, cd);
        const springs::LinearSpring c2 = make(norm3(-dx + dy + dz), cs, cd);
        const springs::LinearSpring c3 = make(norm3(dx - dy + dz), cs, cd);
        const springs::LinearSpring c4 = make(norm3(dx + dy - dz), cs, cd);
        for (int z = 0; z < nz - 1; z++)
          for (int y = 0; y < ny - 1; y++)
            for (int x = 0; x < nx - 1; x++) {
              push(c1, pt(x, y, z), pt(x + 1, y + 1, z + 1));
              push(c2, pt(x + 1, y, z), pt(x, y + 1, z + 1));
              push(c3, pt(x, y + 1, z), pt(x + 1, y, z + 1));
              push(c4, pt(x, y, z + 1), pt(x + 1, y + 1, z));
            }
      }
    }
  }
  SpringForceField::init();
}

void register_regular_grid_spring_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "RegularGridSpringForceField";
  info.category = "ForceField/Spring";
  info.description = "springs along the lines and diagonals of a regular grid";
  info.templates = {"Vec1d", "Vec2d", "Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<RegularGridSpringForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
