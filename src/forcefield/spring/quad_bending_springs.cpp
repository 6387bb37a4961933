#include "forcefield/spring/quad_bending_springs.h"

#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void QuadBendingSprings::init() {
  if (!bind_states()) return;
  springs_.clear();
  generated_ = true;
  if (!topology) topology.set(node()->get_mesh_topology_link());
  if (!topology) {
    msg_error("no topology found (the springs are built from quads)");
    set_state(ComponentState::invalid);
    return;
  }
  using Pair = std::pair<unsigned, unsigned>;
  std::map<Pair, Pair> edge_map;
  std::set<Pair> spring_set;
  const std::vector<double>& x = s1_->read(kPosition);
  const std::size_t np = s1_->size();
  const int N = dim_;
  const double ks = stiffness.get().empty() ? 100.0 : stiffness.get()[0];
  const double kd = damping.get().empty() ? 5.0 : damping.get()[0];
  const VecNi<2> range = local_range.get();
  bool bad = false;
  auto add_spring = [&](unsigned a, unsigned b) {
    if (range[0] >= 0 && static_cast<int>(a) < range[0] && static_cast<int>(b) < range[0]) return;
    if (range[1] >= 0 && static_cast<int>(a) > range[1] && static_cast<int>(b) > range[1]) return;
    if (!spring_set.insert(Pair(std::min(a, b), std::max(a, b))).second) return;
    if (a >= np || b >= np) {
      if (!bad)
        msg_error("a quad refers to point " + std::to_string(std::max(a, b)) + " but the state has " +
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
  auto register_edge = [&](Pair ab, Pair cd) {
    if (ab.first > ab.second) {
      ab = Pair(ab.second, ab.first);
      cd = Pair(cd.second, cd.first);
    }
    auto it = edge_map.find(ab);
    if (it == edge_map.end()) {
      edge_map[ab] = cd;
    } else {
      const Pair ef = it->second;
      add_spring(cd.first, ef.first);
      add_spring(cd.second, ef.second);
    }
  };
  for (const Quad& f : topology->quads()) {
    register_edge(Pair(f[0], f[1]), Pair(f[3], f[2]));
    register_edge(Pair(f[1], f[2]), Pair(f[0], f[3]));
    register_edge(Pair(f[2], f[3]), Pair(f[1], f[0]));
    register_edge(Pair(f[3], f[0]), Pair(f[2], f[1]));
  }
  if (bad) {
    set_state(ComponentState::invalid);
    return;
  }
  SpringForceField::init();
}

void register_quad_bending_springs(Registry& r) {
  ComponentInfo info;
  info.name = "QuadBendingSprings";
  info.category = "ForceField/Spring";
  info.description = "springs between the opposite vertices of quads sharing an edge";
  info.templates = {"Vec1d", "Vec2d", "Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<QuadBendingSprings>();
  r.add(std::move(info));
}

}  // namespace sinew
