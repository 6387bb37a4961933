#include "engine/select/values_from_positions.h"

#include <cmath>
#include <limits>

#include "core/node.h"
#include "core/registry.h"
#include "core/state_creator.h"
#include "engine/empty_coords.h"
#include "io/mesh_loader.h"

namespace sinew {

ValuesFromPositions::ValuesFromPositions(StateType type)
    : position(this, "position", empty_coords(type),
               "rest positions (default: the state's rest_position, else a mesh loader's position)", "Inputs",
               "length") {
  position.add_alias("rest_position");
  for (BaseField* f : std::initializer_list<BaseField*>{&input_values, &direction, &position, &edges, &triangles,
                                                        &tetrahedra, &field_type})
    add_input(f);
  for (BaseField* f : std::initializer_list<BaseField*>{&values, &edge_values, &triangle_values, &tetrahedron_values,
                                                        &point_vectors, &edge_vectors, &triangle_vectors,
                                                        &tetrahedron_vectors})
    add_output(f);
}

void ValuesFromPositions::init() {
  Node& n = *node();
  if (!position.is_set() && !position.parent()) {
    if (auto* ms = n.find_up<MechanicalState>()) {
      if (BaseField* f = ms->find_field("rest_position")) position.set_parent(f);
    } else if (auto* loader = n.find_up<MeshLoader>()) {
      position.set_parent(&loader->position);
    }
  }
  if (auto* topo = n.find_up<MeshTopologyBase>()) {
    auto link = [&](BaseField& mine, const char* name) {
      if (!mine.is_set() && !mine.parent())
        if (BaseField* theirs = topo->find_field(name)) mine.set_parent(theirs);
    };
    link(edges, "edges");
    link(triangles, "triangles");
    link(tetrahedra, "tetrahedra");
  }
  if (field_type.get() != "Scalar" && field_type.get() != "Vector") {
    msg_error("fieldType must be Scalar or Vector (got '" + field_type.get() + "'): Scalar is used");
    field_type.set("Scalar");
  }
  set_dirty();
}

namespace {
// The x range of the scene's box: the root's bbox when set, else every state's positions.
void scene_x_range(Node& root, double& lo, double& hi) {
  const std::vector<double>& b = root.bbox.get();
  if (b.size() == 6) {
    lo = b[0];
    hi = b[3];
    return;
  }
  lo = std::numeric_limits<double>::max();
  hi = std::numeric_limits<double>::lowest();
  for_each_node(root, [&](Node& n) {
    for (auto& o : n.objects())
      if (auto* ms = dynamic_cast<MechanicalState*>(o.get())) {
        const std::vector<double>& x = ms->read(kPosition);
        const std::size_t w = static_cast<std::size_t>(ms->info().coord_width);
        for (std::size_t i = 0; i + w <= x.size(); i += w) {
          lo = std::min(lo, x[i]);
          hi = std::max(hi, x[i]);
        }
      }
  });
}
}  // namespace

void ValuesFromPositions::do_update() {
  const FlatVec& x0 = position.get();
  const std::size_t w = static_cast<std::size_t>(x0.width), np = x0.size();
  auto pos = [&](unsigned i) { return Vec3(x0.data[i * w], x0.data[i * w + 1], x0.data[i * w + 2]); };
  const Vec3 dir = direction.get();
  bool bad = false;
  auto centre = [&](const auto& e) {
    Vec3 c = Vec3::Zero();
    for (unsigned v : e) {
      if (v >= np) {
        bad = true;
        return c;
      }
    }
    // SOFA's sums run from the last vertex down: (p1+p0)*0.5, (p2+p1+p0)/3, (p3+p2+p1+p0)/4.
    for (std::size_t k = e.size(); k-- > 0;) c = k + 1 == e.size() ? pos(e[k]) : Vec3(c + pos(e[k]));
    return e.size() == 2 ? Vec3(c * 0.5) : Vec3(c / static_cast<double>(e.size()));
  };
  if (field_type.get() == "Vector") {
    point_vectors.set(std::vector<Vec3>(np, dir));
    edge_vectors.set(std::vector<Vec3>(edges.get().size(), dir));
    triangle_vectors.set(std::vector<Vec3>(triangles.get().size(), dir));
    tetrahedron_vectors.set(std::vector<Vec3>(tetrahedra.get().size(), dir));
    return;
  }
  const std::vector<double>& in = input_values.get();
  double bmin = 0, bmax = 0;
  scene_x_range(*node()->root(), bmin, bmax);
  auto value = [&](const Vec3& p) -> double {
    const int nbv = static_cast<int>(in.size());
    if (nbv == 0) return 0;
    if (nbv == 1) return in[0];
    double coef = p[0] * dir[0] + p[1] * dir[1] + p[2] * dir[2];
    coef = (coef - bmin) / (bmax - bmin);
    coef *= (nbv - 1);
    const double fl = std::floor(coef);
    if (fl < 0) return in[0];
    if (fl >= nbv - 1) return in[static_cast<std::size_t>(nbv - 1)];
    const int v = static_cast<int>(fl);
    coef -= v;
    return in[static_cast<std::size_t>(v)] * (1 - coef) + in[static_cast<std::size_t>(v + 1)] * coef;
  };
  std::vector<double> pv, ev, tv, qv;
  for (unsigned i = 0; i < np; ++i) pv.push_back(value(pos(i)));
  for (const Edge& e : edges.get()) ev.push_back(value(centre(e)));
  for (const Triangle& t : triangles.get()) tv.push_back(value(centre(t)));
  for (const Tetra& t : tetrahedra.get()) qv.push_back(value(centre(t)));
  if (bad) {
    msg_error("an element refers to a point beyond the " + std::to_string(np) + " positions: element values not set");
    ev.clear();
    tv.clear();
    qv.clear();
  }
  values.set(std::move(pv));
  edge_values.set(std::move(ev));
  triangle_values.set(std::move(tv));
  tetrahedron_values.set(std::move(qv));
}

void register_values_from_positions(Registry& r) {
  ComponentInfo info;
  info.name = "ValuesFromPositions";
  info.category = "Engine/Select";
  info.description = "values (or vectors) of points and elements interpolated along a direction";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<ValuesFromPositions>();
  r.add(std::move(info));
}

}  // namespace sinew
