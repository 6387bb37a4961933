// ReadState (SOFA's Sofa.Component.Playback; spec/user-interfaces.md §4.4): replays a state
// file written by WriteState into the node's mechanical state.
//
// At bwd_init and at every AnimateBeginEvent, with t = time + shift, the last block whose
// "T=" is ≤ t (and that was not applied yet) gives the positions (X=, then scalePos, the
// Euler `rotation` in degrees and `translation`, as SOFA's MechanicalObject applies them)
// and velocities (V=); then the node's subtree is projected and mapped. With `loop`, the
// file starts again after its end, its times shifted by the last time read. A time going
// back by more than dt/2 (a reset) rewinds the file. `interval` is accepted and unused, as
// in SOFA. The filename is searched in the data folders (the scene's first).
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"
#include "regression/state_file.h"

namespace sinew {

class ReadState : public Component {
 public:
  ReadState();

  Field<std::string> filename{this, "filename", "", "state file to read (plain or gzip)", "Export"};
  Field<double> interval{this, "interval", 0.0, "time between inputs (unused, as in SOFA)", "Export", "time"};
  Field<double> shift{this, "shift", 0.0, "added to the simulation time to find the block to read", "Export", "time"};
  Field<bool> loop{this, "loop", false, "start the file again when its end is reached", "Export"};
  Field<double> scale_pos{this, "scalePos", 1.0, "scale applied to the positions read", "Transformation"};
  Field<Vec3> rotation{this, "rotation", Vec3::Zero(), "rotation applied to the positions read (Euler, degrees)",
                       "Transformation"};
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "translation applied to the positions read",
                          "Transformation", "length"};

  void init() override;
  void bwd_init() override;
  void reset() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }
  // Reads what is due at the node's current time; true when the state was updated.
  bool process();

 protected:
  MechanicalState* state_ = nullptr;
  std::vector<regression::StateBlock> blocks_;  // the whole file, parsed at init/reset
  bool opened_ = false;

 private:
  bool apply(const regression::StateBlock& b);

  std::size_t cursor_ = 0;  // next block to look at
  double loop_offset_ = 0, last_time_ = 0, next_time_ = 0;
  bool warned_size_ = false;
};

}  // namespace sinew
