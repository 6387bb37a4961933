#include "topology/grid/cube_topology.h"

#include "core/alloc_check.h"
#include "core/pseudo_attribute.h"
#include "core/registry.h"

namespace sinew {

void CubeTopology::parse(AttributeMap& attrs, Diagnostics& diag) {
  // xmin..zmax: all six required; read as single-precision floats times `scale` (float), as SOFA does.
  const char* keys[6] = {"xmin", "ymin", "zmin", "xmax", "ymax", "zmax"};
  bool all = true;
  for (const char* k : keys) all = all && attrs.peek(k) != nullptr;
  float scale = 1.0f;
  if (const std::string* s = attrs.take("scale")) {
    double d = 1;
    read_pseudo_number(*this, diag, "scale", *s, d);
    scale = static_cast<float>(d);
  }
  if (all) {
    float v[6];
    for (int i = 0; i < 6; ++i) {
      double d = 0;
      read_pseudo_number(*this, diag, keys[i], *attrs.take(keys[i]), d);
      v[i] = static_cast<float>(d);
    }
    min.set(Vec3(static_cast<double>(v[0] * scale), static_cast<double>(v[1] * scale), static_cast<double>(v[2] * scale)));
    max.set(Vec3(static_cast<double>(v[3] * scale), static_cast<double>(v[4] * scale), static_cast<double>(v[5] * scale)));
  }
  MeshTopology::parse(attrs, diag);
}

void CubeTopology::init() {
  if (nx.value() < 1 || ny.value() < 1 || nz.value() < 1) {
    msg_error("nx, ny and nz must be at least 1 (got " + std::to_string(nx.value()) + " " +
              std::to_string(ny.value()) + " " + std::to_string(nz.value()) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  // Surface points only, but the check is on the box (an upper bound).
  if (!check_allocation(*this, "nx ny nz",
                        std::to_string(nx.value()) + " " + std::to_string(ny.value()) + " " + std::to_string(nz.value()),
                        static_cast<double>(nx.value()) * ny.value() * nz.value(), 64)) {
    set_state(ComponentState::invalid);
    return;
  }
  regenerate();
  MeshTopology::init();
}

int CubeTopology::point_index(int x, int y, int z, Plane p) const {
  const int nx_ = nx.value(), ny_ = ny.value(), nz_ = nz.value();
  if (split_normals.value()) {
    if (p == Plane::unknown) {
      if (x == 0) p = Plane::x0;
      else if (x == nx_ - 1) p = Plane::x1;
      else if (y == 0) p = Plane::y0;
      else if (y == ny_ - 1) p = Plane::y1;
      else if (z == 0) p = Plane::z0;
      else if (z == nz_ - 1) p = Plane::z1;
    }
    switch (p) {
      case Plane::x0: return y + ny_ * z;
      case Plane::x1: return ny_ * nz_ + nx_ * nz_ + nx_ * ny_ + y + ny_ * z;
      case Plane::y0: return ny_ * nz_ + x + nx_ * z;
      case Plane::y1: return 2 * ny_ * nz_ + nx_ * nz_ + nx_ * ny_ + x + nx_ * z;
      case Plane::z0: return ny_ * nz_ + nx_ * nz_ + x + nx_ * y;
      case Plane::z1: return 2 * ny_ * nz_ + 2 * nx_ * nz_ + nx_ * ny_ + x + nx_ * y;
      case Plane::unknown: return 0;
    }
    return 0;
  }
  if (!internal_points.value() && nx_ > 1 && ny_ > 1 && nz_ > 1) {
    if (z == 0) return x + nx_ * y;
    if (z == nz_ - 1) return x + nx_ * (y + ny_);
    const int base = nx_ * ny_ * 2 + (2 * nx_ + 2 * ny_ - 4) * (z - 1);
    if (y == 0) return base + x;
    if (y == ny_ - 1) return base + x + nx_;
    if (x == 0) return base + 2 * nx_ + (y - 1);
    return base + 2 * nx_ + (ny_ - 2) + (y - 1);
  }
  return x + nx_ * (y + ny_ * z);
}

Vec3 CubeTopology::lattice_point(int i) const {
  const int nx_ = nx.value(), ny_ = ny.value(), nz_ = nz.value();
  int x = 0, y = 0, z = 0;
  if (split_normals.value()) {
    if (i >= ny_ * nz_ + nx_ * nz_ + nx_ * ny_) {
      i -= ny_ * nz_ + nx_ * nz_ + nx_ * ny_;
      x = nx_ - 1, y = ny_ - 1, z = nz_ - 1;
    }
    if (i < ny_ * nz_) {
      y = i % ny_, z = i / ny_;
    } else {
      i -= ny_ * nz_;
      if (i < nx_ * nz_) {
        x = i % nx_, z = i / nx_;
      } else {
        i -= nx_ * nz_;
        x = i % nx_, y = i / nx_;
      }
    }
  } else if (!internal_points.value() && nx_ > 1 && ny_ > 1 && nz_ > 1) {
    const int nxny = nx_ * ny_;
    if (i < nxny) {
      x = i % nx_, y = i / nx_, z = 0;
    } else if (i < 2 * nxny) {
      i -= nxny;
      x = i % nx_, y = i / nx_, z = nz_ - 1;
    } else {
      i -= 2 * nxny;
      const int ring = 2 * nx_ + 2 * (ny_ - 2);
      z = i / ring;
      i -= z * ring;
      z += 1;
      if (i < nx_) x = i, y = 0;
      else if (i < 2 * nx_) x = i - nx_, y = ny_ - 1;
      else if (i < 2 * nx_ + (ny_ - 2)) x = 0, y = 1 + i - 2 * nx_;
      else x = nx_ - 1, y = 1 + i - 2 * nx_ - (ny_ - 2);
    }
  } else {
    x = i % nx_;
    i /= nx_;
    y = i % ny_;
    z = i / ny_;
  }
  return p0_ + dx_ * x + dy_ * y + dz_ * z;
}

void CubeTopology::generate() {
  const int nx_ = nx.value(), ny_ = ny.value(), nz_ = nz.value();
  if (nx_ < 1 || ny_ < 1 || nz_ < 1) return;  // reported by init
  if (!allocation_fits(static_cast<double>(nx_) * ny_ * nz_, 64)) return;  // reported by init
  const Vec3 lo = min.get(), hi = max.get();
  p0_ = lo;
  dx_ = nx_ > 1 ? Vec3((hi[0] - lo[0]) / (nx_ - 1), 0, 0) : Vec3::Zero();
  dy_ = ny_ > 1 ? Vec3(0, (hi[1] - lo[1]) / (ny_ - 1), 0) : Vec3::Zero();
  dz_ = nz_ > 1 ? Vec3(0, 0, (hi[2] - lo[2]) / (nz_ - 1)) : Vec3::Zero();
  if (split_normals.value())
    count_ = nx_ * ny_ * (nz_ > 1 ? 2 : 1) + ny_ * nz_ * (nx_ > 1 ? 2 : 1) + nz_ * nx_ * (ny_ > 1 ? 2 : 1);
  else if (!internal_points.value() && nx_ > 1 && ny_ > 1 && nz_ > 1)
    count_ = nx_ * ny_ * 2 + (nz_ - 2) * (2 * nx_ + 2 * ny_ - 4);
  else
    count_ = nx_ * ny_ * nz_;

  auto& pts = position.edit();
  pts.resize(static_cast<std::size_t>(count_));
  for (int i = 0; i < count_; ++i) pts[static_cast<std::size_t>(i)] = lattice_point(i);

  auto P = [&](int x, int y, int z, Plane p = Plane::unknown) { return static_cast<unsigned>(point_index(x, y, z, p)); };
  auto& edges = edges_f.edit();
  edges.clear();
  for (int z = 0; z < nz_; z++)
    for (int y = 0; y < ny_; y++)
      for (int x = 0; x < nx_; x++) {
        if (x < nx_ - 1 && (y == 0 || y == ny_ - 1 || z == 0 || z == nz_ - 1)) edges.push_back({P(x, y, z), P(x + 1, y, z)});
        if (y < ny_ - 1 && (x == 0 || x == nx_ - 1 || z == 0 || z == nz_ - 1)) edges.push_back({P(x, y, z), P(x, y + 1, z)});
        if (z < nz_ - 1 && (x == 0 || x == nx_ - 1 || y == 0 || y == ny_ - 1)) edges.push_back({P(x, y, z), P(x, y, z + 1)});
      }

  auto& quads = quads_f.edit();
  quads.clear();
  using Pl = Plane;
  for (int y = 0, z = 0; y < ny_ - 1; y++)
    for (int x = 0; x < nx_ - 1; x++)
      quads.push_back({P(x, y, z, Pl::z0), P(x, y + 1, z, Pl::z0), P(x + 1, y + 1, z, Pl::z0), P(x + 1, y, z, Pl::z0)});
  if (nz_ > 1)
    for (int z = nz_ - 1, y = 0; y < ny_ - 1; y++)
      for (int x = 0; x < nx_ - 1; x++)
        quads.push_back({P(x, y, z, Pl::z1), P(x + 1, y, z, Pl::z1), P(x + 1, y + 1, z, Pl::z1), P(x, y + 1, z, Pl::z1)});
  for (int y = 0, z = 0; z < nz_ - 1; z++)
    for (int x = 0; x < nx_ - 1; x++)
      quads.push_back({P(x, y, z, Pl::y0), P(x + 1, y, z, Pl::y0), P(x + 1, y, z + 1, Pl::y0), P(x, y, z + 1, Pl::y0)});
  if (ny_ > 1)
    for (int y = ny_ - 1, z = 0; z < nz_ - 1; z++)
      for (int x = 0; x < nx_ - 1; x++)
        quads.push_back({P(x, y, z, Pl::y1), P(x, y, z + 1, Pl::y1), P(x + 1, y, z + 1, Pl::y1), P(x + 1, y, z, Pl::y1)});
  for (int x = 0, z = 0; z < nz_ - 1; z++)
    for (int y = 0; y < ny_ - 1; y++)
      quads.push_back({P(x, y, z, Pl::x0), P(x, y, z + 1, Pl::x0), P(x, y + 1, z + 1, Pl::x0), P(x, y + 1, z, Pl::x0)});
  if (nx_ > 1)
    for (int x = nx_ - 1, z = 0; z < nz_ - 1; z++)
      for (int y = 0; y < ny_ - 1; y++)
        quads.push_back({P(x, y, z, Pl::x1), P(x, y + 1, z, Pl::x1), P(x, y + 1, z + 1, Pl::x1), P(x, y, z + 1, Pl::x1)});
  set_nb_points(static_cast<std::size_t>(count_));
}

void register_cube_topology(Registry& r) {
  ComponentInfo info;
  info.name = "CubeTopology";
  info.category = "Topology";
  info.description = "Surface topology of a cube in 3D (points, edges and quads).";
  info.create = creator<CubeTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
