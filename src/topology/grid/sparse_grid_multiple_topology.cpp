#include "topology/grid/sparse_grid_multiple_topology.h"

#include <limits>

#include "core/registry.h"
#include "io/mesh_readers.h"

namespace sinew {

SparseGridMultipleTopology::SparseGridMultipleTopology() {
  file_topologies.set_file(true);
}

void SparseGridMultipleTopology::generate() {
  if (compute_ramifications.value() && finest_connectivity.value() && filename.value().empty() &&
      position.value().empty()) {
    // SOFA warns and leaves every cell unconnected; that grid falls apart under any force.
    msg_error("fileTopology is needed: with computeRamifications and finestConnectivity its surface decides which "
              "cells are connected");
    build_failed_ = true;
    return;
  }
  if (compute_ramifications.value()) {
    SparseGridRamificationTopology::generate();
    return;
  }
  climb_lookup_ = false;
  SparseGridTopology::generate();
}

unsigned SparseGridMultipleTopology::find_cube(const Vec3& p, double& fx, double& fy, double& fz) const {
  return compute_ramifications.value() ? SparseGridRamificationTopology::find_cube(p, fx, fy, fz)
                                       : SparseGridTopology::find_cube(p, fx, fy, fz);
}

unsigned SparseGridMultipleTopology::find_nearest_cube(const Vec3& p, double& fx, double& fy, double& fz) const {
  return compute_ramifications.value() ? SparseGridRamificationTopology::find_nearest_cube(p, fx, fy, fz)
                                       : SparseGridTopology::find_nearest_cube(p, fx, fy, fz);
}

// SOFA's buildAsFinest for several files: the surface given (fileTopology) is not voxelized here.
bool SparseGridMultipleTopology::build_from_surface(Level& L, VecNi<3> dims, Vec3 lo, Vec3 hi, double /*width*/,
                                                    bool only_inside, const std::vector<Vec3>& /*vertices*/,
                                                    const std::vector<std::vector<unsigned>>& /*facets*/) const {
  const std::vector<std::string>& files = file_topologies.value();
  if (files.empty()) {
    msg_error("No file topology provided");
    return false;
  }
  // Missing coefficients are 1 (SOFA warns and appends them).
  std::vector<float> stiffness, mass;
  for (double c : stiffness_coefs.value()) stiffness.push_back(static_cast<float>(c));
  for (double c : mass_coefs.value()) mass.push_back(static_cast<float>(c));
  if (stiffness.size() < files.size()) {
    msg_warning("not enough stiffnessCoefs: 1 for the last " + std::to_string(files.size() - stiffness.size()) +
                " files");
    stiffness.resize(files.size(), 1.0f);
  }
  if (mass.size() < files.size()) {
    msg_warning("not enough massCoefs: 1 for the last " + std::to_string(files.size() - mass.size()) + " files");
    mass.resize(files.size(), 1.0f);
  }

  // Each surface, and the box around all of them.
  struct Surface {
    std::vector<Vec3> vertices;
    std::vector<std::vector<unsigned>> facets;
  };
  std::vector<Surface> surfaces(files.size());
  Vec3 box_lo = Vec3::Constant(std::numeric_limits<double>::max());
  Vec3 box_hi = Vec3::Constant(std::numeric_limits<double>::lowest());
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string& file = files[i];
    if (file.size() < 5 || file.compare(file.size() - 4, 4, ".obj") != 0) {
      msg_error("fileTopologies: '" + file + "' is not an .obj file (the only format SOFA reads here)");
      return false;
    }
    std::string err;
    const std::optional<io::MeshData> mesh = io::read_obj(file, &err);
    if (!mesh) {
      msg_error("Loading mesh " + file + " failed: " + err);
      return false;
    }
    Surface& s = surfaces[i];
    s.vertices = mesh->positions_definition.empty() ? mesh->positions : mesh->positions_definition;
    for (const auto& f : mesh->face_positions) {
      std::vector<unsigned> poly;
      for (int v : f)
        if (v >= 0) poly.push_back(static_cast<unsigned>(v));
      for (unsigned v : poly)
        if (v >= s.vertices.size()) {
          msg_error("Loading mesh " + file + " failed: a face uses vertex " + std::to_string(v) + " of " +
                    std::to_string(s.vertices.size()));
          return false;
        }
      s.facets.push_back(std::move(poly));
    }
    if (s.vertices.empty()) {
      msg_error("Loading mesh " + file + " failed: no vertex");
      return false;
    }
    for (const Vec3& v : s.vertices)
      for (int a = 0; a < 3; ++a) {
        box_lo[a] = std::min(box_lo[a], v[a]);
        box_hi[a] = std::max(box_hi[a], v[a]);
      }
  }
  if (lo == Vec3::Zero() && hi == Vec3::Zero()) {
    Vec3 diff = box_hi - box_lo;
    diff /= 100.0;
    lo = box_lo - diff;
    hi = box_hi + diff;
  }
  L.min = lo;
  L.max = hi;
  L.grid.set(dims, lo, hi);

  // SOFA's assembleRegularGrids: later files override earlier ones where they are.
  const std::size_t nc = static_cast<std::size_t>(L.grid.nb_cells());
  std::vector<CellType> types(nc, CellType::outside);
  std::vector<float> cell_stiffness(nc, 0.0f), cell_mass(nc, 0.0f);
  const bool weighted = fill_weighted.value(), erase = erase_previous_coef.value();
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    std::vector<CellType> file_types;
    if (!voxelize(L.grid, lo, hi, surfaces[i].vertices, surfaces[i].facets, file_types)) return false;
    for (std::size_t w = 0; w < nc; ++w) {
      if (file_types[w] == CellType::inside || (file_types[w] == CellType::boundary && !weighted)) {
        types[w] = CellType::inside;
        cell_stiffness[w] = stiffness[i];
        cell_mass[w] = mass[i];
      } else if (file_types[w] == CellType::boundary) {
        if (types[w] != CellType::inside) types[w] = CellType::boundary;
        cell_stiffness[w] = erase ? stiffness[i] : (cell_stiffness[w] + stiffness[i]) * .5f;
        cell_mass[w] = erase ? mass[i] : (cell_mass[w] + mass[i]) * .5f;
      }
    }
  }
  build_from_types(L, types, only_inside);
  L.stiffness.clear();
  L.mass.clear();
  for (std::size_t w = 0; w < nc; ++w)
    if (L.sparse_of_regular[w] >= 0) {
      // Hexahedra are listed boundary cells first: place each by its sparse index.
      const auto h = static_cast<std::size_t>(L.sparse_of_regular[w]);
      if (L.stiffness.size() <= h) {
        L.stiffness.resize(h + 1);
        L.mass.resize(h + 1);
      }
      L.stiffness[h] = cell_stiffness[w];
      L.mass[h] = cell_mass[w];
    }
  return true;
}

void register_sparse_grid_multiple_topology(Registry& r) {
  ComponentInfo info;
  info.name = "SparseGridMultipleTopology";
  info.category = "Topology";
  info.description = "Sparse grid over several surfaces, each with its own stiffness and mass coefficients";
  info.create = creator<SparseGridMultipleTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
