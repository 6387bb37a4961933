#include "engine/generate/volume_from_volumetric_elements.h"

#include <cmath>
#include <Eigen/Geometry>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

VolumeFromVolumetricElements::VolumeFromVolumetricElements() {
  add_input(&position);
  add_input(&tetras);
  add_input(&hexas);
  add_output(&volume);
}

double tetra_volume(const Vec3& n0, const Vec3& n1, const Vec3& n2, const Vec3& n3) {
  return std::fabs((n1 - n0).cross(n2 - n0).dot(n3 - n0) / 6.0);
}

double hexa_volume(const std::array<Vec3, 8>& n) {
  return tetra_volume(n[0], n[5], n[1], n[6]) + tetra_volume(n[0], n[1], n[3], n[6]) +
         tetra_volume(n[1], n[3], n[6], n[2]) + tetra_volume(n[6], n[3], n[0], n[7]) +
         tetra_volume(n[6], n[7], n[0], n[5]) + tetra_volume(n[7], n[5], n[4], n[0]);
}

void VolumeFromVolumetricElements::init() {
  Node& n = *node();
  if (!position.is_set() && !position.parent()) {
    if (!mechanical) mechanical.set(n.get_mechanical_state());
    BaseField* p = mechanical ? mechanical->find_field("position") : nullptr;
    if (!p) {
      msg_error("no positions given and no mechanical state in the node: the component cannot work");
      set_state(ComponentState::invalid);
      return;
    }
    position.set_parent(p);
  }
  if (!topology) topology.set(n.get_mesh_topology_link());
  const bool has_t = tetras.is_set() || tetras.parent(), has_h = hexas.is_set() || hexas.parent();
  if (!has_t && !has_h && !topology) {
    msg_error("no tetras or hexas given and no topology in the node: the component cannot work");
    set_state(ComponentState::invalid);
    return;
  }
  if (!has_t && topology) tetras.set(topology->tetrahedra());
  if (!has_h && topology) hexas.set(topology->hexahedra());
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
  check(tetras.get(), "tetras");
  check(hexas.get(), "hexas");
  if (state() == ComponentState::invalid) return;
  compute();
}

void VolumeFromVolumetricElements::reinit() {
  if (state() == ComponentState::valid) compute();
}

void VolumeFromVolumetricElements::compute() {
  const std::vector<Vec3>& x = position.get();
  double v = 0;
  for (const Tetra& t : tetras.get()) v += tetra_volume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]);
  for (const Hexa& h : hexas.get()) {
    std::array<Vec3, 8> n;
    for (int k = 0; k < 8; ++k) n[k] = x[h[k]];
    v += hexa_volume(n);
  }
  volume.set(std::fabs(v));
}

void VolumeFromVolumetricElements::do_update() {
  if (state() != ComponentState::valid || !mechanical || !do_update_field.get()) return;
  if (position.get().size() * 3 != mechanical->read(kPosition).size()) {
    msg_error("the state's size changed: volume not updated");
    return;
  }
  compute();
}

void register_volume_from_volumetric_elements(Registry& r) {
  ComponentInfo info;
  info.name = "VolumeFromVolumetricElements";
  info.category = "Engine/Generate";
  info.description = "total volume of tetrahedra and hexahedra";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.aliases = {"VolumeFromTetrahedrons"};
  info.create = [](const std::string&) -> std::unique_ptr<Component> {
    return std::make_unique<VolumeFromVolumetricElements>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
