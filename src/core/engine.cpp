#include "core/engine.h"

namespace sinew {

void Engine::add_input(BaseField* f) {
  inputs_.push_back(f);
  seen_.push_back(0);
}

void Engine::add_output(BaseField* f) {
  outputs_.push_back(f);
  f->set_producer(this);
}

void Engine::update() {
  if (updating_) return;
  updating_ = true;
  bool changed = dirty_;
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    inputs_[i]->update();
    if (inputs_[i]->version() != seen_[i]) changed = true;
  }
  if (changed) {
    do_update();
    for (std::size_t i = 0; i < inputs_.size(); ++i) seen_[i] = inputs_[i]->version();
    for (BaseField* out : outputs_) {
      out->touch();
      out->mark_set();
    }
    dirty_ = false;
  }
  updating_ = false;
}

}  // namespace sinew
