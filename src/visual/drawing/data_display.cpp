#include "visual/drawing/data_display.h"

#include <cmath>

#include "core/diagnostics.h"
#include "core/node.h"
#include "core/registry.h"
#include "visual/color_map.h"

namespace sinew {

namespace {
FlatVec empty3() {
  FlatVec v;
  v.width = 3;
  return v;
}

// min and max of a non-empty list, as SOFA scans it.
void scan(const std::vector<double>& v, double& lo, double& hi) {
  lo = hi = v.front();
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (lo > v[i]) lo = v[i];
    if (hi < v[i]) hi = v[i];
  }
}
}  // namespace

DataDisplay::DataDisplay()
    : position(this, "position", empty3(), "vertex positions", "Vector", "length"),
      rest_position(this, "restPosition", empty3(), "vertex rest positions", "Vector", "length") {
  triangle_data.add_alias("cellData");  // SOFA's older name
}

std::vector<double>* DataDisplay::visual_vec(int id) {
  if (id == kRestPosition) return &rest_position.edit().data;
  if (id == kPosition || id >= kFirstDynamicVec) return &position.edit().data;
  return nullptr;
}

void DataDisplay::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  check_color_field(*this, color_nan, diag);
  const double t = transparency.value();
  if (!(t >= 0.0 && t <= 1.0)) diag.error(where, describe() + ": transparency must lie in [0, 1]");
}

void DataDisplay::init() {
  if (!topology && node()) topology.set(node()->get_mesh_topology_link());
  if (!topology) msg_info("no topology: only the points are drawn");
  if (!color_map && node()) color_map.set(node()->find_up<OglColorMap>());
  if (!color_map) {
    msg_warning("an OglColorMap is required by DataDisplay but has not been found: SOFA's default one (HSV, "
                "256 colours) is used. To remove this warning, add an OglColorMap in the scene.");
    default_palette_ = build_palette(256, "HSV");
  }
  nan_color_ = parse_rgba(color_nan.get()).value_or(Rgba{0, 0, 0, 1});
}

void DataDisplay::report(const std::string& text) {
  // SOFA repeats the message at every frame; once per distinct problem is enough here.
  if (text == last_error_) return;
  last_error_ = text;
  msg_error(text);
}

DataDisplay::Range DataDisplay::update_range() {
  Range r;
  const std::size_t n = position.get().size();
  const auto& pt = point_data.get();
  const auto& tri = triangle_data.get();
  const auto& quad = quad_data.get();
  const auto& ptri = point_triangle_data.get();
  const auto& pquad = point_quad_data.get();
  const MeshTopologyBase* topo = topology.get();
  // SOFA's safety checks, in its order: point data first, else cell data, else corner data.
  if (!pt.empty()) {
    if (pt.size() != n) report("pointData has " + std::to_string(pt.size()) + " values for " + std::to_string(n) +
                               " points");
    else r.point_data = true;
  } else if (!tri.empty() || !quad.empty()) {
    if (!topo) report("a topology is needed to draw cell data");
    else if (tri.size() != topo->triangles().size())
      report("triangleData has " + std::to_string(tri.size()) + " values for " +
             std::to_string(topo->triangles().size()) + " triangles");
    else if (quad.size() != topo->quads().size())
      report("quadData has " + std::to_string(quad.size()) + " values for " + std::to_string(topo->quads().size()) +
             " quads");
    else r.cell_data = true;
  } else if (!ptri.empty() || !pquad.empty()) {
    if (!topo) report("a topology is needed to draw cell data");
    else if (ptri.size() != topo->triangles().size() * 3)
      report("pointTriangleData has " + std::to_string(ptri.size()) + " values for " +
             std::to_string(topo->triangles().size()) + " triangles (3 each)");
    else if (pquad.size() != topo->quads().size() * 4)
      report("pointQuadData has " + std::to_string(pquad.size()) + " values for " +
             std::to_string(topo->quads().size()) + " quads (4 each)");
    else r.cell_data = true;
  }
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  if (r.point_data) scan(pt, lo, hi);
  if (r.cell_data) {  // each non-empty list overwrites the range (SOFA's order)
    if (!tri.empty()) scan(tri, lo, hi);
    if (!quad.empty()) scan(quad, lo, hi);
    if (!ptri.empty()) scan(ptri, lo, hi);
    if (!pquad.empty()) scan(pquad, lo, hi);
  }
  const Vec2 user = user_range.get();
  if (user[0] < user[1]) {
    if (maximal_range.get()) {
      if (hi > user[1]) hi = user[1];
      if (lo < user[0]) lo = user[0];
    } else {
      hi = user[1];
      lo = user[0];
    }
  }
  if (hi > old_max_) old_max_ = hi;
  if (lo < old_min_) old_min_ = lo;
  if (maximal_range.get()) {
    hi = old_max_;
    lo = old_min_;
  }
  current_min.set(lo);
  current_max.set(hi);
  r.min = lo;
  r.max = hi;
  return r;
}

Rgba DataDisplay::color_of(double v, double min, double max) const {
  Rgba c = nan_color_;
  if (!std::isnan(v)) c = evaluate_palette(color_map ? color_map->palette() : default_palette_, min, max, v);
  c[3] = static_cast<float>(transparency.get());
  return c;
}

void register_data_display(Registry& r) {
  ComponentInfo info;
  info.name = "DataDisplay";
  info.category = "Visual";
  info.description = "colours a mesh by values per point, per face or per face corner (viewer only)";
  info.create = creator<DataDisplay>();
  r.add(std::move(info));
}

}  // namespace sinew
