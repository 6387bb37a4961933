#include "io/voxel_grid_loader.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "core/registry.h"

namespace sinew {

VoxelGridLoader::VoxelGridLoader() {
  filename.set_file(true);
  filename.add_alias("segmentationFile");
  for (BaseField* f : std::initializer_list<BaseField*>{&filename, &voxel_size, &resolution, &roi, &header, &bg_value,
                                                        &data_value, &generate_hexa})
    add_input(f);
  add_output(&position);
  add_output(&hexahedra);
  add_output(&idx_in_regular_grid);
}

bool VoxelGridLoader::load() {
  loaded_ = false;
  voxels_.clear();
  const VecNi<3> res = resolution.get();
  const std::string& path = filename.get();
  if (res[0] <= 0 || res[1] <= 0 || res[2] <= 0) {
    msg_error("resolution must be positive along x, y and z (got " + std::to_string(res[0]) + " " +
              std::to_string(res[1]) + " " + std::to_string(res[2]) + ")");
    return false;
  }
  if (path.size() <= 4 || path.compare(path.size() - 4, 4, ".raw") != 0) {
    msg_error("'" + path + "' is not a .raw file");
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    msg_error("cannot open '" + path + "'");
    return false;
  }
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t h = static_cast<std::size_t>(std::max(0, header.get()));
  const std::size_t n = static_cast<std::size_t>(res[0]) * static_cast<std::size_t>(res[1]) *
                        static_cast<std::size_t>(res[2]);
  if (bytes.size() < h + n) {
    msg_error("'" + path + "' holds " + std::to_string(bytes.size()) + " bytes, fewer than the header (" +
              std::to_string(h) + ") and " + std::to_string(n) + " voxels");
    return false;
  }
  voxels_.assign(bytes.begin() + static_cast<std::ptrdiff_t>(h), bytes.begin() + static_cast<std::ptrdiff_t>(h + n));
  loaded_ = true;
  return true;
}

void VoxelGridLoader::init() {
  load();
  const VecNi<3> res = resolution.get();
  std::vector<int> r = roi.get();
  if (r.size() != 6) {
    msg_error("ROI needs 6 values (xmin ymin zmin xmax ymax zmax), got " + std::to_string(r.size()) +
              ": the whole image is used");
    r = {0, 0, 0, 0xFFFF, 0xFFFF, 0xFFFF};
  }
  for (int k = 0; k < 3; ++k) {
    if (r[k] < 0) r[k] = 0;
    if (r[k + 3] >= res[k]) r[k + 3] = res[k] - 1;
    if (r[k] > r[k + 3]) r[k + 3] = r[k];
  }
  roi.set(r);
  if (!loaded_) {
    msg_error("error while loading '" + filename.get() + "': no points or hexahedra");
    set_state(ComponentState::invalid);
    return;
  }
  reinit();
}

void VoxelGridLoader::reinit() {
  set_dirty();
  update();
}

bool VoxelGridLoader::active(std::size_t idx) const {
  const std::vector<int>& act = data_value.get();
  const std::vector<int>& bg = bg_value.get();
  if (act.empty() && bg.empty()) return true;
  const int v = voxels_[idx];
  // SOFA binary-searches the lists as given.
  if (!act.empty()) return std::binary_search(act.begin(), act.end(), v);
  return !std::binary_search(bg.begin(), bg.end(), v);
}

void VoxelGridLoader::do_update() {
  std::vector<Vec3> pts;
  std::vector<Hexa> hexa;
  std::vector<unsigned> ids;
  if (loaded_ && state() == ComponentState::valid && roi.get().size() == 6) {
    const VecNi<3> res = resolution.get();
    const std::vector<int> r = roi.get();
    const Vec3 s = voxel_size.get();
    const std::size_t nx = static_cast<std::size_t>(res[0]), ny = static_cast<std::size_t>(res[1]);
    const std::size_t i0 = static_cast<std::size_t>(r[0]), j0 = static_cast<std::size_t>(r[1]),
                      k0 = static_cast<std::size_t>(r[2]), i1 = static_cast<std::size_t>(r[3]),
                      j1 = static_cast<std::size_t>(r[4]), k1 = static_cast<std::size_t>(r[5]);
    auto vox = [&](std::size_t i, std::size_t j, std::size_t k) { return i + j * nx + k * nx * ny; };
    if (i1 >= nx || j1 >= ny || k1 >= static_cast<std::size_t>(res[2])) {
      msg_error("the ROI reaches beyond the image (call init after changing the resolution)");
    } else if (generate_hexa.get()) {
      const std::size_t px = nx + 1, py = ny + 1;
      auto pid = [&](std::size_t i, std::size_t j, std::size_t k) { return i + j * px + k * px * py; };
      std::set<std::size_t> keep;
      for (std::size_t k = k0; k <= k1; ++k)
        for (std::size_t j = j0; j <= j1; ++j)
          for (std::size_t i = i0; i <= i1; ++i)
            if (active(vox(i, j, k)))
              for (std::size_t q = 0; q < 8; ++q) keep.insert(pid(i + q % 2, j + ((q & 2) >> 1), k + q / 4));
      std::map<std::size_t, unsigned> renumber;
      for (std::size_t k = k0; k <= k1 + 1; ++k)
        for (std::size_t j = j0; j <= j1 + 1; ++j)
          for (std::size_t i = i0; i <= i1 + 1; ++i)
            if (keep.count(pid(i, j, k))) {
              renumber[pid(i, j, k)] = static_cast<unsigned>(pts.size());
              pts.emplace_back(static_cast<double>(i) * s[0], static_cast<double>(j) * s[1],
                               static_cast<double>(k) * s[2]);
            }
      for (std::size_t k = k0; k <= k1; ++k)
        for (std::size_t j = j0; j <= j1; ++j)
          for (std::size_t i = i0; i <= i1; ++i) {
            const std::size_t idx = vox(i, j, k);
            if (!active(idx)) continue;
            unsigned p[8];
            for (std::size_t q = 0; q < 8; ++q) p[q] = renumber[pid(i + q % 2, j + ((q & 2) >> 1), k + q / 4)];
            // Corners q are (x, y, z) bits; SOFA's hexahedron order turns each face around.
            hexa.push_back({p[0], p[1], p[3], p[2], p[4], p[5], p[7], p[6]});
            ids.push_back(static_cast<unsigned>(idx));
          }
    } else {
      for (std::size_t k = k0; k <= k1; ++k)
        for (std::size_t j = j0; j <= j1; ++j)
          for (std::size_t i = i0; i <= i1; ++i) {
            const std::size_t idx = vox(i, j, k);
            if (!active(idx)) continue;
            pts.emplace_back(static_cast<double>(i) * s[0], static_cast<double>(j) * s[1],
                             static_cast<double>(k) * s[2]);
            ids.push_back(static_cast<unsigned>(idx));
          }
    }
  }
  position.set(std::move(pts));
  hexahedra.set(std::move(hexa));
  idx_in_regular_grid.set(std::move(ids));
}

void register_voxel_grid_loader(Registry& r) {
  ComponentInfo info;
  info.name = "VoxelGridLoader";
  info.category = "Loader";
  info.description = "hexahedra or points from the active voxels of a raw 8-bit image";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<VoxelGridLoader>(); };
  r.add(std::move(info));
}

}  // namespace sinew
