// Fields for the loader data that core/field.h has no parser for:
// variable-size element lists (polygons, polylines) and primitive groups.
// They behave like Field<T> (linkable, versioned, text round-trip) but are
// defined here so that core stays unchanged.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/field.h"
#include "io/mesh_readers.h"

namespace sinew::io {

// Text forms. Polygons: "n i0 … in-1 n i0 …" (size-prefixed). Groups: "p0 nbp material group id" per group.
std::string to_text(const std::vector<std::vector<unsigned>>& v);
bool read_text(std::string_view text, std::vector<std::vector<unsigned>>& v);
std::string to_text(const std::vector<std::vector<int>>& v);
bool read_text(std::string_view text, std::vector<std::vector<int>>& v);
std::string to_text(const std::vector<PrimitiveGroup>& v);
bool read_text(std::string_view text, std::vector<PrimitiveGroup>& v);

template <class T>
class ValueField final : public BaseField {
 public:
  ValueField(Base* owner, std::string name, std::string help, std::string group = {})
      : BaseField(owner, std::move(name), std::move(help), std::move(group)) {}

  const T& get() const {
    update();
    return value_;
  }
  const T& value() const { return value_; }
  void set(T v) {
    value_ = std::move(v);
    set_ = true;
    ++version_;
  }
  std::string type_name() const override { return "list"; }
  std::string default_text() const override { return {}; }
  std::string text() const override { return to_text(get()); }
  bool read(std::string_view text) override {
    const bool ok = read_text(text, value_);
    set_ = true;
    ++version_;
    return ok;
  }

 protected:
  void copy_from(const BaseField& other) override {
    if (auto* same = dynamic_cast<const ValueField<T>*>(&other)) value_ = same->value_;
    else read(other.text());
  }

 private:
  T value_{};
};

}  // namespace sinew::io
