#include "engine/generate/generate_cylinder.h"

#include <cmath>
#include <numbers>

#include "core/registry.h"

namespace sinew {

GenerateCylinder::GenerateCylinder() {
  tetra_positions.add_alias("position");
  tetra_positions.add_alias("output_position");
  for (BaseField* f : std::initializer_list<BaseField*>{&radius, &height, &origin, &res_circumferential, &res_radial,
                                                        &res_height, &open_surface, &bezier_triangle_degree,
                                                        &bezier_tetra_degree})
    add_input(f);
  for (BaseField* f : std::initializer_list<BaseField*>{&triangles, &triangle_positions, &bezier_triangle_weights,
                                                        &is_bezier_triangle_rational, &tetrahedra, &tetra_positions,
                                                        &bezier_tetra_weights, &is_bezier_tetra_rational})
    add_output(f);
}

void GenerateCylinder::init() {
  if (res_circumferential.get() < 1 || res_radial.get() < 1 || res_height.get() < 2) {
    msg_error("resCircumferential and resRadial must be at least 1 and resHeight at least 2 (got " +
              std::to_string(res_circumferential.get()) + ", " + std::to_string(res_radial.get()) + ", " +
              std::to_string(res_height.get()) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  if (!open_surface.get() && res_radial.get() < 2)
    msg_error("a closed surface (openSurface=false) needs resRadial >= 2 (SOFA's cap loops run out of range): the "
              "surface is left without caps");
  if (bezier_tetra_degree.get() > 1 || bezier_triangle_degree.get() > 1)
    msg_error("Bézier degrees above 1 (BezierTetrahedronDegree, BezierTriangleDegree) are not supported: the "
              "control points and weights are not computed");
  set_dirty();
}

void GenerateCylinder::do_update() {
  if (state() == ComponentState::invalid) return;
  const double r_max = radius.get(), h = height.get();
  const Vec3 o = origin.get();
  const std::size_t nt = res_circumferential.get(), nr = res_radial.get(), nz = res_height.get();
  if (nt < 1 || nr < 1 || nz < 2) return;
  const double two_pi = 2 * std::numbers::pi;

  // Volume points: per level, the axis point then the rings from the inside out.
  std::vector<Vec3>& x = tetra_positions.edit();
  x.clear();
  x.reserve((nt * nr + 1) * nz);
  for (std::size_t i = 0; i < nz; ++i) {
    const double z = static_cast<double>(i) * h / static_cast<double>(nz - 1);
    x.push_back(Vec3(0, 0, z) + o);
    for (std::size_t j = 1; j <= nr; ++j) {
      const double r = static_cast<double>(j) * r_max / static_cast<double>(nr);
      for (std::size_t k = 0; k < nt; ++k) {
        const double th = static_cast<double>(k) * two_pi / static_cast<double>(nt);
        x.push_back(Vec3(r * std::cos(th), r * std::sin(th), z) + o);
      }
    }
  }

  // Tetrahedra: per level pair, the prisms around the axis, then the ring hexahedra.
  std::vector<Tetra>& tets = tetrahedra.edit();
  tets.clear();
  tets.reserve(3 * nt * (nz - 1) + 6 * (nr - 1) * nt * (nz - 1));
  const auto u = [](std::size_t v) { return static_cast<unsigned>(v); };
  const std::size_t level = nt * nr + 1;
  for (std::size_t i = 1; i < nz; ++i) {
    std::size_t c = i * level;
    std::size_t prev = nt;
    for (std::size_t k = 1; k <= nt; ++k) {
      const std::size_t p0 = c, p1 = c + prev, p2 = c + k, p3 = p0 - level, p4 = p1 - level, p5 = p2 - level;
      tets.push_back({u(p1), u(p0), u(p2), u(p3)});
      tets.push_back({u(p1), u(p2), u(p4), u(p3)});
      tets.push_back({u(p3), u(p4), u(p5), u(p2)});
      prev = k;
    }
    for (std::size_t j = 1; j < nr; ++j) {
      prev = nt;
      for (std::size_t k = 1; k <= nt; ++k) {
        const std::size_t h0 = c + k, h1 = c + prev, h2 = c + k + nt, h3 = c + prev + nt;
        const std::size_t h4 = h0 - level, h5 = h1 - level, h6 = h2 - level, h7 = h3 - level;
        tets.push_back({u(h0), u(h5), u(h4), u(h7)});
        tets.push_back({u(h0), u(h1), u(h5), u(h3)});
        tets.push_back({u(h5), u(h0), u(h3), u(h7)});
        tets.push_back({u(h0), u(h3), u(h7), u(h2)});
        tets.push_back({u(h7), u(h0), u(h2), u(h4)});
        tets.push_back({u(h6), u(h7), u(h2), u(h4)});
        prev = k;
      }
      c += nt;
    }
  }

  // Surface points: the wall's rings, then (closed) each cap's centre and inner rings.
  const bool open = open_surface.get();
  std::vector<Vec3>& y = triangle_positions.edit();
  y.clear();
  for (std::size_t i = 0; i < nz; ++i) {
    const double z = static_cast<double>(i) * h / static_cast<double>(nz - 1);
    for (std::size_t k = 0; k < nt; ++k) {
      const double th = static_cast<double>(k) * two_pi / static_cast<double>(nt);
      y.push_back(Vec3(r_max * std::cos(th), r_max * std::sin(th), z) + o);
    }
  }
  if (!open) {
    for (std::size_t i = 0; i < 2; ++i) {
      const double z = static_cast<double>(i) * h;
      y.push_back(Vec3(0, 0, z) + o);
      for (std::size_t j = 1; j < nr; ++j) {
        const double r = static_cast<double>(j) * r_max / static_cast<double>(nr);
        for (std::size_t k = 0; k < nt; ++k) {
          const double th = static_cast<double>(k) * two_pi / static_cast<double>(nt);
          y.push_back(Vec3(r * std::cos(th), r * std::sin(th), z) + o);
        }
      }
    }
  }

  std::vector<Triangle>& tris = triangles.edit();
  tris.clear();
  for (std::size_t i = 1; i < nz; ++i)
    for (std::size_t k = 0; k < nt; ++k) {
      const std::size_t kn = (k + 1) % nt;
      tris.push_back({u(i * nt + k), u((i - 1) * nt + k), u((i - 1) * nt + kn)});
      tris.push_back({u(i * nt + k), u((i - 1) * nt + kn), u(i * nt + kn)});
    }
  if (!open && nr >= 2) {
    // Caps: the bottom one (i = 0) faces −z, the top one +z.
    for (std::size_t i = 0; i < 2; ++i) {
      const std::size_t c = nt * nz + i * (nt * (nr - 1) + 1);
      const bool top = i == 1;
      for (std::size_t k = 0; k < nt; ++k) {
        const std::size_t kn = (k + 1) % nt;
        if (top) tris.push_back({u(c), u(c + 1 + k), u(c + 1 + kn)});
        else tris.push_back({u(c), u(c + 1 + kn), u(c + 1 + k)});
      }
      for (std::size_t j = 0; j + 2 < nr; ++j)
        for (std::size_t k = 0; k < nt; ++k) {
          const std::size_t kn = (k + 1) % nt;
          const std::size_t a = c + 1 + j * nt + k, b = c + 1 + (j + 1) * nt + k, bn = c + 1 + (j + 1) * nt + kn,
                            an = c + 1 + j * nt + kn;
          if (top) {
            tris.push_back({u(a), u(b), u(bn)});
            tris.push_back({u(a), u(bn), u(an)});
          } else {
            tris.push_back({u(a), u(bn), u(b)});
            tris.push_back({u(a), u(an), u(bn)});
          }
        }
      const std::size_t j = nr - 2, wall = i * (nz - 1) * nt;
      for (std::size_t k = 0; k < nt; ++k) {
        const std::size_t kn = (k + 1) % nt;
        const std::size_t a = c + 1 + j * nt + k, an = c + 1 + j * nt + kn;
        if (top) {
          tris.push_back({u(a), u(wall + k), u(wall + kn)});
          tris.push_back({u(a), u(wall + kn), u(an)});
        } else {
          tris.push_back({u(a), u(wall + kn), u(wall + k)});
          tris.push_back({u(a), u(an), u(wall + kn)});
        }
      }
    }
  }
}

void register_generate_cylinder(Registry& r) {
  ComponentInfo info;
  info.name = "GenerateCylinder";
  info.category = "Engine/Generate";
  info.description = "tetrahedral cylinder along z and its triangulated surface";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<GenerateCylinder>(); };
  r.add(std::move(info));
}

}  // namespace sinew
