// MatrixProjectionMethod (SOFA's Component/LinearSystem): how an assembled linear
// system brings the matrix block recorded between two states, one of them at
// least below mappings, to the independent states: Jᵀ·K·J through the chains of
// mapping Jacobians (mapped_assembly.h). The assembler does that for every
// pair; this component names one ordered pair (`mechanicalStates`: rows, then
// columns) and, with `areJacobiansConstant`, has that pair's Jacobians computed
// at the first assembly and reused afterwards, as SOFA caches them (computed
// again when the assembly pattern changes). The first component of the graph
// naming a pair is the one used (SOFA's search from the root).
#pragma once

#include "core/roles.h"

namespace sinew {

class MatrixProjectionMethod final : public Component {
 public:
  MultiLink<MechanicalState> mechanical_states{this, "mechanicalStates",
                                               "the pair of states whose matrix block is projected (rows, columns)"};
  Field<bool> are_jacobians_constant{this, "areJacobiansConstant", false,
                                     "the mapping Jacobians are computed once, at the first assembly", "Projection"};

  void init() override;
  // SOFA's hasPairStates: the first two linked states are (rows, columns).
  bool has_pair(const MechanicalState* rows, const MechanicalState* cols) const;
};

}  // namespace sinew
