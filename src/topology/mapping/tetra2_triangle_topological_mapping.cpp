#include "topology/mapping/tetra2_triangle_topological_mapping.h"

#include <algorithm>
#include <functional>

#include "core/registry.h"
#include "topology/dynamic/edge_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew {

void Tetra2TriangleTopologicalMapping::init() {
  if (!check_links(false, ElementType::tetrahedron, ElementType::triangle)) return;
  if (!modifier) modifier.set(find_from_output<TriangleSetTopologyModifier>());
  if (!modifier)
    msg_warning("No TriangleSetTopologyModifier found in output topology context. Dynamic topological changes "
                "will not be supported.");

  const std::vector<Triangle> tris = input->triangles();
  const auto& around = input->tetrahedra_around_triangle();
  const std::size_t np = input->nb_points();
  output->clear_topology();
  output->set_nb_points(np);
  loc2glob_.clear();
  glob2loc_.assign(tris.size(), kUnmapped);
  if (no_initial_triangles.value()) return;

  std::vector<Triangle> out;
  const bool flip = flip_normals.value();
  for (std::size_t i = 0; i < tris.size(); ++i) {
    if (i >= around.size() || around[i].size() != 1) continue;
    const Triangle& t = tris[i];
    out.push_back(flip ? Triangle{t[0], t[2], t[1]} : t);
    glob2loc_[i] = static_cast<unsigned>(loc2glob_.size());
    loc2glob_.push_back(static_cast<unsigned>(i));
  }
  output->triangles_f.set(std::move(out));
  output->init();
}

void Tetra2TriangleTopologicalMapping::set_glob2loc(unsigned glob, unsigned loc) {
  if (glob >= glob2loc_.size()) glob2loc_.resize(glob + 1u, kUnmapped);
  glob2loc_[glob] = loc;
}

void Tetra2TriangleTopologicalMapping::update_top_down() {
  if (!input || !output || !modifier || state() == ComponentState::invalid) return;
  TriangleSetTopologyModifier& out = *modifier;
  // Handlers below may queue events on the output only; the input's list is stable here.
  const std::vector<TopologyChange> changes = input->topology_changes();
  for (const TopologyChange& c : changes) {
    switch (c.type) {
      case TopologyChangeType::ending: out.notify_ending_event(); break;
      case TopologyChangeType::triangles_removed: on_triangles_removed(c.indices); break;
      case TopologyChangeType::tetrahedra_added:
        if (!no_new_triangles.value()) on_tetrahedra_added(c.indices);
        break;
      case TopologyChangeType::tetrahedra_removed:
        if (!no_new_triangles.value()) on_tetrahedra_removed(c.indices);
        break;
      case TopologyChangeType::points_removed: out.remove_points(c.indices, false); break;
      case TopologyChangeType::edges_added: {  // copied as they are (propagated after the input changed)
        std::vector<Edge> edges;
        for (unsigned e : c.indices) edges.push_back(input->edges()[e]);
        out.add_edges(edges, c.ancestors, c.coefficients);
        break;
      }
      case TopologyChangeType::points_added:  // relayed with their DoFs (SOFA passes addDOF = true here)
        out.add_points(static_cast<unsigned>(c.indices.size()), c.ancestors, c.coefficients, true);
        break;
      // Triangle additions come with the tetrahedra that bring them (handled there); other kinds
      // do not concern the boundary triangles.
      default: break;
    }
  }
}

// Received before the input changes: a face shared by a removed tetrahedron and a kept one
// becomes boundary; it is built from the kept tetrahedron's face (outward for that tetrahedron).
void Tetra2TriangleTopologicalMapping::on_tetrahedra_removed(const std::vector<unsigned>& removed) {
  const auto& tets = input->tetrahedra();
  const auto& faces_in = input->triangles_in_tetrahedron();
  const auto& around = input->tetrahedra_around_triangle();
  const bool flip = flip_normals.value();
  std::vector<Triangle> create;
  for (std::size_t i = 0; i < removed.size(); ++i) {
    const unsigned tet = removed[i];
    for (unsigned f : faces_in[tet]) {
      const auto& shell = around[f];
      if (shell.size() != 2) continue;  // inner to more tetrahedra, or removed with its only one
      const unsigned other = shell[0] == tet ? shell[1] : shell[0];
      if (std::find(removed.begin(), removed.begin() + static_cast<std::ptrdiff_t>(i), other) !=
          removed.begin() + static_cast<std::ptrdiff_t>(i))
        continue;  // that pair was handled from the other side
      const auto& row = faces_in[other];
      const unsigned pos = static_cast<unsigned>(std::find(row.begin(), row.end(), f) - row.begin());
      if (pos >= 4) continue;
      Triangle t;
      for (unsigned k = 0; k < 3; ++k) t[k] = tets[other][topo::kTrianglesInTetra[pos][k]];
      if (flip) std::swap(t[1], t[2]);
      while (t[0] > t[1] || t[0] > t[2]) t = Triangle{t[1], t[2], t[0]};
      create.push_back(t);
      loc2glob_.push_back(f);
      set_glob2loc(f, static_cast<unsigned>(loc2glob_.size() - 1));
    }
  }
  modifier->add_triangles(create);
}

// Input triangles left without a tetrahedron (received before the input changes): their output
// copies go, and both maps mirror the swap-with-last of the input and of the output.
void Tetra2TriangleTopologicalMapping::on_triangles_removed(const std::vector<unsigned>& removed) {
  std::vector<unsigned> locals;
  for (unsigned g : removed)
    if (glob2loc(g) != kUnmapped) locals.push_back(glob2loc(g));
  std::sort(locals.begin(), locals.end(), std::greater<unsigned>());

  const unsigned n_in = static_cast<unsigned>(input->triangles().size());
  const unsigned n_out = static_cast<unsigned>(output->triangles().size());
  unsigned last_glob = n_in - 1;
  const unsigned kept_glob = n_in - static_cast<unsigned>(removed.size());
  const unsigned kept_loc = n_out - static_cast<unsigned>(locals.size());
  for (unsigned g : removed) {
    const unsigned last_loc = glob2loc(last_glob);
    if (last_loc != kUnmapped) {
      set_glob2loc(g, last_loc);
      if (last_loc < loc2glob_.size()) loc2glob_[last_loc] = g;
      glob2loc_[last_glob] = kUnmapped;
    } else if (glob2loc(g) != kUnmapped) {
      glob2loc_[g] = kUnmapped;
    }
    --last_glob;
  }
  for (unsigned loc : locals) {
    const unsigned glob = loc2glob_.back();
    loc2glob_[loc] = glob;
    if (glob < kept_glob && loc < kept_loc) set_glob2loc(glob, loc);
    loc2glob_.pop_back();
  }
  modifier->remove_triangles(locals, true, false);
}

// Received after the input changed: faces of the new tetrahedra that became boundary are added
// (input orientation), mapped faces that stopped being boundary are removed.
void Tetra2TriangleTopologicalMapping::on_tetrahedra_added(const std::vector<unsigned>& added) {
  const auto& faces_in = input->triangles_in_tetrahedron();
  const auto& around = input->tetrahedra_around_triangle();
  std::vector<Triangle> create;
  std::vector<unsigned> stale;
  for (unsigned tet : added)
    for (unsigned f : faces_in[tet]) {
      const std::size_t shell = around[f].size();
      if (glob2loc(f) != kUnmapped) {
        if (shell != 1) stale.push_back(f);
        continue;
      }
      if (shell > 1) continue;
      create.push_back(input->triangles()[f]);
      loc2glob_.push_back(f);
      set_glob2loc(f, static_cast<unsigned>(loc2glob_.size() - 1));
    }
  modifier->add_triangles(create);

  std::vector<unsigned> locals;
  for (unsigned f : stale) {
    const unsigned loc = glob2loc(f);
    if (loc == kUnmapped) {
      msg_error("on tetrahedra added: triangle " + std::to_string(f) + " is not mapped");
      continue;
    }
    locals.push_back(loc);
    glob2loc_[f] = kUnmapped;
  }
  std::sort(locals.begin(), locals.end(), std::greater<unsigned>());
  for (unsigned loc : locals) {
    const unsigned last = loc2glob_.back();
    loc2glob_[loc] = last;
    loc2glob_.pop_back();
    set_glob2loc(last, loc);
  }
  modifier->remove_triangles(locals, true, false);
}

bool Tetra2TriangleTopologicalMapping::input_elements(unsigned out, std::vector<unsigned>& in) const {
  if (!input || out >= loc2glob_.size()) return true;
  const auto& shells = input->tetrahedra_around_triangle();
  const unsigned glob = loc2glob_[out];
  // SOFA answers tetrahedron 0 for a face that bounds no single tetrahedron; nothing is safer.
  if (glob < shells.size() && shells[glob].size() == 1) in.push_back(shells[glob][0]);
  return true;
}

void register_tetra2_triangle_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Tetra2TriangleTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where TetrahedronSetTopology is converted to TriangleSetTopology";
  info.create = creator<Tetra2TriangleTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
