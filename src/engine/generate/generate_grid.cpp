#include "engine/generate/generate_grid.h"

#include "core/registry.h"

namespace sinew {

namespace {
FlatVec flat(int w) {
  FlatVec v;
  v.width = w;
  return v;
}
}  // namespace

GenerateGrid::GenerateGrid(int dim)
    : output_position(this, "output_position", flat(dim), "points of the grid", "Outputs", "length"), dim_(dim) {
  output_position.add_alias("position");
  add_input(&min);
  add_input(&max);
  add_input(&resolution);
  add_output(&output_position);
  add_output(&tetrahedra);
  add_output(&hexahedra);
  add_output(&quads);
  add_output(&triangles);
}

void GenerateGrid::do_update() {
  const VecNi<3> res = resolution.get();
  if (res[0] < 0 || res[1] < 0 || res[2] < 0) {
    msg_error("resolution has a negative entry: nothing is generated");
    return;
  }
  std::size_t nx = static_cast<std::size_t>(res[0]), ny = static_cast<std::size_t>(res[1]),
              nz = static_cast<std::size_t>(res[2]);
  // SOFA: a zero count along x or y is an error and becomes 1.
  if (nx == 0) {
    msg_error("the number of cells along x cannot be 0: 1 is used");
    nx = 1;
  }
  if (ny == 0) {
    msg_error("the number of cells along y cannot be 0: 1 is used");
    ny = 1;
  }
  const Vec3 lo = min.get(), size = max.get() - lo;
  const double dx = size[0] / static_cast<double>(nx), dy = size[1] / static_cast<double>(ny);
  const double dz = nz == 0 ? 0.0 : size[2] / static_cast<double>(nz);

  FlatVec& out = output_position.edit();
  out.width = dim_;
  out.data.clear();
  out.data.reserve((nx + 1) * (ny + 1) * (nz + 1) * static_cast<std::size_t>(dim_));
  for (std::size_t k = 0; k <= nz; ++k)
    for (std::size_t j = 0; j <= ny; ++j)
      for (std::size_t i = 0; i <= nx; ++i) {
        const double p[3] = {static_cast<double>(i) * dx, static_cast<double>(j) * dy, static_cast<double>(k) * dz};
        for (int c = 0; c < dim_; ++c) out.data.push_back(p[c] + lo[c]);
      }

  const auto id = [&](std::size_t i, std::size_t j, std::size_t k) {
    return static_cast<unsigned>(i + j * (nx + 1) + k * (nx + 1) * (ny + 1));
  };
  // Like SOFA, only the lists of the grid's kind are rewritten.
  if (nz == 0) {
    std::vector<Quad>& q = quads.edit();
    std::vector<Triangle>& t = triangles.edit();
    q.clear();
    t.clear();
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j) {
        const Quad c{id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)};
        q.push_back(c);
        t.push_back({c[0], c[1], c[3]});
        t.push_back({c[3], c[1], c[2]});
      }
  } else {
    std::vector<Hexa>& hx = hexahedra.edit();
    std::vector<Tetra>& te = tetrahedra.edit();
    hx.clear();
    te.clear();
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t k = 0; k < nz; ++k) {
          const Hexa h{id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),     id(i, j + 1, k),
                       id(i, j, k + 1),     id(i + 1, j, k + 1),     id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
          hx.push_back(h);
          te.push_back({h[0], h[5], h[1], h[6]});
          te.push_back({h[0], h[1], h[3], h[6]});
          te.push_back({h[1], h[3], h[6], h[2]});
          te.push_back({h[6], h[3], h[0], h[7]});
          te.push_back({h[6], h[7], h[0], h[5]});
          te.push_back({h[7], h[5], h[4], h[0]});
        }
  }
}

void register_generate_grid(Registry& r) {
  ComponentInfo info;
  info.name = "GenerateGrid";
  info.category = "Engine/Generate";
  info.description = "regular grid of hexahedra and tetrahedra (or quads and triangles when flat)";
  info.templates = {"Vec3d", "Vec2d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    return std::make_unique<GenerateGrid>(t == "Vec2d" ? 2 : 3);
  };
  r.add(std::move(info));
}

}  // namespace sinew
