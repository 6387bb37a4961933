// Numbered input fields (`input1..N`, `position1..N`): SOFA's vectorData.
//
// Their count is a field of the component (`nbInputs`, `nbMeshes`), read
// before the other attributes so that `input3="..."` finds its field. Fields
// register with their owner when constructed and are never unregistered, so
// the list only grows: a smaller count leaves the extra fields unused.
#pragma once

#include <deque>
#include <memory>
#include <string>

#include "core/component.h"
#include "core/engine.h"

namespace sinew {

// Most numbered fields a component creates: a larger count is clamped (an
// error) rather than allocating without bound.
inline constexpr unsigned kMaxNumberedFields = 1024;

template <class T>
class NumberedFields {
 public:
  NumberedFields(std::string prefix, std::string help, T def = T{}) : prefix_(std::move(prefix)), help_(std::move(help)), def_(std::move(def)) {}

  // Creates fields up to `n` (1-based names) owned by `owner`; `on_new` sees each new one.
  template <class F>
  void grow(Base& owner, unsigned n, F&& on_new) {
    while (fields_.size() < n) {
      const std::string name = prefix_ + std::to_string(fields_.size() + 1);
      fields_.push_back(std::make_unique<Field<T>>(&owner, name, def_, help_ + std::to_string(fields_.size() + 1), "Inputs"));
      on_new(fields_.back().get());
    }
  }
  std::size_t size() const { return fields_.size(); }
  Field<T>& operator[](std::size_t i) { return *fields_[i]; }
  const Field<T>& operator[](std::size_t i) const { return *fields_[i]; }
  const std::string& prefix() const { return prefix_; }

 private:
  std::string prefix_, help_;
  T def_;
  std::deque<std::unique_ptr<Field<T>>> fields_;
};

// Reads the count attribute `count` (if given) into `field`, clamped to
// kMaxNumberedFields, and returns the count to create. Attributes
// `<prefix>K` with K beyond the count are reported and consumed.
unsigned read_field_count(Component& c, Field<unsigned>& field, AttributeMap& attrs, Diagnostics& diag,
                          const std::vector<std::string>& prefixes);

}  // namespace sinew
