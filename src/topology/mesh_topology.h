// MeshTopology-like containers: point coordinates and element lists as fields.
//
// The base of the static containers (MeshTopology, RegularGridTopology, ...).
// Subclasses that generate their lists (grids) override `generate()`, which
// runs lazily on first access so that components initialised earlier in the
// node (a MechanicalObject declared before its grid) already see the data.
#pragma once

#include "core/roles.h"

namespace sinew {

class MeshContainer : public MeshTopologyBase {
 public:
  MeshContainer();

  Field<std::vector<Vec3>> position{this, "position", {}, "vertex coordinates", "Topology"};
  Field<std::vector<Edge>> edges_f{this, "edges", {}, "edges (pairs of point indices)", "Topology"};
  Field<std::vector<Triangle>> triangles_f{this, "triangles", {}, "triangles", "Topology"};
  Field<std::vector<Quad>> quads_f{this, "quads", {}, "quads", "Topology"};
  Field<std::vector<Tetra>> tetrahedra_f{this, "tetrahedra", {}, "tetrahedra", "Topology"};
  Field<std::vector<Hexa>> hexahedra_f{this, "hexahedra", {}, "hexahedra", "Topology"};

  std::size_t nb_points() const override;
  bool has_positions() const override;
  Vec3 point(std::size_t i) const override;
  const std::vector<Edge>& edges() const override { return ensure(), edges_f.get(); }
  const std::vector<Triangle>& triangles() const override { return ensure(), triangles_f.get(); }
  const std::vector<Quad>& quads() const override { return ensure(), quads_f.get(); }
  const std::vector<Tetra>& tetrahedra() const override { return ensure(), tetrahedra_f.get(); }
  const std::vector<Hexa>& hexahedra() const override { return ensure(), hexahedra_f.get(); }

  void init() override { ensure(); }

 protected:
  // Fills the fields from the subclass's parameters; called once, lazily.
  virtual void generate() {}
  // Invalidate generated data (parameters changed).
  void regenerate() { generated_ = false; }

 private:
  void ensure() const;
  mutable bool generated_ = false;
};

}  // namespace sinew
