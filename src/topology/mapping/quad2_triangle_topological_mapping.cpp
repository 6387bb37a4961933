#include "topology/mapping/quad2_triangle_topological_mapping.h"

#include <utility>

#include "core/registry.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew {

void Quad2TriangleTopologicalMapping::init() {
  if (!check_links(true, ElementType::quad, ElementType::triangle)) return;
  modifier_ = find_from_output<TriangleSetTopologyModifier>();
  if (!modifier_) {
    msg_error("No TriangleSetTopologyModifier found in the output topology node '" + output->node()->name.value() +
              "'.");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<Quad> quads = input->quads();
  const std::size_t np = input->nb_points();
  output->clear_topology();
  output->set_nb_points(np);

  int nx = 2, ny = 1;
  input_grid_cells(nx, ny);
  const int scale = nx == 0 ? ny : nx;
  if (nx == 0 && ny == 0) {
    msg_error("Input topology is only 1D, this topology can't be mapped into a triangulation.");
    set_state(ComponentState::invalid);
    return;
  }
  if (scale <= 0) {
    msg_error("the input grid has no cell along x or y");
    set_state(ComponentState::invalid);
    return;
  }
  const unsigned s = static_cast<unsigned>(scale);
  std::vector<Triangle> out;
  out.reserve(quads.size() * 2);
  loc2glob_.clear();
  in2out_.assign(quads.size(), {kUnmapped, kUnmapped});
  for (std::size_t k = 0; k < quads.size(); ++k) {
    const unsigned i = static_cast<unsigned>(k);
    const Quad& q = quads[k];
    if (swapping.value() && (((i % s) ^ (i / s)) & 1u)) {
      out.push_back({q[0], q[1], q[3]});
      out.push_back({q[2], q[3], q[1]});
    } else {
      out.push_back({q[1], q[2], q[0]});
      out.push_back({q[3], q[0], q[2]});
    }
    loc2glob_.push_back(i);
    loc2glob_.push_back(i);
    in2out_[k] = {2 * i, 2 * i + 1};
  }
  output->triangles_f.set(std::move(out));
  output->init();
}

void Quad2TriangleTopologicalMapping::set_in2out(unsigned quad, std::array<unsigned, 2> tris) {
  if (quad >= in2out_.size()) in2out_.resize(quad + 1u, {kUnmapped, kUnmapped});
  in2out_[quad] = tris;
}

void Quad2TriangleTopologicalMapping::update_top_down() {
  if (!input || !output || !modifier_ || state() != ComponentState::valid) return;
  // Handlers below may queue events on the output only; the input's list is stable here.
  const std::vector<TopologyChange> changes = input->topology_changes();
  for (const TopologyChange& c : changes) {
    switch (c.type) {
      case TopologyChangeType::ending: modifier_->notify_ending_event(); break;
      case TopologyChangeType::quads_added: on_quads_added(c.indices); break;
      case TopologyChangeType::quads_removed: on_quads_removed(c.indices); break;
      case TopologyChangeType::points_removed: modifier_->remove_points(c.indices, false); break;
      case TopologyChangeType::points_added:
        msg_error("point additions are not followed yet: the output keeps its points");
        break;
      default: break;
    }
  }
}

// Received after the input changed: two triangles per new quad, split along p0–p2.
void Quad2TriangleTopologicalMapping::on_quads_added(const std::vector<unsigned>& added) {
  const auto& quads = input->quads();
  std::vector<Triangle> create;
  for (unsigned k : added) {
    const Quad& q = quads[k];
    create.push_back({q[0], q[1], q[2]});
    create.push_back({q[0], q[2], q[3]});
    loc2glob_.push_back(k);
    loc2glob_.push_back(k);
    const unsigned n = static_cast<unsigned>(loc2glob_.size());
    set_in2out(k, {n - 2, n - 1});
  }
  modifier_->add_triangles(create);
}

// Received before the input changes: each mapped quad's two triangles are removed from the output
// on their own, after the maps mirrored both swap-with-lasts (SOFA's bookkeeping, step by step,
// including the reversed pair it records when the output's last pair moves).
void Quad2TriangleTopologicalMapping::on_quads_removed(const std::vector<unsigned>& removed) {
  unsigned last = static_cast<unsigned>(input->quads().size() - 1);
  unsigned ind_last = static_cast<unsigned>(output->triangles().size());
  for (unsigned k : removed) {
    if (!mapped(k)) {
      --last;
      continue;  // SOFA only informs
    }
    const std::array<unsigned, 2> ind_k = in2out_[k];
    --ind_last;
    if (mapped(last)) {
      const std::array<unsigned, 2> ind_real_last = in2out_[last];
      if (k != last) {
        in2out_[k] = ind_real_last;
        in2out_[last] = ind_k;
        std::swap(loc2glob_[ind_real_last[0]], loc2glob_[ind_k[0]]);
        std::swap(loc2glob_[ind_real_last[1]], loc2glob_[ind_k[1]]);
      }
    } else {
      msg_warning("In2OutMap should have the quad " + std::to_string(last));
    }
    if (ind_k[1] != ind_last) {
      set_in2out(loc2glob_[ind_last], ind_k);
      set_in2out(loc2glob_[ind_k[1]], {ind_last, ind_last - 1});
      std::swap(loc2glob_[ind_k[1]], loc2glob_[ind_last]);
    }
    --ind_last;
    if (ind_k[0] != ind_last) std::swap(loc2glob_[ind_k[0]], loc2glob_[ind_last]);
    if (loc2glob_.back() < in2out_.size()) in2out_[loc2glob_.back()] = {kUnmapped, kUnmapped};
    loc2glob_.resize(loc2glob_.size() - 2);
    modifier_->remove_triangles({ind_k[0], ind_k[1]}, true, false);
    --last;
  }
}

void register_quad2_triangle_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Quad2TriangleTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where QuadSetTopology is converted to TriangleSetTopology";
  info.create = creator<Quad2TriangleTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
