// BarycentricMapping: each output point is a fixed weighted sum of the
// vertices of one input element (spec/mechanics.md §6.2). Vec3d → Vec3d
// (Vec3d → Rigid3d frames: barycentric_mapping_rigid.h, same XML class).
//
// The input topology (`input_topology`, default: the first mesh topology of
// the input state's node or its ancestors) decides the mapper:
//  - RegularGridTopology: the grid cell containing the point (computed from
//    the grid's own origin and spacing), else the nearest cell with
//    extrapolated coordinates; trilinear weights. No mapper without volume.
//  - SparseGridTopology: the same with the sparse grid's findCube /
//    findNearestCube (nearest boundary cell).
//  - *SetTopologyContainer: hexahedra, else tetrahedra, quads, triangles;
//    nearest element by SOFA's distance criterion; weights summed in
//    element-node order.
//  - other meshes (MeshTopology, loaders' meshes): tetrahedra and hexahedra,
//    else triangles and quads, else edges (MeshMapper rules and summation order).
// Coordinates are computed at init from the current (or, with
// useRestPosition, rest) positions of input and output (barycentric_coords.h).
// Whatever the mapper, the result is one table of vertices and weights per
// output point (barycentric_table.h): J is constant, apply and apply_j gather
// with it, apply_jt scatters weight·f.
//
// Topological changes. SOFA's BarycentricMapping::handleTopologyChange runs for
// every propagation whose visit reaches it (any source topology: input, output
// or another) and calls TopologyBarycentricMapper::processTopologicalChanges,
// which is not virtual: every mapper clears its map and runs its init again
// from the current `position` of output and input (never the rest positions),
// with the mapper chosen at init (a tetrahedron mapper keeps searching
// tetrahedra only). The per-mapper handlers (tetrahedron mapper's
// processTopologicalChanges, hexahedron mapper's handleTopologyChange) are never
// reached: the first is hidden behind the non-virtual call, the second belongs
// to the mapper, a slave the visitor does not visit; its `map` PointData has no
// topology handler. Sinew does the same relocation, once the change is over
// rather than in the middle of it: each propagation takes a snapshot of both
// positions (renumbered as the coming point removal will renumber the states),
// and the next use of the map relocates the snapshot's output points among the
// current elements. Where SOFA's result is defined (its last propagation of a
// change sees the final elements: element removals followed by a cascade,
// additions) the two agree; where SOFA keeps stale element indices (a removal
// without cascade, output points removed: its map keeps the old count and
// regrows the output) Sinew's map follows the final lists instead. When no
// element of the mapper's kind remains, the output points keep their positions
// (warning once; SOFA would read out of bounds).
#pragma once

#include <optional>

#include "mapping/linear/barycentric_coords.h"
#include "mapping/mapping_base.h"
#include "mapping/relocation_snapshot.h"

namespace sinew {

class BarycentricMapping final : public MappingBase {
 public:
  BarycentricMapping(StateType in, StateType out) : MappingBase(in, out) {}

  Field<bool> use_rest_position{this, "useRestPosition", false,
                                "compute the barycentric coordinates from the rest positions", "Mapping"};
  Link<MeshTopologyBase> input_topology{this, "input_topology", "topology of the embedding (input) mesh"};
  Link<MeshTopologyBase> output_topology{this, "output_topology", "topology of the embedded (output) mesh"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool has_jt_entry() const override { return true; }
  void jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  void handle_topology_change(MeshTopologyBase& source) override;

  // Which mapper was chosen ("RegularGrid", "Mesh", "TetrahedronSet", ...), for tests and messages.
  const std::string& mapper_name() const { return mapper_; }
  // The map as last built, without relocating (drawing: one frame late after a topological change).
  const BaryTable& drawn_table() const { return table_; }
  // The current map (after any pending relocation), for tests.
  const BaryTable& table() {
    follow_topology();
    return table_;
  }

 protected:
  bool init_mapping() override;
  bool apply_at_init() const override { return false; }

 private:
  struct Located {
    BaryReport report;
    const char* element = nullptr;  // word for the candidates in messages (nullptr: grids, edges)
    std::size_t n_elements = 0;
  };
  bool choose_mapper();
  Located locate(const std::vector<double>& in, const std::vector<double>& out, std::string& bad);
  bool report(const BaryReport& r, const char* element, std::size_t n_elements);

  // Topological changes (see above): relocate when a propagation reached the mapping or the
  // input's lists moved without one; cheap when nothing changed (called by every apply).
  // The last test keeps every read within the input, whatever happened to it.
  void follow_topology() {
    if (snapshot_.pending || input_version() != version_ || needed_ > in_[0]->size()) relocate();
  }
  void relocate();
  // Version of the list a set-container mapper searches (0 for the others: SOFA has them
  // follow propagations only, and their lists do not change).
  std::uint64_t input_version() const {
    return searched_ ? input_topology->elements_version(*searched_) : 0;
  }

  BaryTable table_;
  std::string mapper_;
  std::optional<MeshTopologyBase::Elements> searched_;  // the set-container mapper's list
  std::uint64_t version_ = 0;   // input_version() the table was built against
  std::size_t needed_ = 0;      // input points the table reads
  bool frozen_ = false;         // no element left: outputs keep their positions
  bool warned_frozen_ = false;
  RelocationSnapshot snapshot_;  // positions at the last propagation, renumbered
};

}  // namespace sinew
