#include "topology/mapping/hexa2_quad_topological_mapping.h"

#include <algorithm>
#include <utility>

#include "core/registry.h"
#include "topology/dynamic/quad_set_topology_modifier.h"

namespace sinew {

void Hexa2QuadTopologicalMapping::init() {
  if (!check_links(true, ElementType::hexahedron, ElementType::quad)) return;
  modifier_ = find_from_output<QuadSetTopologyModifier>();
  if (!modifier_) {
    msg_error("No QuadSetTopologyModifier found in the output topology node '" + output->node()->name.value() +
              "'.");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<Quad> quads = input->quads();
  const auto& around = input->hexahedra_around_quad();
  const std::size_t np = input->nb_points();
  output->clear_topology();
  output->set_nb_points(np);
  loc2glob_.clear();
  glob2loc_.assign(quads.size(), kUnmapped);
  std::vector<Quad> out;
  const bool flip = flip_normals.value();
  for (std::size_t i = 0; i < quads.size(); ++i) {
    if (i >= around.size() || around[i].size() != 1) continue;
    const Quad& q = quads[i];
    out.push_back(flip ? Quad{q[3], q[2], q[1], q[0]} : q);
    glob2loc_[i] = static_cast<unsigned>(loc2glob_.size());
    loc2glob_.push_back(static_cast<unsigned>(i));
  }
  output->quads_f.set(std::move(out));
  output->init();
}

void Hexa2QuadTopologicalMapping::set_glob2loc(unsigned glob, unsigned loc) {
  if (glob >= glob2loc_.size()) glob2loc_.resize(glob + 1u, kUnmapped);
  glob2loc_[glob] = loc;
}

void Hexa2QuadTopologicalMapping::update_top_down() {
  if (!input || !output || !modifier_ || state() != ComponentState::valid) return;
  // Handlers below may queue events on the output only; the input's list is stable here.
  const std::vector<TopologyChange> changes = input->topology_changes();
  for (const TopologyChange& c : changes) {
    switch (c.type) {
      case TopologyChangeType::ending: modifier_->notify_ending_event(); break;
      case TopologyChangeType::quads_removed: on_quads_removed(c.indices); break;
      case TopologyChangeType::hexahedra_removed: on_hexahedra_removed(c.indices); break;
      case TopologyChangeType::points_removed: modifier_->remove_points(c.indices, false); break;
      default: break;  // SOFA follows no addition here
    }
  }
}

// Received before the input changes: a face shared by a removed hexahedron and another one not
// removed earlier in the list becomes boundary; it is built from that other hexahedron's face
// (kQuadsInHexa order, outward for it), unrotated.
void Hexa2QuadTopologicalMapping::on_hexahedra_removed(const std::vector<unsigned>& removed) {
  const auto& hexas = input->hexahedra();
  const auto& faces_in = input->quads_in_hexahedron();
  const auto& around = input->hexahedra_around_quad();
  const bool flip = flip_normals.value();
  std::vector<Quad> create;
  for (std::size_t i = 0; i < removed.size(); ++i) {
    const unsigned hex = removed[i];
    for (unsigned k : faces_in[hex]) {
      const auto& shell = around[k];
      if (shell.size() == 1) continue;  // its output copy goes with the input quad
      if (shell.size() < 2) continue;
      const unsigned other = shell[0] == hex ? shell[1] : shell[0];
      if (std::find(removed.begin(), removed.begin() + static_cast<std::ptrdiff_t>(i), other) !=
          removed.begin() + static_cast<std::ptrdiff_t>(i))
        continue;  // that pair was handled from the other side
      const auto& row = faces_in[other];
      const unsigned pos = static_cast<unsigned>(std::find(row.begin(), row.end(), k) - row.begin());
      if (pos >= 6) continue;
      Quad q;
      for (unsigned v = 0; v < 4; ++v) q[v] = hexas[other][topo::kQuadsInHexa[pos][v]];
      if (flip) q = Quad{q[3], q[2], q[1], q[0]};
      create.push_back(q);
      loc2glob_.push_back(k);
      if (glob2loc(k) != kUnmapped) msg_warning("Failed to add quad " + std::to_string(k) + " which already exists");
      set_glob2loc(k, static_cast<unsigned>(loc2glob_.size() - 1));
    }
  }
  modifier_->add_quads(create);
}

// Input quads removed (received before the input changes): each mapped one is removed from the
// output on its own, after both maps mirrored the swap-with-last of the input and of the output
// (SOFA's bookkeeping, step by step).
void Hexa2QuadTopologicalMapping::on_quads_removed(const std::vector<unsigned>& removed) {
  unsigned last = static_cast<unsigned>(input->quads().size() - 1);
  unsigned ind_last = static_cast<unsigned>(output->quads().size());
  for (unsigned k : removed) {
    if (glob2loc(k) != kUnmapped) {
      --ind_last;
      const unsigned ind_k = glob2loc(k);
      if (glob2loc(last) != kUnmapped && k != last) {
        const unsigned ind_real_last = glob2loc(last);
        glob2loc_[k] = ind_real_last;
        glob2loc_[last] = ind_k;
        std::swap(loc2glob_[ind_real_last], loc2glob_[ind_k]);
      }
      if (ind_k != ind_last) {
        set_glob2loc(loc2glob_[ind_last], ind_k);
        set_glob2loc(loc2glob_[ind_k], ind_last);
        std::swap(loc2glob_[ind_k], loc2glob_[ind_last]);
      }
      if (loc2glob_.back() < glob2loc_.size()) glob2loc_[loc2glob_.back()] = kUnmapped;
      loc2glob_.pop_back();
      modifier_->remove_quads({ind_k}, true, false);
    } else {
      msg_warning("Glob2LocMap should have the visible quad " + std::to_string(k) + " - nb quads = " +
                  std::to_string(ind_last));
    }
    --last;
  }
}

void register_hexa2_quad_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Hexa2QuadTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where HexahedronSetTopology is converted to QuadSetTopology";
  info.create = creator<Hexa2QuadTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
