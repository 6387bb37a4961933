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
#pragma once

#include "mapping/barycentric_coords.h"
#include "mapping/mapping_base.h"

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

  // Which mapper was chosen ("RegularGrid", "Mesh", "TetrahedronSet", ...), for tests and messages.
  const std::string& mapper_name() const { return mapper_; }

 protected:
  bool init_mapping() override;
  bool apply_at_init() const override { return false; }

 private:
  bool init_regular_grid(const std::vector<double>& out);
  bool init_sparse_grid(const std::vector<double>& out);
  bool init_mesh(const std::vector<double>& out, const std::vector<double>& in, bool set_container);
  bool report(const BaryReport& r, const char* element, std::size_t n_elements);

  BaryTable table_;
  std::string mapper_;
};

}  // namespace sinew
