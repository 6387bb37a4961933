#include "io/sphere_loader.h"

#include "core/registry.h"
#include "io/mesh_readers.h"
#include "io/sofa_quat.h"

namespace sinew {

SphereLoader::SphereLoader() {
  filename.set_file(true);
  position.add_alias("sphere_centers");
  scale.add_alias("scale3d");
  for (BaseField* f : std::initializer_list<BaseField*>{&filename, &scale, &rotation, &translation}) add_input(f);
  add_output(&position);
  add_output(&list_radius);
}

void SphereLoader::init() { update(); }

void SphereLoader::do_update() {
  std::string error;
  std::optional<io::MeshData> m;
  if (filename.get().empty()) error = "no file name given (attribute 'filename')";
  else m = io::read_sph(filename.get(), &error);
  if (!m) {
    msg_error(error);
    set_state(ComponentState::invalid);
    position.set({});
    list_radius.set({});
    return;
  }
  set_state(ComponentState::valid);
  const Vec3 s = scale.get(), r = rotation.get(), t = translation.get();
  if (!io::sofa_vec_eq(s, Vec3::Ones()) || !io::sofa_vec_eq(r, Vec3::Zero()) || !io::sofa_vec_eq(t, Vec3::Zero())) {
    if (!io::sofa_vec_eq(s, Vec3::Ones()) && (s[0] == 0.0 || s[1] == 0.0 || s[2] == 0.0))
      msg_warning("scale should not be zero");
    const auto M = io::trs_matrix(t, r, s);
    for (Vec3& p : m->positions) p = io::transform_point(M, p);
  }
  position.set(std::move(m->positions));
  list_radius.set(std::move(m->radii));
}

void register_sphere_loader(Registry& r) {
  ComponentInfo info;
  info.name = "SphereLoader";
  info.category = "Loader";
  info.description = "loads sphere centres and radii from a .sph file";
  info.create = creator<SphereLoader>();
  r.add(std::move(info));
}

}  // namespace sinew
