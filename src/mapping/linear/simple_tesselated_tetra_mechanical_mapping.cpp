#include "mapping/linear/simple_tesselated_tetra_mechanical_mapping.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/mapping/simple_tesselated_tetra_topological_mapping.h"

namespace sinew {

namespace {
constexpr unsigned kNone = SimpleTesselatedTetraTopologicalMapping::kNone;
}

bool SimpleTesselatedTetraMechanicalMapping::init_mapping() {
  topo_map_ = node() ? node()->find_up<SimpleTesselatedTetraTopologicalMapping>() : nullptr;
  if (!topo_map_ || !topo_map_->input || !topo_map_->output) {
    msg_error("no SimpleTesselatedTetraTopologicalMapping found from this node up (it gives the refined points)");
    return false;
  }
  resize_output(topo_map_->output->nb_points());
  return true;
}

bool SimpleTesselatedTetraMechanicalMapping::map(const std::vector<double>& in, std::vector<double>& out) const {
  if (!topo_map_ || topo_map_->state() != ComponentState::valid) return false;
  const std::vector<unsigned>& from_point = topo_map_->point_mapped_from_point.value();
  const std::vector<unsigned>& from_edge = topo_map_->point_mapped_from_edge.value();
  if (from_point.empty() && from_edge.empty()) return false;
  const std::vector<Edge>& edges = topo_map_->input->edges();
  const std::size_t n_in = in.size() / 3, n_out = topo_map_->output->nb_points();
  if (out.size() != 3 * n_out) out.resize(3 * n_out, 0.0);
  for (std::size_t i = 0; i < from_point.size() && i < n_in; ++i)
    if (from_point[i] != kNone && from_point[i] < n_out)
      for (int c = 0; c < 3; ++c) out[3 * from_point[i] + c] = in[3 * i + c];
  for (std::size_t i = 0; i < from_edge.size() && i < edges.size(); ++i) {
    const unsigned o = from_edge[i], a = edges[i][0], b = edges[i][1];
    if (o == kNone || o >= n_out || a >= n_in || b >= n_in) continue;
    for (int c = 0; c < 3; ++c) out[3 * o + c] = (in[3 * a + c] + in[3 * b + c]) * 0.5;
  }
  return true;
}

void SimpleTesselatedTetraMechanicalMapping::apply(int x) {
  if (topo_map_ && out_size() != topo_map_->output->nb_points()) resize_output(topo_map_->output->nb_points());
  std::vector<double>* out = out_coord(x);
  if (out) map(in_coord(x), *out);
}

void SimpleTesselatedTetraMechanicalMapping::apply_j(int v, int role) {
  std::vector<double>* out = out_deriv(v, role);
  if (out) map(in_deriv(v, role), *out);
}

void SimpleTesselatedTetraMechanicalMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp || !topo_map_ || topo_map_->state() != ComponentState::valid) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::vector<unsigned>& from_point = topo_map_->point_mapped_from_point.value();
  const std::vector<unsigned>& from_edge = topo_map_->point_mapped_from_edge.value();
  const std::vector<Edge>& edges = topo_map_->input->edges();
  const std::size_t n_in = in.size() / 3, n_out = out.size() / 3;
  for (std::size_t i = 0; i < from_point.size() && i < n_in; ++i)
    if (from_point[i] != kNone && from_point[i] < n_out)
      for (int c = 0; c < 3; ++c) in[3 * i + c] += out[3 * from_point[i] + c];
  for (std::size_t i = 0; i < from_edge.size() && i < edges.size(); ++i) {
    const unsigned o = from_edge[i], a = edges[i][0], b = edges[i][1];
    if (o == kNone || o >= n_out || a >= n_in || b >= n_in) continue;
    for (int c = 0; c < 3; ++c) {
      const double h = out[3 * o + c] * 0.5;
      in[3 * a + c] += h;
      in[3 * b + c] += h;
    }
  }
}

bool SimpleTesselatedTetraMechanicalMapping::jacobian(std::vector<JacobianEntry>& out) {
  if (!topo_map_ || topo_map_->state() != ComponentState::valid) return false;
  const std::vector<unsigned>& from_point = topo_map_->point_mapped_from_point.value();
  const std::vector<unsigned>& from_edge = topo_map_->point_mapped_from_edge.value();
  const std::vector<Edge>& edges = topo_map_->input->edges();
  const std::size_t n_in = in_size(), n_out = out_size();
  auto put = [&](unsigned o, unsigned i, double w) {
    for (std::uint32_t c = 0; c < 3; ++c) out.push_back({0, 3 * o + c, 3 * i + c, w});
  };
  for (std::size_t i = 0; i < from_point.size() && i < n_in; ++i)
    if (from_point[i] != kNone && from_point[i] < n_out) put(from_point[i], static_cast<unsigned>(i), 1.0);
  for (std::size_t i = 0; i < from_edge.size() && i < edges.size(); ++i) {
    const unsigned o = from_edge[i], a = edges[i][0], b = edges[i][1];
    if (o == kNone || o >= n_out || a >= n_in || b >= n_in) continue;
    put(o, a, 0.5);
    put(o, b, 0.5);
  }
  return true;
}

void register_simple_tesselated_tetra_mechanical_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "SimpleTesselatedTetraMechanicalMapping";
  info.category = "Mapping/Linear";
  info.description = "DoFs of a tetrahedral mesh refined by SimpleTesselatedTetraTopologicalMapping";
  info.templates = {"Vec3d,Vec3d"};
  info.default_template = "Vec3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    if (in != StateType::vec3 || out != StateType::vec3) return nullptr;
    return std::make_unique<SimpleTesselatedTetraMechanicalMapping>(in, out);
  };
  r.add(std::move(info));
}

}  // namespace sinew
