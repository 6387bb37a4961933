// What a barycentric mapping (Vec3 or Rigid3 output) relocates its output
// points from after a topological change. SOFA re-runs the mapper's init during
// each propagation reaching the mapping (barycentric_mapping.h); Sinew waits for
// the final element lists, so it keeps the positions of that moment and
// renumbers them as the coming point removal will renumber the states that
// follow the source topology (SOFA's states move their DoFs in the removal's
// process step, after the propagation).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class MechanicalState;
class MeshTopologyBase;

struct RelocationSnapshot {
  bool pending = false;      // a propagation reached the mapping since the last relocation
  std::vector<double> in;    // input positions, 3 per point
  std::vector<double> out;   // output positions, `out_stride` per point
  bool warned_unannounced = false;

  // During a propagation from `source`; a state follows its point removals when `source` is the
  // topology of its node.
  void take(const MeshTopologyBase& source, const MechanicalState* in_state, const std::vector<double>& in_now,
            const MechanicalState* out_state, const std::vector<double>& out_now, std::size_t out_stride);
  // The positions to relocate from, copied into in_pos/out_pos: the snapshot when the states
  // followed as expected (same sizes now), else the present ones. Returns, the first time the
  // lists changed without a propagation reaching the mapping (SOFA keeps a stale map then), the
  // warning naming `topology` and what the mapping does instead (`doing`); "" otherwise.
  std::string select(const std::vector<double>& in_now, const std::vector<double>& out_now,
                     std::vector<double>& in_pos, std::vector<double>& out_pos, const std::string& topology,
                     const std::string& doing);
  void clear() {
    pending = false;
    in.clear();
    out.clear();
  }
};

// The output of a mapping left without elements (frozen): positions stay where they are, and
// another position vector `x` (free motion) takes them.
inline void hold_output(int x, std::vector<double>& out, const std::vector<double>& position) {
  if (x != kPosition) out = position;
}

}  // namespace sinew
