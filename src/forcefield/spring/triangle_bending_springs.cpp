#include "forcefield/spring/triangle_bending_springs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void TriangleBendingSprings::init() {
  if (!bind_states()) return;
  springs_.clear();
  generated_ = true;
  if (!topology) topology.set(node()->get_mesh_topology_link());
  if (!topology) {
    msg_error("no topology found (the springs are built from triangles)");
    set_state(ComponentState::invalid);
    return;
  }
  const double ks = stiffness.get().empty() ? 100.0 : stiffness.get()[0];
  const double kd = damping.get().empty() ? 5.0 : damping.get()[0];
  stiffness.set({ks});
  damping.set({kd});
  const std::vector<double>& x = s1_->read(kPosition);
  const std::size_t np = s1_->size();
  const int N = dim_;
  bool bad = false;
  const auto add_spring = [&](unsigned a, unsigned b) {
    if (a >= np || b >= np) {
      if (!bad)
        msg_error("a triangle refers to point " + std::to_string(std::max(a, b)) + " but the state has " +
                  std::to_string(np) + " points");
      bad = true;
      return;
    }
    double n2 = 0;
    for (int c = 0; c < N; ++c) {
      const double u = x[a * N + c] - x[b * N + c];
      n2 = c == 0 ? u * u : n2 + u * u;
    }
    springs_.push_back({a, b, ks, kd, std::sqrt(n2), false, true});
  };
  using Pair = std::pair<unsigned, unsigned>;
  std::map<Pair, unsigned> opposite_of;  // edge → the opposite vertex of its first triangle
  const auto register_edge = [&](unsigned a, unsigned b, unsigned opposite) {
    const Pair edge(std::min(a, b), std::max(a, b));
    const auto [it, first] = opposite_of.emplace(edge, opposite);
    if (!first) add_spring(opposite, it->second);
  };
  const auto register_triangle = [&](unsigned a, unsigned b, unsigned c) {
    register_edge(a, b, c);
    register_edge(b, c, a);
    register_edge(c, a, b);
  };
  for (const Triangle& t : topology->triangles()) register_triangle(t[0], t[1], t[2]);
  for (const Quad& q : topology->quads()) {
    register_triangle(q[0], q[1], q[2]);
    register_triangle(q[0], q[2], q[3]);
  }
  if (bad) {
    set_state(ComponentState::invalid);
    return;
  }
  SpringForceField::init();
}

void register_triangle_bending_springs(Registry& r) {
  ComponentInfo info;
  info.name = "TriangleBendingSprings";
  info.category = "ForceField/Spring";
  info.description = "springs between the opposite vertices of triangles sharing an edge";
  info.templates = {"Vec3d", "Vec2d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TriangleBendingSprings>();
  r.add(std::move(info));
}

}  // namespace sinew
