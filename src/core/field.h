// Fields: the typed, named, linkable values a component declares once.
//
// One declaration (name, default, help, group) serves the XML loader, links
// (`@path.field`), `sinew components`, Python and the viewer. Values are
// pulled lazily: every write bumps a version number, and a linked field or an
// engine output compares versions when read, copying or recomputing only when
// something upstream changed (SOFA's DDG without dirty-flag propagation).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/parse.h"

namespace sinew {

class Base;
class Engine;

// A flat array of doubles grouped in elements of `width` scalars: state
// vectors whose element type is chosen at run time (Vec3d: 3, Rigid3d: 7 or 6).
struct FlatVec {
  int width = 3;
  std::vector<double> data;
  std::size_t size() const { return width > 0 ? data.size() / static_cast<std::size_t>(width) : 0; }
  bool operator==(const FlatVec&) const = default;
};

// Where and how a value lies in memory, so that a front end can view it without
// copying (Python's numpy arrays). Values with no such layout (strings, nested
// lists) have scalar == none and are exchanged as text.
struct FieldLayout {
  enum class Scalar { none, f64, f32, i32, u32, boolean };
  Scalar scalar = Scalar::none;
  void* data = nullptr;       // first scalar (may be nullptr for an empty list)
  std::size_t rows = 1;       // elements of a list (1 for a single value)
  int cols = 1;               // scalars per element
  int dims = 0;               // 0: one scalar; 1: one vector or a list of scalars; 2: a list of vectors or a matrix
  bool column_major = false;  // a matrix stored by columns (Eigen's Mat3)
  bool list = false;          // a list whose length changes when a value of another length is written
};

class BaseField {
 public:
  // `unit`: a string literal naming the quantity's unit in consistent units
  // ("length", "force/length", "mass/length³"): SOFA scenes use any length unit.
  BaseField(Base* owner, std::string name, std::string help, std::string group, const char* unit = "");
  BaseField(const BaseField&) = delete;
  BaseField& operator=(const BaseField&) = delete;
  virtual ~BaseField() = default;

  const std::string& name() const { return name_; }
  const std::string& help() const { return help_; }
  const std::string& group() const { return group_; }
  // Unit of the value in consistent units, "" when it has none (flags, counts, names, indices).
  const char* unit() const { return unit_; }
  Base* owner() const { return owner_; }
  const std::vector<std::string>& aliases() const { return aliases_; }
  void add_alias(std::string a) { aliases_.push_back(std::move(a)); }

  virtual std::string type_name() const = 0;
  virtual std::string default_text() const = 0;
  // Current value as text (pulls linked values first).
  virtual std::string text() const = 0;
  // Parses `text` into the value (SOFA rules); false when the text was not fully valid.
  virtual bool read(std::string_view text) = 0;

  bool is_set() const { return set_; }
  void mark_set() { set_ = true; }
  // Back to "not given" (the value is kept): SOFA's Data::unset.
  void unset() { set_ = false; }
  std::uint64_t version() const { return version_; }
  void touch() { changed(); }

  // Called after every write (set, edit, read, touch): lets an owner follow a
  // field that shapes the graph (a node's `activated`). A plain function
  // pointer: one branch on the write paths, nothing on reads.
  using ChangeHook = void (*)(BaseField&);
  void set_change_hook(ChangeHook h) { change_hook_ = h; }

  // File-name fields are resolved against the scene folder and data paths by the loader.
  // A required file that is not found is a load error; an optional one keeps its text
  // (the component decides at init, e.g. recomputing what the file would have held).
  bool is_file() const { return is_file_; }
  bool file_required() const { return file_required_; }
  void set_file(bool b, bool required = true) {
    is_file_ = b;
    file_required_ = required;
  }

  // False for fields that must not be copied by `src="@loader"` (name, tags, transforms...).
  bool autolink() const { return autolink_; }
  void set_autolink(bool b) { autolink_ = b; }

  // Data links: this field takes its value from `parent` whenever parent changed.
  void set_parent(BaseField* parent);
  BaseField* parent() const { return parent_; }
  // Unresolved link text ("@path.field"), kept until the builder resolves it.
  const std::string& link_path() const { return link_path_; }
  void set_link_path(std::string p) { link_path_ = std::move(p); }

  // Outputs of an engine know their producer so reading them runs the engine.
  void set_producer(Engine* e) { producer_ = e; }
  Engine* producer() const { return producer_; }

  // Brings the value up to date with its parent link or producing engine.
  void update() const;

  // Element-wise access for copies between fields of different types
  // (e.g. a Vec3 list linked to a Rigid3 position receives the centres).
  virtual int row_width() const { return 0; }
  virtual void get_rows(std::vector<double>&) const {}
  virtual void set_rows(const std::vector<double>&, int /*width*/) {}

  // Memory layout of the stored value as it is now (no pull: call update() first to read
  // an up-to-date value). Writing through it must be followed by touch().
  virtual FieldLayout layout() { return {}; }

 protected:
  // Copies `other`'s value (same type: direct; otherwise rows, else text).
  virtual void copy_from(const BaseField& other) = 0;
  void changed() {
    ++version_;
    // A write stands until the parent changes again, read or not (SOFA's setValue cleans the
    // Data): without this, a field written before its first read got the parent's value back.
    if (parent_) parent_version_seen_ = parent_->version_;
    if (change_hook_) change_hook_(*this);
  }
  void copy_generic(const BaseField& other);

  Base* owner_;
  std::string name_, help_, group_;
  const char* unit_ = "";
  std::vector<std::string> aliases_;
  bool set_ = false;
  bool autolink_ = true;
  bool is_file_ = false;
  bool file_required_ = true;
  mutable std::uint64_t version_ = 1;
  BaseField* parent_ = nullptr;
  mutable std::uint64_t parent_version_seen_ = 0;
  std::string link_path_;
  Engine* producer_ = nullptr;
  ChangeHook change_hook_ = nullptr;
};

// Element-wise row access for the types that have one.
template <class T>
struct Rows {
  static constexpr int width = 0;
};
template <int N>
struct Rows<std::vector<VecN<N>>> {
  static constexpr int width = N;
  static void get(const std::vector<VecN<N>>& v, std::vector<double>& flat) {
    flat.resize(v.size() * N);
    for (std::size_t i = 0; i < v.size(); ++i)
      for (int c = 0; c < N; ++c) flat[i * N + c] = v[i][c];
  }
  static void set(std::vector<VecN<N>>& v, const std::vector<double>& flat, int w) {
    v.assign(w > 0 ? flat.size() / w : 0, VecN<N>::Zero());
    for (std::size_t i = 0; i < v.size(); ++i)
      for (int c = 0; c < std::min(N, w); ++c) v[i][c] = flat[i * w + c];
  }
};

// Memory layouts of the value types that have one (FieldLayout).
template <class T> struct ScalarOf { static constexpr auto kind = FieldLayout::Scalar::none; };
template <> struct ScalarOf<double> { static constexpr auto kind = FieldLayout::Scalar::f64; };
template <> struct ScalarOf<float> { static constexpr auto kind = FieldLayout::Scalar::f32; };
template <> struct ScalarOf<int> { static constexpr auto kind = FieldLayout::Scalar::i32; };
template <> struct ScalarOf<unsigned> { static constexpr auto kind = FieldLayout::Scalar::u32; };
template <> struct ScalarOf<bool> { static constexpr auto kind = FieldLayout::Scalar::boolean; };

template <class T>
struct LayoutOf {
  static FieldLayout get(T& v) {
    if constexpr (ScalarOf<T>::kind != FieldLayout::Scalar::none) return {ScalarOf<T>::kind, &v, 1, 1, 0};
    else return {};
  }
};
template <class S, int R, int C>
struct LayoutOf<Eigen::Matrix<S, R, C>> {
  static FieldLayout get(Eigen::Matrix<S, R, C>& v) {
    if constexpr (R < 0 || C < 0) return {};
    else if constexpr (C == 1) return {ScalarOf<S>::kind, v.data(), 1, R, 1};
    else return {ScalarOf<S>::kind, v.data(), R, C, 2, /*column_major=*/true};
  }
};
template <class S>
struct LayoutOf<std::vector<S>> {
  static FieldLayout get(std::vector<S>& v) {
    if constexpr (std::is_same_v<S, bool>) {
      return {};  // std::vector<bool> packs bits
    } else if constexpr (ScalarOf<S>::kind != FieldLayout::Scalar::none) {
      return {ScalarOf<S>::kind, v.data(), v.size(), 1, 1, false, true};
    } else {
      return LayoutOf<std::vector<S>>::elements(v);
    }
  }
  // Lists of fixed-size vectors stored without padding: one row per element.
  static FieldLayout elements(std::vector<S>& v) {
    if constexpr (requires { typename S::Scalar; S::RowsAtCompileTime; }) {
      using E = typename S::Scalar;
      constexpr int n = S::RowsAtCompileTime * S::ColsAtCompileTime;
      if constexpr (S::RowsAtCompileTime > 0 && S::ColsAtCompileTime > 0 && sizeof(S) == n * sizeof(E) && ScalarOf<E>::kind != FieldLayout::Scalar::none)
        return {ScalarOf<E>::kind, v.empty() ? nullptr : v.data()->data(), v.size(), n, 2, false, true};
      else return {};
    } else if constexpr (requires { std::tuple_size<S>::value; typename S::value_type; }) {
      using E = typename S::value_type;
      constexpr int n = static_cast<int>(std::tuple_size<S>::value);
      if constexpr (sizeof(S) == n * sizeof(E) && ScalarOf<E>::kind != FieldLayout::Scalar::none)
        return {ScalarOf<E>::kind, v.empty() ? nullptr : v.data()->data(), v.size(), n, 2, false, true};
      else return {};
    } else {
      return {};
    }
  }
};
template <>
struct LayoutOf<FlatVec> {
  static FieldLayout get(FlatVec& v) {
    return {FieldLayout::Scalar::f64, v.data.data(), v.size(), v.width, 2, false, true};
  }
};

// Type names shown by `sinew components`.
template <class T> struct TypeName { static std::string get() { return "value"; } };
template <> struct TypeName<double> { static std::string get() { return "double"; } };
template <> struct TypeName<float> { static std::string get() { return "float"; } };
template <> struct TypeName<int> { static std::string get() { return "int"; } };
template <> struct TypeName<unsigned> { static std::string get() { return "unsigned"; } };
template <> struct TypeName<bool> { static std::string get() { return "bool"; } };
template <> struct TypeName<std::string> { static std::string get() { return "string"; } };
template <> struct TypeName<FlatVec> { static std::string get() { return "state vector"; } };
template <> struct TypeName<std::vector<double>> { static std::string get() { return "vector<double>"; } };
template <> struct TypeName<std::vector<int>> { static std::string get() { return "vector<int>"; } };
template <> struct TypeName<std::vector<unsigned>> { static std::string get() { return "index list"; } };
template <> struct TypeName<std::vector<std::string>> { static std::string get() { return "vector<string>"; } };
template <> struct TypeName<Mat3> { static std::string get() { return "Mat3x3d"; } };
template <int N> struct TypeName<VecN<N>> { static std::string get() { return "Vec" + std::to_string(N) + "d"; } };
template <int N> struct TypeName<VecNi<N>> { static std::string get() { return "Vec" + std::to_string(N) + "i"; } };
template <int N> struct TypeName<std::vector<VecN<N>>> { static std::string get() { return "vector<Vec" + std::to_string(N) + "d>"; } };
template <std::size_t N> struct TypeName<std::vector<std::array<unsigned, N>>> {
  static std::string get() { return "vector<" + std::to_string(N) + " indices>"; }
};

template <class T>
class Field final : public BaseField {
 public:
  Field(Base* owner, std::string name, T def, std::string help, std::string group = {}, const char* unit = "")
      : BaseField(owner, std::move(name), std::move(help), std::move(group), unit),
        value_(def),
        default_(std::move(def)) {}

  // Up-to-date value (follows links, runs engines).
  const T& get() const {
    update();
    return value_;
  }
  // Raw value without pulling: for hot paths on fields that are never linked.
  const T& value() const { return value_; }
  // Write access: marks the field set and changed.
  T& edit() {
    update();
    set_ = true;
    changed();
    return value_;
  }
  void set(T v) {
    value_ = std::move(v);
    set_ = true;
    changed();
  }
  const T& default_value() const { return default_; }
  // Write access without a version change or pull, for storage whose changes
  // are announced separately (state vectors: MechanicalState::write/touch).
  T& raw() { return value_; }

  std::string type_name() const override { return TypeName<T>::get(); }
  std::string default_text() const override { return to_text(default_); }
  std::string text() const override { return to_text(get()); }
  bool read(std::string_view text) override {
    const bool ok = read_value(text, value_);
    set_ = true;
    changed();
    return ok;
  }

  int row_width() const override {
    if constexpr (std::is_same_v<T, FlatVec>) return value_.width;
    else return Rows<T>::width;
  }
  void get_rows(std::vector<double>& flat) const override {
    if constexpr (std::is_same_v<T, FlatVec>) flat = get().data;
    else if constexpr (Rows<T>::width > 0) Rows<T>::get(get(), flat);
  }
  FieldLayout layout() override { return LayoutOf<T>::get(value_); }
  void set_rows(const std::vector<double>& flat, int w) override {
    if constexpr (std::is_same_v<T, FlatVec>) {
      const int mw = value_.width;
      const std::size_t n = w > 0 ? flat.size() / w : 0;
      value_.data.assign(n * mw, 0.0);
      // Rigid3d coordinates (width 7) built from points get the identity orientation, as a
      // resized SOFA vector of RigidCoord would (never the invalid quaternion 0 0 0 0).
      if (mw == 7 && w < 7)
        for (std::size_t i = 0; i < n; ++i) value_.data[i * 7 + 6] = 1.0;
      for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < std::min(mw, w); ++c) value_.data[i * mw + c] = flat[i * w + c];
    } else if constexpr (Rows<T>::width > 0) {
      Rows<T>::set(value_, flat, w);
    }
  }

 protected:
  void copy_from(const BaseField& other) override {
    if (auto* same = dynamic_cast<const Field<T>*>(&other)) {
      if constexpr (std::is_same_v<T, FlatVec>) {
        if (same->value_.width != value_.width) {
          copy_generic(other);
          return;
        }
      }
      value_ = same->value_;
    } else {
      copy_generic(other);
    }
  }

 private:
  static std::string to_text(const T& v) {
    if constexpr (std::is_same_v<T, FlatVec>) return parse::flat_to_text(v.data);
    else return parse::to_text(v);
  }
  static bool read_value(std::string_view text, T& v) {
    if constexpr (std::is_same_v<T, FlatVec>) return parse::read_flat(text, v.width, v.data);
    else return parse::read(text, v);
  }

  T value_;
  T default_;
};

// Object links (`topology="@grid"`, `mstate="@../dofs"`): a path resolved to a component or node.
class BaseLink {
 public:
  BaseLink(Base* owner, std::string name, std::string help);
  virtual ~BaseLink() = default;
  const std::string& name() const { return name_; }
  const std::string& help() const { return help_; }
  const std::string& path() const { return path_; }
  void set_path(std::string p) { path_ = std::move(p); }
  bool is_set() const { return !path_.empty(); }
  // Type-checks a resolved target; returns false when it has the wrong type.
  virtual bool accept(Base* target) = 0;
  virtual Base* target() const = 0;
  virtual std::string type_name() const = 0;
  // Multi-links (several space-separated paths, e.g. a multi-mapping's `input`):
  // the builder resolves each path, using accept() as a type check only, then
  // calls add_target() for each resolved object after clear_targets().
  virtual bool is_multi() const { return false; }
  virtual void clear_targets() {}
  virtual void add_target(Base*) {}
  // Whether `b` is (one of) the target(s); forget(b) drops it. Used when `b`
  // leaves the graph so that no link is left dangling.
  virtual bool references(const Base* b) const { return b && target() == b; }
  virtual void forget(const Base* b) = 0;

 private:
  std::string name_, help_, path_;
};

template <class T>
class Link final : public BaseLink {
 public:
  Link(Base* owner, std::string name, std::string help) : BaseLink(owner, std::move(name), std::move(help)) {}
  T* get() const { return ptr_; }
  T* operator->() const { return ptr_; }
  T& operator*() const { return *ptr_; }
  explicit operator bool() const { return ptr_ != nullptr; }
  void set(T* p) { ptr_ = p; }
  bool accept(Base* target) override {
    ptr_ = dynamic_cast<T*>(target);
    return ptr_ != nullptr;
  }
  Base* target() const override;
  std::string type_name() const override { return "link"; }
  void forget(const Base* b) override {
    if (references(b)) ptr_ = nullptr;
  }

 private:
  T* ptr_ = nullptr;
};

// A link to several objects of type T (`collisionModels="@a @b"`), in path order.
template <class T>
class MultiLink final : public BaseLink {
 public:
  MultiLink(Base* owner, std::string name, std::string help) : BaseLink(owner, std::move(name), std::move(help)) {}
  const std::vector<T*>& get() const { return targets_; }
  bool accept(Base* target) override { return dynamic_cast<T*>(target) != nullptr; }
  Base* target() const override;
  std::string type_name() const override { return "multi-link"; }
  bool is_multi() const override { return true; }
  void clear_targets() override { targets_.clear(); }
  void add_target(Base* b) override {
    if (T* t = dynamic_cast<T*>(b)) targets_.push_back(t);
  }
  bool references(const Base* b) const override;
  void forget(const Base* b) override;

 private:
  std::vector<T*> targets_;
};

template <class T>
Base* MultiLink<T>::target() const {
  return targets_.empty() ? nullptr : targets_.front();
}
template <class T>
bool MultiLink<T>::references(const Base* b) const {
  for (T* t : targets_)
    if (static_cast<const Base*>(t) == b) return true;
  return false;
}
template <class T>
void MultiLink<T>::forget(const Base* b) {
  std::erase_if(targets_, [b](T* t) { return static_cast<const Base*>(t) == b; });
}

template <class T>
Base* Link<T>::target() const {
  return ptr_;  // T derives from Base; implicit upcast
}

}  // namespace sinew
