// Engine: a component computing output fields from input fields, lazily.
//
// Reading an output runs the engine if any input changed since the last run
// (version comparison), like SOFA's DataEngine. No per-step engine pass.
#pragma once

#include <cstdint>
#include <vector>

#include "core/component.h"

namespace sinew {

class Engine : public Component {
 public:
  // Runs do_update() when an input changed (or never ran); re-entrant calls are ignored.
  void update();
  // Forces the next read of an output to recompute.
  void set_dirty() { dirty_ = true; }

 protected:
  void add_input(BaseField* f);
  void add_output(BaseField* f);
  virtual void do_update() = 0;

 private:
  std::vector<BaseField*> inputs_, outputs_;
  std::vector<std::uint64_t> seen_;
  bool dirty_ = true;
  bool updating_ = false;
};

}  // namespace sinew
