#include "forcefield/spring/mesh_spring_force_field.h"

#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

MeshSpringForceField::MeshSpringForceField() {
  tetrahedra_stiffness.add_alias("tetrasStiffness");
  tetrahedra_damping.add_alias("tetrasDamping");
}

void MeshSpringForceField::parse(AttributeMap& attrs, Diagnostics& diag) {
  // SOFA aliases `stiffness` and `damping` to all five per-element values
  // (and the base lists keep them too); an explicit per-element value wins.
  if (const std::string* s = attrs.peek("stiffness"); s && !s->empty() && (*s)[0] != '@')
    for (Field<double>* f : {&lines_stiffness, &triangles_stiffness, &quads_stiffness, &tetrahedra_stiffness,
                             &cubes_stiffness})
      f->read(*s);
  if (const std::string* d = attrs.peek("damping"); d && !d->empty() && (*d)[0] != '@')
    for (Field<double>* f :
         {&lines_damping, &triangles_damping, &quads_damping, &tetrahedra_damping, &cubes_damping})
      f->read(*d);
  SpringForceField::parse(attrs, diag);
}

void MeshSpringForceField::init() {
  if (!bind_states()) return;
  if (!springs_indices1.get().empty() || !springs_indices2.get().empty())
    msg_warning("indices1/indices2 are ignored: the springs are built from the mesh");
  springs_.clear();
  generated_ = true;
  if (s1_ == s2_) {
    if (!topology) topology.set(node()->get_mesh_topology_link());
    if (!topology) {
      msg_error("no topology found (the springs are built from a mesh)");
      set_state(ComponentState::invalid);
      return;
    }
    const std::vector<double>& x0 = s1_->read(kRestPosition);
    const int N = dim_;
    const std::size_t np = s1_->size();
    const VecNi<2> range = local_range.get();
    const bool no_comp = no_compression.get();
    std::set<std::pair<unsigned, unsigned>> seen;
    bool bad = false;
    auto add = [&](unsigned m1, unsigned m2, double s, double d) {
      if (range[0] >= 0 && (m1 < static_cast<unsigned>(range[0]) || m2 < static_cast<unsigned>(range[0]))) return;
      if (range[1] >= 0 && m1 > static_cast<unsigned>(range[1]) && m2 > static_cast<unsigned>(range[1])) return;
      if (!seen.insert(m1 < m2 ? std::make_pair(m1, m2) : std::make_pair(m2, m1)).second) return;
      if (m1 >= np || m2 >= np) {
        if (!bad)
          msg_error("the topology refers to point " + std::to_string(std::max(m1, m2)) + " but the state has " +
                    std::to_string(np) + " points");
        bad = true;
        return;
      }
      double n2 = 0;
      for (int c = 0; c < N; ++c) {
        const double u = x0[m2 * N + c] - x0[m1 * N + c];
        n2 = c == 0 ? u * u : n2 + u * u;
      }
      const double l = std::sqrt(n2);
      if (l > std::numeric_limits<double>::epsilon())
        springs_.push_back({m1, m2, s / l, d / l, l, no_comp, true});
      else
        springs_.push_back({m1, m2, s, d, l, no_comp, true});
    };
    const MeshTopologyBase& t = *topology;
    if (lines_stiffness.get() != 0.0 || lines_damping.get() != 0.0)
      for (const Edge& e : t.edges()) add(e[0], e[1], lines_stiffness.get(), lines_damping.get());
    if (triangles_stiffness.get() != 0.0 || triangles_damping.get() != 0.0) {
      const double s = triangles_stiffness.get(), d = triangles_damping.get();
      for (const Triangle& e : t.triangles()) {
        add(e[0], e[1], s, d);
        add(e[0], e[2], s, d);
        add(e[1], e[2], s, d);
      }
    }
    if (quads_stiffness.get() != 0.0 || quads_damping.get() != 0.0) {
      const double s = quads_stiffness.get(), d = quads_damping.get();
      for (const Quad& e : t.quads())
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j) add(e[i], e[j], s, d);
    }
    if (tetrahedra_stiffness.get() != 0.0 || tetrahedra_damping.get() != 0.0) {
      const double s = tetrahedra_stiffness.get(), d = tetrahedra_damping.get();
      for (const Tetra& e : t.tetrahedra())
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j) add(e[i], e[j], s, d);
    }
    if (cubes_stiffness.get() != 0.0 || cubes_damping.get() != 0.0) {
      const double s = cubes_stiffness.get(), d = cubes_damping.get();
      for (const Hexa& e : t.hexahedra())
        for (int i = 0; i < 8; ++i)
          for (int j = i + 1; j < 8; ++j) add(e[i], e[j], s, d);
    }
    if (bad) {
      set_state(ComponentState::invalid);
      return;
    }
  }
  SpringForceField::init();
}

void register_mesh_spring_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "MeshSpringForceField";
  info.category = "ForceField/Spring";
  info.description = "springs along the edges (and diagonals) of the mesh elements";
  info.templates = {"Vec1d", "Vec2d", "Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<MeshSpringForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
