// Engine: a component computing output fields from input fields, lazily.
//
// Reading an output runs the engine if any input changed since the last run
// (version comparison), like SOFA's DataEngine. No per-step engine pass.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/component.h"

namespace sinew {

class Engine : public Component {
 public:
  // Runs do_update() when an input changed (or never ran); re-entrant calls are ignored.
  void update();
  // Forces the next read of an output to recompute.
  void set_dirty() { dirty_ = true; }
  const std::vector<BaseField*>& inputs() const { return inputs_; }
  const std::vector<BaseField*>& outputs() const { return outputs_; }

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

namespace sinew {

// Cycles of the "takes its value from" graph over `fields`: a field depends on
// its parent link and, when an engine produces it, on that engine's inputs.
// Each cycle is listed once, as the fields in dependency order (the first
// depends on the second, ..., the last on the first).
std::vector<std::vector<const BaseField*>> find_field_cycles(const std::vector<const BaseField*>& fields);

// "component 'a' (T).indices (file:12) → component 'b' (T).indices (file:13) → component 'a' (T).indices".
std::string describe_field_cycle(const std::vector<const BaseField*>& cycle);

}  // namespace sinew
