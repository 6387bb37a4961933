#include "topology/grid/regular_grid_topology.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/alloc_check.h"
#include "core/pseudo_attribute.h"
#include "core/registry.h"

namespace sinew {

namespace {
// Rough bytes per grid point of the lists a grid builds (points, cells, faces, edges).
constexpr double kBytesPerPoint = 256;
}  // namespace

RegularGridTopology::RegularGridTopology() = default;

void RegularGridTopology::parse(AttributeMap& attrs, Diagnostics& diag) {
  // nx ny nz: integers, used only when all three are given.
  const std::string* sx = attrs.peek("nx");
  const std::string* sy = attrs.peek("ny");
  const std::string* sz = attrs.peek("nz");
  if (sx && sy && sz) {
    VecNi<3> v;
    double a = 0, b = 0, c = 0;
    read_pseudo_number(*this, diag, "nx", *attrs.take("nx"), a);
    read_pseudo_number(*this, diag, "ny", *attrs.take("ny"), b);
    read_pseudo_number(*this, diag, "nz", *attrs.take("nz"), c);
    // Integers as SOFA's atoi reads them; out-of-range counts stay out of range (init refuses them).
    auto to_int = [](double d) { return static_cast<int>(std::clamp(d, -2147483648.0, 2147483647.0)); };
    v << to_int(a), to_int(b), to_int(c);
    n.set(v);
  }
  // xmin..zmax: all six required; read as single-precision floats and scaled (SOFA quirk).
  const char* keys[6] = {"xmin", "ymin", "zmin", "xmax", "ymax", "zmax"};
  bool all = true;
  for (const char* k : keys) all = all && attrs.peek(k) != nullptr;
  if (all) {
    float scale = 1.0f;
    if (const std::string* s = attrs.take("scale")) {
      double d = 1;
      read_pseudo_number(*this, diag, "scale", *s, d);
      scale = static_cast<float>(d);
    }
    float v[6];
    for (int i = 0; i < 6; ++i) {
      double d = 0;
      read_pseudo_number(*this, diag, keys[i], *attrs.take(keys[i]), d);
      v[i] = static_cast<float>(d) * scale;
    }
    min.set(Vec3(v[0], v[1], v[2]));
    max.set(Vec3(v[3], v[4], v[5]));
  }
  MeshContainer::parse(attrs, diag);
}

void RegularGridTopology::init() {
  VecNi<3> dims = n.get();
  if (dims.minCoeff() < 1) {
    msg_warning("n must be at least 1 along each axis; reset to 2 2 2");
    n.set(VecNi<3>(2, 2, 2));
  }
  if (cell_width.value() > 0) {
    const Vec3 size = max.get() - min.get();
    double count = 1;
    double per_axis[3];
    for (int a = 0; a < 3; ++a) count *= per_axis[a] = std::ceil(std::abs(size[a]) / cell_width.value()) + 1;
    if (!check_allocation(*this, "cellWidth", parse::to_text(cell_width.value()) + " (" + parse::format_double(per_axis[0]) +
                                                  " × " + parse::format_double(per_axis[1]) + " × " +
                                                  parse::format_double(per_axis[2]) + " points)",
                          count, kBytesPerPoint)) {
      set_state(ComponentState::invalid);
      return;
    }
    VecNi<3> d;
    for (int a = 0; a < 3; ++a) d[a] = static_cast<int>(per_axis[a]);
    n.set(d);
  }
  regenerate();
  MeshContainer::init();
}

void RegularGridTopology::generate() {
  if (state() == ComponentState::invalid) return;  // reported
  {
    const VecNi<3> want = n.get();
    double count = 1;
    for (int a = 0; a < 3; ++a) count *= want[a] < 1 ? 2.0 : static_cast<double>(want[a]);
    // Point indices are ints (SOFA's too).
    bool ok = check_allocation(*this, "n", parse::to_text(want), count, kBytesPerPoint);
    if (ok && count > 2147483647.0) {
      msg_error("'n' = " + parse::to_text(want) + " has more than 2³¹ points");
      ok = false;
    }
    if (!ok) {
      set_state(ComponentState::invalid);
      return;
    }
  }
  dims_ = n.get();
  for (int a = 0; a < 3; ++a)
    if (dims_[a] < 1) dims_[a] = 2;
  const Vec3 lo = min.get(), hi = max.get();
  Vec3 d[3];
  Vec3 o;
  for (int a = 0; a < 3; ++a) {
    d[a] = Vec3::Zero();
    if (dims_[a] > 1) {
      d[a][a] = (hi[a] - lo[a]) / (dims_[a] - 1);
      o[a] = lo[a];
    } else {
      d[a][a] = hi[a] - lo[a];
      o[a] = a < 2 ? (hi[a] + lo[a]) / 2 : lo[a];  // z keeps min (SOFA quirk)
    }
  }
  if (p0.is_set()) o = p0.get();
  dx_ = d[0], dy_ = d[1], dz_ = d[2], origin_ = o;
  const int nx = dims_[0], ny = dims_[1], nz = dims_[2];

  if (compute_point_list.value()) {
    auto& pts = position.edit();
    pts.clear();
    pts.reserve(static_cast<std::size_t>(nx) * ny * nz);
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) pts.push_back(grid_point(i, j, k));
  }
  auto p = [&](int i, int j, int k) { return static_cast<unsigned>(point_index(i, j, k)); };

  if (compute_hexa_list.value()) {
    auto& hexas = hexahedra_f.edit();
    hexas.clear();
    for (int z = 0; z + 1 < nz; ++z)
      for (int y = 0; y + 1 < ny; ++y)
        for (int x = 0; x + 1 < nx; ++x)
          hexas.push_back({p(x, y, z), p(x + 1, y, z), p(x + 1, y + 1, z), p(x, y + 1, z), p(x, y, z + 1),
                           p(x + 1, y, z + 1), p(x + 1, y + 1, z + 1), p(x, y + 1, z + 1)});
  }
  std::vector<Quad> quads;
  if (compute_quad_list.value() || compute_triangle_list.value()) {
    for (int z = 0; z < nz; ++z)
      for (int y = 0; y + 1 < ny; ++y)
        for (int x = 0; x + 1 < nx; ++x) quads.push_back({p(x, y, z), p(x + 1, y, z), p(x + 1, y + 1, z), p(x, y + 1, z)});
    for (int z = 0; z + 1 < nz; ++z)
      for (int y = 0; y < ny; ++y)
        for (int x = 0; x + 1 < nx; ++x) quads.push_back({p(x, y, z), p(x + 1, y, z), p(x + 1, y, z + 1), p(x, y, z + 1)});
    for (int z = 0; z + 1 < nz; ++z)
      for (int y = 0; y + 1 < ny; ++y)
        for (int x = 0; x < nx; ++x) quads.push_back({p(x, y, z), p(x, y + 1, z), p(x, y + 1, z + 1), p(x, y, z + 1)});
  }
  if (compute_quad_list.value()) quads_f.edit() = quads;
  std::vector<Triangle> tris;
  if (compute_triangle_list.value()) {
    for (const Quad& q : quads) {
      tris.push_back({q[0], q[1], q[2]});
      tris.push_back({q[0], q[2], q[3]});
    }
    triangles_f.edit() = tris;
  }
  if (compute_edge_list.value()) {
    auto& edges = edges_f.edit();
    edges.clear();
    if (!tris.empty()) {
      // Edges of the triangles, oriented as first met, each once (so one diagonal per quad).
      std::map<std::pair<unsigned, unsigned>, bool> seen;
      for (const Triangle& t : tris)
        for (int j = 0; j < 3; ++j) {
          const unsigned a = t[(j + 1) % 3], b = t[(j + 2) % 3];
          const auto key = std::minmax(a, b);
          if (seen.emplace(std::make_pair(key.first, key.second), true).second) edges.push_back({a, b});
        }
    } else {
      for (int z = 0; z < nz; ++z)
        for (int y = 0; y < ny; ++y)
          for (int x = 0; x + 1 < nx; ++x) edges.push_back({p(x, y, z), p(x + 1, y, z)});
      for (int z = 0; z < nz; ++z)
        for (int y = 0; y + 1 < ny; ++y)
          for (int x = 0; x < nx; ++x) edges.push_back({p(x, y, z), p(x, y + 1, z)});
      for (int z = 0; z + 1 < nz; ++z)
        for (int y = 0; y < ny; ++y)
          for (int x = 0; x < nx; ++x) edges.push_back({p(x, y, z), p(x, y, z + 1)});
    }
  }
}

void register_regular_grid_topology(Registry& r) {
  ComponentInfo info;
  info.name = "RegularGridTopology";
  info.category = "Topology";
  info.description = "regular axis-aligned grid of points with hexahedra, quads, triangles and edges";
  info.create = creator<RegularGridTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
