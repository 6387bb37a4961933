// BarycentricMapping Vec3d → Rigid3d: frames embedded in a tetrahedral mesh
// (SOFA's BarycentricMapperTetrahedronSetTopologyRigid,
// Sofa/Component/Mapping/Linear/BarycentricMappingRigid.inl). The XML class is
// BarycentricMapping; the registry creates this class for "Vec3d,Rigid3d".
//
// init (from the current, or with useRestPosition the rest, positions): each
// frame takes the nearest tetrahedron (SOFA's criterion: the first one that
// contains its centre, else the one with the nearest centroid) and stores
//  - the barycentric coordinates (fx, fy, fz) of its centre, and
//  - each axis d_c of its orientation in the tetrahedron's edge basis E
//    (columns x1−x0, x2−x0, x3−x0): b_c = E⁻¹·d_c / ‖E⁻¹·d_c‖.
// apply: centre = x0·(1−fx−fy−fz) + x1·fx + x2·fy + x3·fz; orientation = the
// rotation of the polar decomposition of [E·b_0 E·b_1 E·b_2] (E current).
//
// J is SOFA's, which is NOT the derivative of apply for the rotation:
//   v = Σ w_k·v_k (the derivative),   ω = Σ_k x_k × v_k over the 4 vertices,
// with x_k the input positions at the last apply (absolute: ω depends on the
// origin, and a translation of the tetrahedron gives ω ≠ 0). Jᵀ is its exact
// transpose: a torque τ adds τ × x_k to each vertex. The assembled J
// (jacobian()) is the same. Constraint rows (apply_jt_constraints) carry only
// the translation part, as SOFA's applyJT on constraint matrices does.
// These are kept because the project reproduces SOFA's numbers; the battery
// checks the translation rows against finite differences and Jᵀ against J.
//
// Only tetrahedral set containers are supported as inputs (SOFA chooses other,
// generic mappers for grids, hexahedra and MeshTopology): anything else is an
// error at init. Topological changes are followed as BarycentricMapping does
// (SOFA's same handleTopologyChange: the mapper's init again, centres and axes
// taken from the output's current frames): every propagation reaching the
// mapping snapshots the positions, the next use re-embeds the frames among the
// final tetrahedra; none left: the frames stay where they are (one warning).
#pragma once

#include <array>

#include "mapping/mapping_base.h"
#include "mapping/relocation_snapshot.h"

namespace sinew {

class BarycentricMappingRigid final : public MappingBase {
 public:
  BarycentricMappingRigid() : MappingBase(StateType::vec3, StateType::rigid3) {}

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

  // What init computed for frame i: its tetrahedron, the barycentric coordinates
  // (fx, fy, fz) of its centre, and axis c of its orientation in the edge basis.
  struct Embedding {
    unsigned tetra = 0;
    double bary[3] = {0, 0, 0};
    double axis[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};  // axis[c] = b_c
  };
  // (after any pending re-embedding)
  const std::vector<Embedding>& embeddings() {
    follow_topology();
    return map_;
  }

 protected:
  bool init_mapping() override;
  // Like BarycentricMapping: SOFA creates the mapper after Mapping::init, so the
  // first apply is the end-of-init propagation.
  bool apply_at_init() const override { return false; }

 private:
  const Tetra& tetra_of(std::size_t i) const { return tetras_[map_[i].tetra]; }
  // Embeds the frames of `out` (7 per frame) in the tetrahedra of the input topology, points read
  // from `in`; the problem that made it impossible, else "". `degenerate` receives the flat ones.
  std::string embed(const std::vector<double>& in, const std::vector<double>& out,
                    std::vector<std::size_t>& degenerate);
  // Re-embeds after a propagation, or when the tetrahedra changed without one (then with a
  // warning), or when the input lost points the copy uses. Cheap otherwise.
  void follow_topology() {
    if (snapshot_.pending || tetra_version() != version_ || needed_ > in_[0]->size()) reembed();
  }
  void reembed();
  std::uint64_t tetra_version() const {
    return input_topology->elements_version(MeshTopologyBase::Elements::tetrahedra);
  }

  std::vector<Tetra> tetras_;        // the input tetrahedra when the frames were embedded
  std::vector<Embedding> map_;
  std::vector<double> actual_;       // input positions at the last apply (3 per vertex), SOFA's actualTetraPosition
  std::uint64_t version_ = 0;        // tetra_version() of tetras_
  std::size_t needed_ = 0;           // input points tetras_ uses
  bool frozen_ = false;              // no tetrahedron left: the frames keep their positions
  bool warned_frozen_ = false;
  RelocationSnapshot snapshot_;
};

}  // namespace sinew
