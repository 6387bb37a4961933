// Quad2TriangleTopologicalMapping: splits each quad of the input into two
// triangles, alternating the diagonal in a checkerboard when `swapping`
// (spec/mechanics.md §5.7). The output follows the input's changes as SOFA's
// updateTopologicalMappingTopDown does (spec/interaction.md §7.3): added quads
// bring two triangles each (p0 p1 p2, p0 p2 p3: no checkerboard), removed quads
// take theirs, points follow.
#pragma once

#include <array>

#include "topology/mapping/topological_mapping.h"

namespace sinew {

class TriangleSetTopologyModifier;

class Quad2TriangleTopologicalMapping final : public TopologicalMapping {
 public:
  Field<bool> swapping{this, "swapping", true,
                       "If true (default), alternate the diagonal orientation per quad in a checkerboard pattern to "
                       "avoid numerical bias",
                       "Mapping"};
  void init() override;
  void update_top_down() override;

  // Output triangle → input quad, and input quad → its two output triangles (kUnmapped when not mapped).
  const std::vector<unsigned>& loc2glob() const { return loc2glob_; }
  std::array<unsigned, 2> in2out(unsigned quad) const {
    return quad < in2out_.size() ? in2out_[quad] : std::array<unsigned, 2>{kUnmapped, kUnmapped};
  }
  static constexpr unsigned kUnmapped = ~0u;

 private:
  bool mapped(unsigned quad) const { return quad < in2out_.size() && in2out_[quad][0] != kUnmapped; }
  void set_in2out(unsigned quad, std::array<unsigned, 2> tris);
  void on_quads_added(const std::vector<unsigned>& added);
  void on_quads_removed(const std::vector<unsigned>& removed);

  TriangleSetTopologyModifier* modifier_ = nullptr;
  std::vector<unsigned> loc2glob_;
  // SOFA's In2OutMap (a map of pairs) as a flat array indexed by input quad.
  std::vector<std::array<unsigned, 2>> in2out_;
};

}  // namespace sinew
