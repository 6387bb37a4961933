#include "engine/generate/volume_from_triangles.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"
#include "core/state_creator.h"
#include "engine/empty_coords.h"

namespace sinew {

VolumeFromTriangles::VolumeFromTriangles(StateType type)
    : position(this, "position", empty_coords(type), "points of the surface (default: the node's state's position)",
               "Inputs", "length") {
  add_input(&position);
  add_input(&triangles);
  add_input(&quads);
  add_output(&volume);
}

double enclosed_volume(const std::vector<double>& x, int width, const std::vector<Triangle>& tris,
                       const std::vector<Quad>& quads) {
  const std::size_t w = static_cast<std::size_t>(width);
  auto term = [&](unsigned a, unsigned b, unsigned c) {
    const double* p0 = &x[a * w];
    const double* p1 = &x[b * w];
    const double* p2 = &x[c * w];
    return ((p1[1] - p0[1]) * (p2[2] - p0[2]) - (p2[1] - p0[1]) * (p1[2] - p0[2])) * (p0[0] + p1[0] + p2[0]) / 6;
  };
  double v = 0;
  for (const Triangle& t : tris) v += term(t[0], t[1], t[2]);
  for (const Quad& q : quads) {
    v += term(q[0], q[1], q[2]);
    v += term(q[0], q[2], q[3]);
  }
  return std::fabs(v);
}

void VolumeFromTriangles::init() {
  Node& n = *node();
  if (!position.is_set() && !position.parent()) {
    if (!mechanical) mechanical.set(n.get_mechanical_state());
    if (!mechanical) {
      msg_error("no positions given and no mechanical state in the node: the component cannot work");
      set_state(ComponentState::invalid);
      return;
    }
    BaseField* p = mechanical->find_field("position");
    if (!p) {
      msg_error("the mechanical state has no 'position'");
      set_state(ComponentState::invalid);
      return;
    }
    position.set_parent(p);
  }
  if (!topology) topology.set(n.get_mesh_topology_link());
  const bool has_t = triangles.is_set() || triangles.parent(), has_q = quads.is_set() || quads.parent();
  if (!has_t && !has_q && !topology) {
    msg_error("no triangles or quads given and no topology in the node: the component cannot work");
    set_state(ComponentState::invalid);
    return;
  }
  if (!has_t && topology) triangles.set(topology->triangles());
  if (!has_q && topology) quads.set(topology->quads());
  const std::size_t np = position.get().size();
  auto check = [&](const auto& elems, const char* what) {
    for (std::size_t i = 0; i < elems.size(); ++i)
      for (std::size_t j = 0; j < elems[i].size(); ++j)
        if (elems[i][j] >= np) {
          msg_error(std::string(what) + "[" + std::to_string(i) + "][" + std::to_string(j) + "] = " +
                    std::to_string(elems[i][j]) + " is beyond the " + std::to_string(np) + " positions");
          set_state(ComponentState::invalid);
          return;
        }
  };
  check(triangles.get(), "triangles");
  check(quads.get(), "quads");
  if (state() == ComponentState::invalid) return;
  compute();
}

void VolumeFromTriangles::reinit() {
  if (state() == ComponentState::valid) compute();
}

void VolumeFromTriangles::compute() {
  const FlatVec& x = position.get();
  volume.set(enclosed_volume(x.data, x.width, triangles.get(), quads.get()));
}

void VolumeFromTriangles::do_update() {
  if (state() != ComponentState::valid || !mechanical || !do_update_field.get()) return;
  if (mechanical->read(kPosition).size() != position.get().data.size()) {
    msg_error("the state's size changed: volume not updated");
    return;
  }
  compute();
}

void register_volume_from_triangles(Registry& r) {
  ComponentInfo info;
  info.name = "VolumeFromTriangles";
  info.category = "Engine/Generate";
  info.description = "volume enclosed by a closed triangle/quad surface";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<VolumeFromTriangles>();
  r.add(std::move(info));
}

}  // namespace sinew
