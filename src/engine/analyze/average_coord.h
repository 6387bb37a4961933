// AverageCoord: the mean of some coordinates of a state (SOFA's
// Engine/Analyze): the entries `indices` (all when empty) of the state's
// vector vecId (SOFA's numbering: 1 position, 2 rest_position, 3
// free_position, 4 reset_position), recomputed when read and at every
// AnimateBeginEvent. Rigid templates average the quaternions component-wise
// and, as SOFA, start the sum from the identity quaternion (its w adds 1).
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class AverageCoord final : public Engine {
 public:
  explicit AverageCoord(StateType type);

  Link<MechanicalState> mstate{this, "mstate", "state whose coordinates are averaged (default: the node's)"};
  Field<std::vector<unsigned>> indices{this, "indices", {}, "entries averaged (all when empty)", "Inputs"};
  Field<unsigned> vec_id{this, "vecId", 1, "vector averaged (1 position, 2 rest_position, 3 free, 4 reset)",
                         "Inputs"};
  Field<FlatVec> average;

  void init() override;
  void reinit() override { update(); }
  void handle_event(Event& e) override;

 protected:
  void do_update() override;

 private:
  StateType type_;
};

}  // namespace sinew
