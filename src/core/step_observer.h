// StepObserver: the seam between stages where outside code acts on a running
// simulation (MuJoCo's "user can modify ctrl between mj_step1 and mj_step2",
// its mjcb_* callbacks). A controller or a haptic device applies its inputs
// before a stage (e.g. before collision) and reads the state after one (e.g.
// after end integration). Observers belong to one simulation (its root).
#pragma once

#include "core/profile.h"

namespace sinew {

class Node;

class StepObserver {
 public:
  virtual ~StepObserver() = default;
  // `root` is the simulation's root node. The graph is locked (no structural
  // edit) around every stage but begin_events and end_events.
  virtual void before_stage(Stage, Node& /*root*/) {}
  virtual void after_stage(Stage, Node& /*root*/) {}
};

}  // namespace sinew
