#include "core/engine.h"

#include <string>
#include <unordered_map>

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


namespace sinew {

namespace {
void field_dependencies(const BaseField* f, std::vector<const BaseField*>& out) {
  out.clear();
  if (f->parent()) out.push_back(f->parent());
  if (Engine* e = f->producer())
    for (const BaseField* in : e->inputs()) out.push_back(in);
}
}  // namespace

std::vector<std::vector<const BaseField*>> find_field_cycles(const std::vector<const BaseField*>& fields) {
  enum Color : char { white = 0, grey, black };
  std::unordered_map<const BaseField*, Color> color;
  std::vector<std::vector<const BaseField*>> cycles;
  struct Frame {
    const BaseField* f;
    std::vector<const BaseField*> deps;
    std::size_t next = 0;
  };
  std::vector<Frame> stack;  // iterative: long link chains never exhaust the call stack
  for (const BaseField* start : fields) {
    if (color[start] != white) continue;
    stack.push_back({start, {}, 0});
    field_dependencies(start, stack.back().deps);
    color[start] = grey;
    while (!stack.empty()) {
      Frame& top = stack.back();
      if (top.next == top.deps.size()) {
        color[top.f] = black;
        stack.pop_back();
        continue;
      }
      const BaseField* d = top.deps[top.next++];
      Color& c = color[d];
      if (c == grey) {
        std::vector<const BaseField*> cycle;
        std::size_t i = stack.size();
        while (i > 0 && stack[i - 1].f != d) --i;
        for (std::size_t k = i - 1; k < stack.size(); ++k) cycle.push_back(stack[k].f);
        cycles.push_back(std::move(cycle));
      } else if (c == white) {
        c = grey;
        Frame fr{d, {}, 0};
        field_dependencies(d, fr.deps);
        stack.push_back(std::move(fr));
      }
    }
  }
  return cycles;
}

std::string describe_field_cycle(const std::vector<const BaseField*>& cycle) {
  auto one = [](const BaseField* f) {
    std::string s = (f->owner() ? f->owner()->describe() : std::string("?")) + "." + f->name();
    if (f->owner() && f->owner()->where.line > 0)
      s += " (" + f->owner()->where.file + ":" + std::to_string(f->owner()->where.line) + ")";
    return s;
  };
  std::string s;
  for (const BaseField* f : cycle) s += one(f) + " → ";
  if (!cycle.empty()) s += cycle.front()->owner() ? cycle.front()->owner()->describe() + "." + cycle.front()->name()
                                                  : cycle.front()->name();
  return s;
}

}  // namespace sinew
