#include "engine/merge_meshes.h"

#include "core/registry.h"
#include "core/state_creator.h"
#include "engine/empty_coords.h"

namespace sinew {

namespace {
// Appends the elements of `in` (mesh `m`) shifted by `offset`; reports indices
// beyond the mesh's own points (kept, as SOFA does).
template <std::size_t N>
void append_shifted(Engine& e, const char* what, std::size_t m, const std::vector<std::array<unsigned, N>>& in,
                    unsigned offset, std::size_t mesh_points, std::vector<std::array<unsigned, N>>& out) {
  bool reported = false;
  for (const auto& el : in) {
    std::array<unsigned, N> s;
    for (std::size_t k = 0; k < N; ++k) {
      if (el[k] >= mesh_points && !reported) {
        e.msg_warning(std::string(what) + std::to_string(m + 1) + " has index " + std::to_string(el[k]) +
                      ", beyond the " + std::to_string(mesh_points) + " points of position" + std::to_string(m + 1));
        reported = true;
      }
      s[k] = el[k] + offset;
    }
    out.push_back(s);
  }
}
}  // namespace

MergeMeshes::MergeMeshes(StateType type)
    : positions("position", "input positions of mesh ", empty_coords(type)),
      position(this, "position", empty_coords(type), "points of the merged mesh", "Outputs") {
  add_input(&nb_meshes);
  grow(nb_meshes.value());
  add_output(&npoints);
  add_output(&position);
  add_output(&out_edges);
  add_output(&out_triangles);
  add_output(&out_quads);
  add_output(&out_tetrahedra);
  add_output(&out_hexahedra);
}

void MergeMeshes::grow(unsigned n) {
  auto in = [this](BaseField* f) { add_input(f); };
  positions.grow(*this, n, in);
  edges.grow(*this, n, in);
  triangles.grow(*this, n, in);
  quads.grow(*this, n, in);
  tetrahedra.grow(*this, n, in);
  hexahedra.grow(*this, n, in);
}

void MergeMeshes::parse(AttributeMap& attrs, Diagnostics& diag) {
  grow(read_field_count(*this, nb_meshes, attrs, diag,
                        {"position", "edges", "triangles", "quads", "tetrahedra", "hexahedra"}));
  Engine::parse(attrs, diag);
}

void MergeMeshes::init() {
  set_dirty();
  update();
}

void MergeMeshes::do_update() {
  std::size_t n = nb_meshes.get();
  if (n > positions.size()) {
    msg_error("nbMeshes = " + std::to_string(n) + " but only " + std::to_string(positions.size()) +
              " meshes exist (their number is fixed when the scene is read): merging those");
    n = positions.size();
  }
  FlatVec& x = position.edit();
  x.width = positions[0].value().width;
  x.data.clear();
  auto& e = out_edges.edit();
  auto& t = out_triangles.edit();
  auto& q = out_quads.edit();
  auto& te = out_tetrahedra.edit();
  auto& h = out_hexahedra.edit();
  e.clear();
  t.clear();
  q.clear();
  te.clear();
  h.clear();
  unsigned offset = 0;
  for (std::size_t m = 0; m < n; ++m) {
    const FlatVec& xm = positions[m].get();
    const std::size_t np = xm.size();
    if (xm.width != x.width) {
      msg_error("position" + std::to_string(m + 1) + " has " + std::to_string(xm.width) +
                " values per point, position1 has " + std::to_string(x.width) + ": mesh " + std::to_string(m + 1) +
                " skipped");
      continue;
    }
    x.data.insert(x.data.end(), xm.data.begin(), xm.data.begin() + static_cast<std::ptrdiff_t>(np * x.width));
    append_shifted(*this, "edges", m, edges[m].get(), offset, np, e);
    append_shifted(*this, "triangles", m, triangles[m].get(), offset, np, t);
    append_shifted(*this, "quads", m, quads[m].get(), offset, np, q);
    append_shifted(*this, "tetrahedra", m, tetrahedra[m].get(), offset, np, te);
    append_shifted(*this, "hexahedra", m, hexahedra[m].get(), offset, np, h);
    offset += static_cast<unsigned>(np);
  }
  npoints.set(static_cast<unsigned>(x.size()));
}

void register_merge_meshes(Registry& r) {
  ComponentInfo info;
  info.name = "MergeMeshes";
  info.category = "Engine/Generate";
  info.description = "appends nbMeshes meshes, shifting each one's element indices by the points before it";
  info.templates = {"Vec3d", "Vec1d", "Vec2d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<MergeMeshes>();
  r.add(std::move(info));
}

}  // namespace sinew
