#include "exporter/blender_exporter.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {
constexpr int kHair = 3;
using File = std::unique_ptr<FILE, int (*)(FILE*)>;
void put_u32(FILE* f, std::uint32_t v) { std::fwrite(&v, 4, 1, f); }  // little-endian, as this machine
void put_f3(FILE* f, const double* v) {
  const float x[3] = {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
  std::fwrite(x, 4, 3, f);
}
}  // namespace

void BlenderExporter::do_init() {
  state_ = node() ? node()->find_local<MechanicalState>() : nullptr;
  if (!state_) {
    msg_error("no mechanical state in this node to export");
    set_state(ComponentState::invalid);
    return;
  }
  if (state_->state_type() != StateType::vec3 && state_->state_type() != StateType::rigid3) {
    msg_error(std::string("only Vec3d and Rigid3d states are exported (got ") + state_->info().name + ")");
    set_state(ComponentState::invalid);
    return;
  }
  const int type = simulation_type.get();
  if (type < 0 || type > kHair) {
    msg_error("simulationType " + std::to_string(type) + " (0 soft body, 1 particles, 2 cloth, 3 hair)");
    set_state(ComponentState::invalid);
    return;
  }
  if (type == kHair) {
    if (nb_pts_by_hair.get() <= 0) {
      msg_error("nbPtsByHair must be positive (got " + std::to_string(nb_pts_by_hair.get()) + ")");
      set_state(ComponentState::invalid);
      return;
    }
    // SOFA's hair info frame, at the (unsuffixed) target path.
    const std::string name = target_path(base_name(), export_every.get() != 0);
    if (name.empty()) return;
    File f(std::fopen(name.c_str(), "wb"), &std::fclose);
    if (!f) {
      msg_error("filename: cannot open '" + name + "' for writing");
      return;
    }
    std::fwrite("BPHYSICS", 1, 8, f.get());
    for (std::uint32_t v : {1u, 1u, 64u}) put_u32(f.get(), v);
    const float info[3] = {0.f, 100.f, 100.f};
    std::fwrite(info, 4, 3, f.get());
  }
}

bool BlenderExporter::write() {
  if (state() != ComponentState::valid || !state_) return false;
  const std::string base = target_path(base_name(), export_every.get() != 0);
  if (base.empty()) return false;
  const std::string name = base + "_00.bphys";
  File file(std::fopen(name.c_str(), "wb"), &std::fclose);
  if (!file) {
    msg_error("filename: cannot open '" + name + "' for writing");
    return false;
  }
  FILE* f = file.get();
  const int type = simulation_type.get();
  const bool hair = type == kHair;
  const int per_hair = nb_pts_by_hair.get();
  const std::size_t n = state_->size();
  const int cw = state_->info().coord_width, dw = state_->info().deriv_width;
  const std::vector<double>& x = state_->read(kPosition);
  const std::vector<double>& v = state_->read(kVelocity);
  const std::vector<double>& x0 = state_->read(kRestPosition);
  std::fwrite("BPHYSICS", 1, 8, f);
  put_u32(f, static_cast<std::uint32_t>(hair ? 2 : type));  // Blender has no hair cache: cloth
  put_u32(f, static_cast<std::uint32_t>(hair ? n + n / static_cast<std::size_t>(per_hair) : n));
  put_u32(f, hair ? 22u : 6u);
  const double zero[3] = {0, 0, 0};
  for (std::size_t k = n; k-- > 0;) {
    const double* p = &x[k * cw];
    if (hair && k % static_cast<std::size_t>(per_hair) == 0) {
      // The strand's root tangent point, one unit along its first segment (SOFA reads past
      // the last point for a strand of one point: none is added there, with no direction).
      double root[3] = {p[0], p[1], p[2]};
      if (k + 1 < n) {
        const double* q = &x[(k + 1) * cw];
        const double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (len > 0)
          for (int c = 0; c < 3; ++c) root[c] += d[c] / len;
      }
      put_f3(f, root);
      put_f3(f, zero);
      put_f3(f, root);
    }
    put_f3(f, p);
    put_f3(f, (k + 1) * dw <= v.size() ? &v[k * dw] : zero);
    if (hair) put_f3(f, (k + 1) * cw <= x0.size() ? &x0[k * cw] : zero);
  }
  if (std::ferror(f)) {
    msg_error("filename: write error on '" + name + "'");
    return false;
  }
  if (print_log.get()) msg_info("exported " + name);
  return true;
}

void register_blender_exporter(Registry& r) {
  ComponentInfo info;
  info.name = "BlenderExporter";
  info.category = "Exporter";
  info.description = "the node's state as a Blender point cache (.bphys) every few steps";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<BlenderExporter>();
  r.add(std::move(info));
}

}  // namespace sinew
